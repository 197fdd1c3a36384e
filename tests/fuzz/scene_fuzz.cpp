// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: JSON scene files and their solver settings.
//
// Input: the text of scene.json, beside a valid two-patch OBJ (fuzz.obj, fuzz.mtl) it may name.
// The scene is loaded, and its "solver" object applied to solver options as `hmcr solve` does.
#include <cstdint>

#include "meshes/scene.h"
#include "radiosity/solver_settings.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    static const bool mesh_written = [] {
        write("fuzz.obj",
              "mtllib fuzz.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
              "v 1 0 1\nv 1 1 1\nv 0 1 1\nusemtl e\nf 1 2 3 4\nusemtl r\nf 5 8 7 6\n");
        write("fuzz.mtl", "newmtl e\nKd 0 0 0\nKe 1 1 1\nnewmtl r\nKd 0.5 0.5 0.5\n");
        return true;
    }();
    (void)mesh_written;
    const auto json = write("scene.json", std::string(reinterpret_cast<const char*>(data), size));
    expect_only_input_errors([&] {
        const hmcr::Scene scene = hmcr::load_scene(json.string());
        if (scene.views.empty()) crash("a scene without a view");
        hmcr::SolverOptions options;
        hmcr::apply_scene_settings(scene.solver_defaults, json.string(), options);
        hmcr::validate(options);
    });
    return 0;
}
