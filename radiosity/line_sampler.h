// SPDX-License-Identifier: Apache-2.0
// The line sampler of the line-based oracles (docs/design.md §4): N_s segments between
// area-uniform points of two elements, each with its point-to-point kernel and visibility.
#pragma once

#include <span>

#include "radiosity/clusters.h"
#include "radiosity/hierarchy.h"
#include "rays/embree_scene.h"
#include "rays/rng.h"

namespace hmcr {

// Fills out[k] = F(x_k, y_k) for out.size() lines, x_k uniform on element i, y_k uniform on
// element j, visibility from Embree (one coherent packet per 16 lines). Either may be a cluster
// of `clusters` (docs/design.md §2.7): its points are uniform over its sides, each with its
// side's normal; the top cluster as j, the source, has its points where its light leaves it
// (ClusterTree::source_point).
void sample_kernel(const EmbreeScene& scene, const Hierarchy& hierarchy, const Element& i,
                   const Element& j, Rng& rng, std::span<double> out,
                   const ClusterTree* clusters = nullptr);

}  // namespace hmcr
