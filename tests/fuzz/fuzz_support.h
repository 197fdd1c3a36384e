// SPDX-License-Identifier: Apache-2.0
// What every fuzz target shares: a private folder for the files a reader reads, and the one rule
// of hmcr's readers: reject anything, but only with a one-line InputError. Any other exception,
// a crash or a sanitizer report aborts, so that libFuzzer keeps the input.
#pragma once

#include <stdlib.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/error.h"

namespace hmcr::fuzz {

[[noreturn]] inline void crash(const std::string& what) {
    std::fprintf(stderr, "fuzz: %s\n", what.c_str());
    std::abort();
}

inline const std::filesystem::path& work_dir() {
    static const std::filesystem::path dir = [] {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "hmcr_fuzz_XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr) crash("cannot create a temporary folder");
        return std::filesystem::path(pattern);
    }();
    return dir;
}

inline std::filesystem::path write(const std::string& name, const std::string& bytes) {
    const std::filesystem::path path = work_dir() / name;
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    return path;
}

// Runs `read`; an InputError of one line is a fine answer, anything else is a finding.
template <class Read>
void expect_only_input_errors(Read&& read) {
    try {
        read();
    } catch (const InputError& e) {
        const std::string what = e.what();
        if (what.empty() || what.find('\n') != std::string::npos || what.size() > 2000) {
            crash("an InputError that is not one short line: " + what.substr(0, 200));
        }
    } catch (const std::exception& e) {
        crash(std::string("unexpected exception: ") + e.what());
    } catch (...) {
        crash("unexpected non-standard exception");
    }
}

}  // namespace hmcr::fuzz
