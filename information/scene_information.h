// SPDX-License-Identifier: Apache-2.0
// Information measures of a scene's visibility channel (docs/design.md §7; Feixas, del Acebo,
// Bekaert, Sbert, "An information theory framework for the analysis of scene complexity",
// Eurographics 1999). The states are the sides of a discretisation's patches, the transition
// probabilities their form factors, the stationary distribution the relative areas
// a_i = A_i / A_T. In bits:
//   H_P = -sum a_i log a_i                       positional entropy
//   H_S = -sum_i a_i sum_j F_ij log F_ij         scene visibility entropy
//   I_S = sum_i sum_j a_i F_ij log(F_ij / a_j)   mutual information (= H_P - H_S when closed)
//   H_J = H_P + H_S                              joint entropy
//   I^c_S = (1/N) sum_k log(A_T F(x_k, y_k))     continuous mutual information
//   I^c_S - I_S >= 0                             discretisation error
// The form factors come from local or global lines (information/channel_samples.h); I^c_S uses the
// point kernel on the same rays (skipping those that miss or hit a one-sided back). Standard errors
// are batch means: each measure is computed on every one of the independent ray batches, and
// SE = sd(batch values) / sqrt(batches).
//
// The plug-in entropies are biased: H_S low and I_S high, by at most log2(1 + (K - 1) / n) for
// rows of K reachable patches and n rays (Paninski, "Estimation of entropy and mutual
// information", Neural Computation 2003). Few rays per patch make form factors look spiky.
#pragma once

#include <cstddef>
#include <nlohmann/json_fwd.hpp>

#include "information/back_sides.h"
#include "information/channel_samples.h"
#include "rays/embree_scene.h"
#include "rays/patch.h"

namespace hmcr {

struct InformationMeasures {
    struct Value {
        double estimate = 0;
        double standard_error = 0;
        // Estimated bias of the plug-in estimate, to be subtracted. Plug-in biases fall as 1/n
        // to leading order, so a batch (B times fewer lines) carries B times the bias of all
        // the lines: bias = (mean of the batch values - estimate) / (B - 1). About 0 for the
        // linear I^c_S; large against the standard error means too few lines per patch.
        double bias = 0;
    };
    Value h_p, h_s, i_s, h_j, i_cs, discretisation_error;
    LineMethod method = LineMethod::local;
    std::size_t lines = 0;              // lines traced
    std::size_t samples = 0;            // rays leaving a patch (local: one per line)
    std::size_t samples_open = 0;       // of which landing on no state (skipped in I^c_S)
    std::size_t patches_unsampled = 0;  // states no line crossed: their rows are missing
};

// The measures of the discretisation given by the patches, from freshly traced lines: its
// states are the sides of the patches (information/back_sides.h), a patch's front and the back
// of a two-sided one.
InformationMeasures scene_information(const PatchSet& patches, const LineOptions& options,
                                      Progress& progress = no_progress());
// The same for the states of any discretisation (a solution's leaves).
InformationMeasures scene_information(const ChannelStates& channels, const LineOptions& options,
                                      Progress& progress = no_progress());
// The same from samples already traced on these patches.
InformationMeasures scene_information(const PatchSet& patches, const ChannelSamples& samples,
                                      LineMethod method);

nlohmann::json to_json(const InformationMeasures& m);

}  // namespace hmcr
