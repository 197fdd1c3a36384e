// SPDX-License-Identifier: Apache-2.0
#include "studies/study_figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "common/file_names.h"
#include "meshes/patch_mesh.h"
#include "studies/montage.h"
#include "viz/paraview_collection.h"
#include "viz/paraview_state.h"
#include "viz/renderer.h"
#include "viz/shaded_tracer.h"
#include "viz/solution_file.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

constexpr Srgb8 kEdgeInk{0, 0, 0};
constexpr int kTilesPerRow = 4;

fs::path budget_figure_file(const StudyOptions& o, const View& view, std::size_t budget,
                            const char* kind) {
    return named_file(o.output / "figures", fmt::format("{}-B{}-{}", view.name, budget, kind),
                      ".png");
}

fs::path cell_mesh(const StudyOptions& o, const CellResult& c) {
    return named_file(o.output / "meshes", cell_name(c.scene, c.oracle, c.budget, c.seed), ".vtp");
}

fs::path cell_image(const StudyOptions& o, const CellResult& c, const View& view) {
    return named_file(o.output / "images",
                      cell_name(c.scene, c.oracle, c.budget, c.seed) + "-" + view.name, ".png");
}

// The first seed's cell of an oracle at a budget, when its search succeeded.
const CellResult* first_seed(const std::vector<CellResult>& cells, const StudyOptions& o,
                             const Oracle* oracle, std::size_t budget) {
    for (const CellResult& c : cells) {
        if (c.oracle == oracle->name() && c.budget == budget && c.seed == o.solver.seed) {
            return c.ok() ? &c : nullptr;
        }
    }
    return nullptr;
}

Image8 white(int width, int height) {
    Image8 im(width, height);
    for (Srgb8& p : im.pixels) p = {255, 255, 255};
    return im;
}

// Every view's two figures at one budget.
void write_budget_figures(OutputSet& out, const Scene& scene, const StudyOptions& o,
                          const std::vector<CellResult>& cells,
                          const std::map<std::string, Image8>& references, std::size_t budget) {
    std::map<std::string, std::vector<Image8>> images, meshes;
    std::vector<std::string> labels;
    for (const View& v : scene.views) images[v.name].push_back(references.at(v.name));
    for (const Oracle* oracle : o.oracles) {
        const CellResult* cell = first_seed(cells, o, oracle, budget);
        labels.push_back(std::string(oracle->name()) + (cell ? "" : " failed"));
        std::optional<ShadedTracer> tracer;
        if (cell) tracer.emplace(read_solution(cell_mesh(o, *cell), scene).mesh);
        for (const View& v : scene.views) {
            const Image8& ref = references.at(v.name);
            View sized = v;  // at the reference's size, as the cells' images are
            sized.width = ref.width;
            sized.height = ref.height;
            const Image8 image =
                cell ? read_png(cell_image(o, *cell, v)) : white(ref.width, ref.height);
            images[v.name].push_back(image);
            meshes[v.name].push_back(tracer ? draw_cell_edges(*tracer, sized, image, kEdgeInk)
                                            : image);
        }
    }
    std::vector<std::string> image_labels{"reference"};
    image_labels.insert(image_labels.end(), labels.begin(), labels.end());
    for (const View& v : scene.views) {
        const int shrink = references.at(v.name).width >= 256 ? 2 : 1;
        write_png(out.temp(budget_figure_file(o, v, budget, "images")),
                  montage(images[v.name], kTilesPerRow, shrink, image_labels));
        // Full size: an element edge is one pixel.
        write_png(out.temp(budget_figure_file(o, v, budget, "meshes")),
                  montage(meshes[v.name], kTilesPerRow, 1, labels));
    }
}

bool has_backs(const Scene& scene) {
    const FaceMaterials materials(scene.mesh);
    return std::any_of(scene.mesh.faces_begin(), scene.mesh.faces_end(),
                       [&](auto f) { return materials.back_index(f) != kOneSided; });
}

// meshes.pvsm and meshes.pvd: every cell's mesh that exists, in the study's order.
void write_paraview_files(OutputSet& out, const Scene& scene, const StudyOptions& o,
                          const std::vector<CellResult>& cells) {
    std::vector<CollectionEntry> steps;
    std::vector<StateSource> sources;
    for (const CellResult& c : cells) {
        const fs::path mesh = cell_mesh(o, c);
        std::error_code ec;
        if (!c.ok() || !fs::is_regular_file(mesh, ec)) continue;
        const std::string name = cell_name(c.scene, c.oracle, c.budget, c.seed);
        steps.push_back({fs::path("meshes") / mesh.filename(), name});
        sources.push_back({mesh, mesh.filename().string(), sources.empty()});
    }
    write_paraview_collection(out.temp(o.output / "meshes.pvd"), steps);
    write_paraview_state(out.temp(o.output / "meshes.pvsm"), sources, scene.views.front(),
                         has_backs(scene));
}

}  // namespace

std::vector<fs::path> study_figure_files(const Scene& scene, const StudyOptions& o) {
    std::vector<fs::path> files{o.output / "meshes.pvd", o.output / "meshes.pvsm"};
    for (std::size_t b : o.budgets)
        for (const View& v : scene.views)
            for (const char* kind : {"images", "meshes"})
                files.push_back(budget_figure_file(o, v, b, kind));
    return files;
}

void write_study_figures(OutputSet& out, const Scene& scene, const StudyOptions& o,
                         const std::vector<CellResult>& cells,
                         const std::map<std::string, Image8>& reference_images) {
    for (std::size_t b : o.budgets) write_budget_figures(out, scene, o, cells, reference_images, b);
    write_paraview_files(out, scene, o, cells);
}

}  // namespace hmcr
