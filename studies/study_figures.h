// SPDX-License-Identifier: Apache-2.0
// A meshing study's figures and ParaView files, written at its end from the cells' files
// (docs/studies.md, "A meshing study's files"):
//   OUT/figures/VIEW-B{budget}-images.png  the reference's image of the view, then each
//                                          oracle's first seed's, 4 a row, each labelled
//   OUT/figures/VIEW-B{budget}-meshes.png  each oracle's first seed's image with the edges of
//                                          its elements drawn over it, the same way
//   OUT/meshes.pvsm                        a ParaView state of every cell's mesh, each a source
//                                          named by its file (CELL.vtp), coloured as `hmcr
//                                          solve`'s state, the first shown, seen from the first
//                                          view
//   OUT/meshes.pvd                         the same meshes as the time steps of one source
// A cell whose search failed is a white tile labelled "failed".
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "common/output_set.h"
#include "image/image.h"
#include "meshes/scene.h"
#include "studies/study.h"

namespace hmcr {

// The files write_study_figures() writes, for the check of the outputs before any cell.
std::vector<std::filesystem::path> study_figure_files(const Scene& scene, const StudyOptions& o);

// Writes them into `out` from the cells (in the study's order), their files in o.output and
// the reference's images of the views (at its exposure and size).
void write_study_figures(OutputSet& out, const Scene& scene, const StudyOptions& o,
                         const std::vector<CellResult>& cells,
                         const std::map<std::string, Image8>& reference_images);

}  // namespace hmcr
