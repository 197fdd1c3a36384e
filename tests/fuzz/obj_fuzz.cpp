// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: OBJ and MTL (README.md in this folder says how to build and run it).
//
// Input: OBJ text, optionally followed by a NUL byte and MTL text, written to fuzz.obj and
// fuzz.mtl (the seeds reach the MTL with `mtllib fuzz.mtl`), loaded with and without the
// repairs and a default material. A loaded mesh must keep the loader's guarantees.
#include <cstdint>

#include "meshes/scene.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/mesh_checks.h"

namespace hmcr::fuzz {
namespace {

void load(const LoadOptions& options) {
    expect_only_input_errors([&] {
        PatchMesh mesh = load_obj(work_dir() / "fuzz.obj", options);
        check_loaded_mesh(mesh);
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
