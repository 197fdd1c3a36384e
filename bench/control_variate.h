// SPDX-License-Identifier: Apache-2.0
// `hmcr_bench --control-variate SEEDS`: the constant control variate's variance gain on every
// bundled scene (docs/results.md, "Constant control variate"). Each scene is solved on a fixed
// uniform mesh of about kElements elements with each seed, without and with the control
// variate; a row gives the mean over the fronts' leaves and the channels of the variance of B
// across the seeds, their ratio, and the mean time per solve.
#pragma once

namespace hmcr::bench {

int run_control_variate_study(int seeds);

}  // namespace hmcr::bench
