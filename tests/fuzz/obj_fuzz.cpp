// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: OBJ and MTL (README.md in this folder says how to build and run it).
//
// Input: OBJ text, optionally followed by a NUL byte and MTL text, written to fuzz.obj and
// fuzz.mtl (the seeds reach the MTL with `mtllib fuzz.mtl`), loaded with and without the
// repairs and a default material. A loaded mesh must keep the loader's guarantees.
#include <cmath>
#include <cstdint>

#include "meshes/scene.h"
#include "tests/fuzz/fuzz_support.h"

namespace hmcr::fuzz {
namespace {

void check_mesh(PatchMesh& mesh) {
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
        if (material[fh].roughness != 0) crash("an MTL mirror with a roughness");
        if (line[fh] <= 0) crash("face without a source line");
    }
    if (!(emitted > 0)) crash("loaded a scene without an emitter");
}

void load(const LoadOptions& options) {
    expect_only_input_errors([&] {
        PatchMesh mesh = load_obj(work_dir() / "fuzz.obj", options);
        check_mesh(mesh);
    });
}

}  // namespace
}  // namespace hmcr::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t split = input.find('\0');
    write("fuzz.obj", input.substr(0, split));
    write("fuzz.mtl", split == std::string::npos ? "" : input.substr(split + 1));
    load({});
    hmcr::LoadOptions strict;
    strict.strict = true;
    load(strict);
    hmcr::LoadOptions options;
    options.default_material = hmcr::Material{"default", {0.5, 0.5, 0.5}, {1, 1, 1}};
    load(options);
    return 0;
}
