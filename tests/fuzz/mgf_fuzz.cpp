// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: MGF (README.md in this folder says how to build and run it).
//
// Input: MGF text written to fuzz.mgf, with a NUL byte separating a second file, part.mgf,
// that fuzz.mgf can include (`i part.mgf`). Read with a small statement budget (arrays of
// 10^9 instances must end in an error, not a timeout), given its sides, then repaired (or, as
// --strict, only its opposite faces joined) and built into a patch mesh as the loader does. What
// the reader returns must hold finite positions, valid corner and material indices and sides 1 or
// 2; a loaded mesh, triangles and quads with reflectance in [0, 1] on both sides, diffuse +
// specular at most 1 and a roughness in [0, 1].
#include <cmath>
#include <cstdint>

#include "meshes/material_sides.h"
#include "meshes/mgf_reader.h"
#include "meshes/repairs.h"
#include "meshes/scene.h"
#include "tests/fuzz/fuzz_support.h"

namespace hmcr::fuzz {
namespace {

void check_soup(const PolygonSoup& soup) {
    for (const Eigen::Vector3d& p : soup.positions) {
        if (!p.allFinite()) crash("a position that is not finite");
    }
    for (std::size_t k = 0; k < soup.polygon_count(); ++k) {
        if (soup.corners(k).size() < 3) crash("a polygon of fewer than 3 corners");
        for (std::uint32_t c : soup.corners(k)) {
            if (c >= soup.positions.size()) crash("a corner index out of range");
        }
        const std::int32_t m = soup.material[k];
        if (m < 0 || std::size_t(m) >= soup.materials.size())
            crash("a material index out of range");
    }
    for (const hmcr::SoupMaterial& m : soup.materials) {
        if (m.sides != 1 && m.sides != 2) crash("a material of sides other than 1 or 2");
    }
}

void check_back(const hmcr::FaceMaterials& material, OpenMesh::FaceHandle fh) {
    const std::uint32_t back = material.back_index(fh);
    if (back == hmcr::kOneSided) return;
    for (int c = 0; c < 3; ++c) {
        const double rho = material.table()[back].reflectance[c];
        if (!(rho >= 0 && rho <= 1)) crash("bad reflectance behind");
    }
}

void check_mesh(PatchMesh& mesh) {
    const FaceMaterials material(mesh);
    for (auto fh : mesh.faces()) {
        if (mesh.valence(fh) < 3 || mesh.valence(fh) > 4)
            crash("face that is neither a triangle nor a quad");
        for (int c = 0; c < 3; ++c) {
            const double rho = material[fh].reflectance[c], ks = material[fh].specular[c];
            if (!(rho >= 0 && rho <= 1)) crash("bad reflectance");
            if (!(ks >= 0 && rho + ks <= 1)) crash("bad specular reflectance");
        }
        const double alpha = material[fh].roughness;
        if (!(alpha >= 0 && alpha <= 1)) crash("bad roughness");
        check_back(material, fh);
    }
}

MgfOptions small_budget() {
    MgfOptions options;
    // 20,000 statements take up to 1.3 s under the sanitizers (about 60 us each, against 1 us
    // in hmcr): at 100,000, arrays of arrays ran 6 s and, on a busy machine, past the 20 s
    // timeout of the hour-long runs.
    options.max_statements = 20'000;
    options.max_polygons = 100'000;
    options.curve_segments = 8;
    return options;
}

}  // namespace
}  // namespace hmcr::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t split = input.find('\0');
    write("fuzz.mgf", input.substr(0, split));
    write("part.mgf", split == std::string::npos ? "" : input.substr(split + 1));
    // The loader's steps (meshes/scene_loader.cpp) on the budgeted read.
    for (bool strict : {false, true}) {
        expect_only_input_errors([&] {
            hmcr::PolygonSoup soup = hmcr::read_mgf(work_dir() / "fuzz.mgf", small_budget());
            check_soup(soup);
            hmcr::check_positions(soup);
            hmcr::LoadOptions options;
            hmcr::assign_sides(soup, options);
            const hmcr::Welding welding = hmcr::weld(soup.positions);
            if (strict) {
                hmcr::join_opposite_faces(soup, welding);
            } else {
                hmcr::repair_soup(soup, welding);
            }
            options.strict = strict;
            options.use = hmcr::SceneUse::geometry;
            options.default_material = hmcr::Material{"default", {0.5, 0.5, 0.5}, {0, 0, 0}};
            hmcr::PatchMesh mesh = hmcr::build_patch_mesh(soup, options);
            check_mesh(mesh);
        });
    }
    return 0;
}
