// SPDX-License-Identifier: Apache-2.0
// What every mesh reader (OBJ, MGF, PLY, glTF) produces and the patch-mesh builder turns into a
// validated PatchMesh: positions, polygons with their material and the place they were read
// from, and materials with the places of their reflectance and emission. Errors found later
// (a degenerate face, a reflectance of 1.2) are reported at those places.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "meshes/scene.h"
#include "meshes/weld.h"

namespace hmcr {

// A line of one of the soup's files (or, in a file without lines, a numbered item of it).
struct SourcePlace {
    std::uint32_t file = 0;  // index into PolygonSoup::files
    std::uint32_t line = 0;  // 1-based; 0: the file as a whole
};

struct SoupMaterial {
    Material material;
    bool defined = true;     // false: named by a face but defined nowhere (an error if used)
    SourcePlace kd, ke, ks;  // where Kd, Ke and Ks were set (the definition if they were not)
    int sides = 0;           // 1 or 2 as the file says (MGF's `sides`); 0: the format has none
    // MGF: a specular part (rs) that takes the sum with the diffuse one above 1 may be reduced
    // to fit, a repair (meshes/repairs.h); OBJ's Ks of a mirror (illum 3) is the user's word.
    bool specular_reducible = false;
};

struct PolygonSoup {
    static constexpr std::int32_t kNoMaterial = -1;
    static constexpr std::int32_t kOneSided = -2;  // a polygon's back: black and absorbing

    std::vector<std::filesystem::path> files;  // every file read, in order
    std::vector<Eigen::Vector3d> positions;    // finite
    std::vector<SoupMaterial> materials;
    std::vector<std::string> warnings;  // "file:line: what", one line each
    // Files without lines (a binary PLY, glTF), by index into files: there a place's `line`
    // numbers an item, of the kind named here ("face"), and where() says "path: face 12".
    std::map<std::uint32_t, std::string> item_names;
    // Why a face may have no material, in the reader's terms, for the error when one has none.
    std::string no_material = "no usemtl before it";

    // Polygon k: corners (indices into positions, counter-clockwise seen from the front),
    // material (index into materials, or kNoMaterial), the material of its back (the same, or
    // kOneSided; docs/design.md §1.3) and the statement it came from.
    std::size_t polygon_count() const { return material.size(); }
    std::span<const std::uint32_t> corners(std::size_t k) const {
        return {corner_ids.data() + corner_offsets[k], corner_offsets[k + 1] - corner_offsets[k]};
    }
    void add_polygon(std::span<const std::uint32_t> ids, std::int32_t material_id, SourcePlace at,
                     std::int32_t back_id = kOneSided);

    std::vector<std::uint32_t> corner_offsets{0};
    std::vector<std::uint32_t> corner_ids;
    std::vector<std::int32_t> material;
    std::vector<std::int32_t> back;
    std::vector<SourcePlace> place;

    std::string where(SourcePlace p) const;  // "path:line", "path: face N", or "path" for 0
    // What a place's `line` counts in the file: "line", or its item_names entry ("face").
    std::string item_word(std::uint32_t file) const;
};

// Throws InputError at the place of the first polygon with a corner that check_position
// (meshes/validation.h) refuses. The loader checks before the repairs, whose arithmetic on such
// corners overflows (a sphere of radius 1e300 was "self-intersecting").
void check_positions(const PolygonSoup& soup);

// The validated patch mesh of the soup (docs/design.md §1): equal positions welded, every polygon
// checked (geometry, material), no duplicate faces, an emitter when the scene is to be solved.
// Throws InputError at the place of the first problem.
PatchMesh build_patch_mesh(const PolygonSoup& soup, const LoadOptions& options);

// A scene of the soup, loaded as a mesh file's (its warnings told, repaired unless
// options.strict, validated), named `name`, with the default view: a program's own polygons (the
// Python module's arrays). Throws InputError at the place of the first problem.
Scene load_soup_scene(const std::string& name, PolygonSoup soup, const LoadOptions& options);
// The same built into `mesh`, which must be empty, with the soup's welding, weld(soup.positions),
// already made.
void build_patch_mesh(const PolygonSoup& soup, const Welding& welding, const LoadOptions& options,
                      PatchMesh& mesh);

}  // namespace hmcr
