// SPDX-License-Identifier: Apache-2.0
// Loader test helpers: scene files in a fresh temporary directory, and error-message checks.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include "meshes/scene.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {

using SceneFiles = TempDir;

// Passes when `text` contains `part`; the failure shows both.
inline testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// The message of the InputError that `load` throws, or a failure note when it throws none.
template <typename Load>
std::string scene_error(Load&& load) {
    try {
        load();
    } catch (const InputError& e) {
        return e.what();
    }
    return "<no InputError thrown>";
}

}  // namespace hmcr::test
