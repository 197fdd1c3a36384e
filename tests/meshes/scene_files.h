// Test helper: a fresh temporary directory to write small scene files into, removed at the end
// of the test, so that every loader test states its whole input next to its expectations.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include "meshes/scene.h"

namespace hmcr::test {

class SceneFiles {
  public:
    SceneFiles() {
        static std::atomic<int> counter{0};
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        const std::string name = info != nullptr ? info->name() : "scene";
        m_dir = std::filesystem::temp_directory_path() /
                ("hmcr_" + name + "_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
        std::filesystem::remove_all(m_dir);
        std::filesystem::create_directories(m_dir);
    }
    ~SceneFiles() {
        std::error_code ec;
        std::filesystem::remove_all(m_dir, ec);
    }
    SceneFiles(const SceneFiles&) = delete;
    SceneFiles& operator=(const SceneFiles&) = delete;

    // Writes `text` to dir/name and returns the path.
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const std::filesystem::path path = m_dir / name;
        std::filesystem::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }
    const std::filesystem::path& dir() const { return m_dir; }

  private:
    std::filesystem::path m_dir;
};

// Passes when `text` contains `part`; the failure shows both.
inline testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// The message of the SceneError that `load` throws, or a failure note when it throws none.
template <typename Load>
std::string scene_error(Load&& load) {
    try {
        load();
    } catch (const SceneError& e) {
        return e.what();
    }
    return "<no SceneError thrown>";
}

}  // namespace hmcr::test
