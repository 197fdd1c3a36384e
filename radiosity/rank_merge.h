// SPDX-License-Identifier: Apache-2.0
// An iteration shared by MPI ranks (docs/cluster.md). Each rank shoots a slice of the
// iteration's rays on its own copy of the hierarchy; then every rank takes the union of all
// ranks' subdivisions and the sum of all deposits, so that every copy is again the same.
//
// Why the union is the single process's hierarchy: within an iteration a link's decision
// depends only on the pair (its elements' frozen B and Delta B, and lines keyed by their ids),
// so a ray descends to the same element whichever rank traces it, and each subdivision is
// made by the rank of a ray that needed it. Why the sums are the same bits: deposits are whole
// quanta (power_quanta.h), and integer sums do not depend on the order.
#pragma once

#include "common/ranks.h"
#include "radiosity/clusters.h"
#include "radiosity/hierarchy.h"
#include "radiosity/shooting.h"

namespace hmcr {

// The rays [begin, end) of `rays` that `rank` of `ranks` shoots: contiguous, each beginning at a
// multiple of EmbreeScene::kPacketRays, sizes differing by at most one packet.
RaySlice slice_of(std::uint64_t rays, int rank, int ranks);

// Makes every rank's hierarchy and outcome the whole iteration's. `refined`: ranks may have
// subdivided (else the mesh is fixed and only deposits are summed). `clusters`' deposits are
// summed too (the tree is the same on every rank), and their open flags united. A collective.
void merge_iteration(Hierarchy& h, IterationOutcome& out, const Ranks& ranks, bool refined,
                     ClusterTree* clusters = nullptr);

}  // namespace hmcr
