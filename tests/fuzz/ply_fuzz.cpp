// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: PLY (README.md in this folder says how to build and run it).
//
// Input: a PLY file, ascii or binary, written to fuzz.ply and loaded with the repairs, with
// `--strict` and with a default material. A loaded mesh must keep the loader's guarantees.
#include <cstdint>

#include "meshes/scene.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/mesh_checks.h"

namespace hmcr::fuzz {
namespace {

void load_ply(const LoadOptions& options) {
    expect_only_input_errors([&] {
        MeshFile file = load_mesh(work_dir() / "fuzz.ply", options);
        check_loaded_mesh(file.mesh);
    });
}

}  // namespace
}  // namespace hmcr::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    write("fuzz.ply", std::string(reinterpret_cast<const char*>(data), size));
    load_ply({});
    hmcr::LoadOptions strict;
    strict.strict = true;
    load_ply(strict);
    hmcr::LoadOptions options;
    options.default_material = hmcr::Material{"default", {0.5, 0.5, 0.5}, {1, 1, 1}};
    load_ply(options);
    return 0;
}
