// SPDX-License-Identifier: Apache-2.0
// The promises of a mesh that a polygon reader (OBJ, PLY, glTF) loaded, checked by its fuzz
// target: faces are triangles or quads, reflectance in [0, 1], Kd + Ks at most 1, no roughness,
// finite emission (a back's too), an emitter on either side, and a source line (or item number) on
// every face.
#pragma once

#include <cmath>

#include "meshes/scene.h"
#include "tests/fuzz/fuzz_support.h"

namespace hmcr::fuzz {

inline void check_loaded_mesh(PatchMesh& mesh) {
    if (mesh.n_faces() == 0) crash("loaded a mesh without faces");
    const FaceMaterials material(mesh);
    auto line = source_line_prop(mesh);
    double emitted = 0;
    for (auto fh : mesh.faces()) {
        const auto valence = mesh.valence(fh);
        if (valence < 3 || valence > 4) crash("face that is neither a triangle nor a quad");
        for (int c = 0; c < 3; ++c) {
            // 1 is accepted with a warning (docs/usage.md#repairs), above is refused.
            const double rho = material[fh].reflectance[c], e = material[fh].emission[c];
            const double ks = material[fh].specular[c];
            if (!(rho >= 0 && rho <= 1)) crash("bad reflectance");
            if (!(ks >= 0 && rho + ks <= 1)) crash("bad specular reflectance");
            if (!(e >= 0 && std::isfinite(e))) crash("bad emission");
            emitted += e;
        }
        if (material[fh].roughness != 0) crash("a material with a roughness");
        // A two-sided face's back may be the emitter (opposite faces joined, one of them a lamp).
        const std::uint32_t back = material.back_index(fh);
        if (back != kOneSided) {
            const FaceMaterial& b = material.table()[back];
            for (int c = 0; c < 3; ++c) {
                if (!(b.reflectance[c] >= 0 && b.reflectance[c] <= 1))
                    crash("bad back reflectance");
                if (!(b.emission[c] >= 0 && std::isfinite(b.emission[c])))
                    crash("bad back emission");
                emitted += b.emission[c];
            }
        }
        if (line[fh] <= 0) crash("face without a source line");
    }
    if (!(emitted > 0)) crash("loaded a scene without an emitter");
}

}  // namespace hmcr::fuzz
