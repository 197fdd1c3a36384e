// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: glTF 2.0 (README.md in this folder says how to build and run it).
//
// Input: a .glb file (it starts with "glTF"), or glTF JSON optionally followed by a NUL byte and
// the bytes of its buffer fuzz.bin (the seeds name it as their buffer's uri). Loaded with the
// repairs, with `--strict` and with a default material. A loaded mesh must keep the loader's
// guarantees.
#include <cstdint>

#include "meshes/scene.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/mesh_checks.h"

namespace hmcr::fuzz {
namespace {

void load_gltf(const std::filesystem::path& path, const LoadOptions& options) {
    expect_only_input_errors([&] {
        MeshFile file = load_mesh(path, options);
        check_loaded_mesh(file.mesh);
    });
}

}  // namespace
}  // namespace hmcr::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    const std::string input(reinterpret_cast<const char*>(data), size);
    std::filesystem::path path;
    if (input.rfind("glTF", 0) == 0) {
        path = write("fuzz.glb", input);
    } else {
        const std::size_t split = input.find('\0');
        path = write("fuzz.gltf", input.substr(0, split));
        write("fuzz.bin", split == std::string::npos ? "" : input.substr(split + 1));
    }
    load_gltf(path, {});
    hmcr::LoadOptions strict;
    strict.strict = true;
    load_gltf(path, strict);
    hmcr::LoadOptions options;
    options.default_material = hmcr::Material{"default", {0.5, 0.5, 0.5}, {1, 1, 1}};
    load_gltf(path, options);
    return 0;
}
