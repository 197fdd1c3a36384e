// libFuzzer entry point for load_obj (see README.md in this folder for how to build and run it).
//
// Input: OBJ text, optionally followed by a NUL byte and MTL text. The parts are written to
// fuzz.obj and fuzz.mtl in a private temporary directory (an OBJ reaches the MTL through
// `mtllib fuzz.mtl`, as the seeds do) and loaded with and without a default material. The
// loader may reject any input, but only with a InputError; anything else, or a loaded mesh that
// breaks the loader's guarantees, aborts so that libFuzzer records the input.
#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "meshes/scene.h"

namespace {

namespace fs = std::filesystem;

[[noreturn]] void crash(const char* what) {
    std::fprintf(stderr, "obj_loader_fuzz: %s\n", what);
    std::abort();
}

const fs::path& work_dir() {
    static const fs::path dir = [] {
        std::string pattern = (fs::temp_directory_path() / "hmcr_fuzz_XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr) crash("cannot create a temporary directory");
        return fs::path(pattern);
    }();
    return dir;
}

void write(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// What every mesh load_obj returns must satisfy.
void check_mesh(hmcr::PatchMesh& mesh) {
    if (mesh.n_faces() == 0) crash("loaded a mesh without faces");
    auto reflectance = hmcr::reflectance_prop(mesh);
    auto emission = hmcr::emission_prop(mesh);
    auto line = hmcr::source_line_prop(mesh);
    double emitted = 0;
    for (auto fh : mesh.faces()) {
        const auto valence = mesh.valence(fh);
        if (valence < 3 || valence > 4) crash("face that is neither a triangle nor a quad");
        for (int c = 0; c < 3; ++c) {
            if (!(reflectance[fh][c] >= 0 && reflectance[fh][c] < 1)) crash("bad reflectance");
            if (!(emission[fh][c] >= 0 && std::isfinite(emission[fh][c]))) crash("bad emission");
            emitted += emission[fh][c];
        }
        if (line[fh] <= 0) crash("face without a source line");
    }
    if (!(emitted > 0)) crash("loaded a scene without an emitter");
}

void load(const fs::path& obj, const hmcr::LoadOptions& options) {
    try {
        hmcr::PatchMesh mesh = hmcr::load_obj(obj, options);
        check_mesh(mesh);
    } catch (const hmcr::InputError& e) {
        const std::string what = e.what();
        if (what.empty() || what.find('\n') != std::string::npos) crash("multi-line InputError");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "obj_loader_fuzz: unexpected exception: %s\n", e.what());
        std::abort();
    } catch (...) {
        crash("unexpected non-standard exception");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t split = input.find('\0');
    write(work_dir() / "fuzz.obj", input.substr(0, split));
    write(work_dir() / "fuzz.mtl", split == std::string::npos ? "" : input.substr(split + 1));
    load(work_dir() / "fuzz.obj", {});
    hmcr::LoadOptions options;
    options.default_material = hmcr::Material{"default", {0.5, 0.5, 0.5}, {1, 1, 1}};
    load(work_dir() / "fuzz.obj", options);
    return 0;
}
