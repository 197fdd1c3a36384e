// SPDX-License-Identifier: Apache-2.0
// A scene without views, as a user meets it: a bare OBJ of a closed room with z up renders lit
// from its default view; an image that comes out black says so; `hmcr info --bounds` prints what
// writing a view takes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "image/image.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

// room.obj and room.mtl: the box [0, 4] x [0, 3] x [0, 2.5], 3 x 3 grey quads a wall, facing in,
// the ceiling's (z = 2.5) middle quad a light. OBJ's faces are two-sided by default.
void write_z_up_room(const fs::path& dir) {
    std::ofstream(dir / "room.mtl") << "newmtl wall\nKd 0.6 0.6 0.6\nnewmtl light\nKd 0 0 0\n"
                                       "Ke 5 5 5\n";
    std::ofstream obj(dir / "room.obj");
    obj << "mtllib room.mtl\n";
    int vertices = 0;
    for (const TestPolygon& p :
         inward_box({0, 0, 0}, {4, 3, 2.5}, 3, Rgb::Constant(0.6), Rgb::Zero())) {
        Vec3 c = Vec3::Zero();
        for (const Vec3& v : p.corners) c += v / double(p.corners.size());
        const bool light = c.z() == 2.5 && c.x() == 2 && c.y() == 1.5;
        obj << "usemtl " << (light ? "light" : "wall") << "\n";
        for (const Vec3& v : p.corners)
            obj << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
        obj << "f";
        for (std::size_t k = 0; k < p.corners.size(); ++k) obj << " " << ++vertices;
        obj << "\n";
    }
}

double lit_share(const fs::path& png) {
    const Image8 image = read_png(png);
    std::size_t lit = 0;
    for (const Srgb8& p : image.pixels) lit += p[0] > 0 || p[1] > 0 || p[2] > 0;
    return double(lit) / double(image.pixels.size());
}

class DefaultViewCli : public testing::Test {
protected:
    void SetUp() override {
        write_z_up_room(m_dir);
        const CliRun solve = run_hmcr("solve room.obj --rays 200000 -q -o room.vtp", m_dir);
        ASSERT_EQ(solve.exit_code, 0) << solve.err;
    }
    TempDir m_temp;
    const fs::path& m_dir = m_temp.path();
};

// Seen from outside, along -z, the room showed the dark outer face of its ceiling: all black.
TEST_F(DefaultViewCli, AZUpClosedRoomWithoutViewsRendersLit) {
    const CliRun r = run_hmcr("render room.vtp --scene room.obj -o room.png", m_dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("is black"), std::string::npos) << r.err;
    EXPECT_GT(lit_share(m_dir / "room.png"), 0.99);
}

TEST_F(DefaultViewCli, ABlackImageIsWarnedOf) {
    // A view from outside the room, looking away from it.
    std::ofstream(m_dir / "away.json")
        << R"({"mesh": "room.obj", "views": [{"name": "away", "position": [2, 1.5, 4],)"
        << R"( "look_at": [2, 1.5, 9]}]})";
    const CliRun r = run_hmcr("render room.vtp --scene away.json -o away.png", m_dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("hmcr: warning: away.png is black: view 'away' sees no lit surface "
                         "(`hmcr info --bounds away.json` prints"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(lit_share(m_dir / "away.png"), 0);
    const CliRun quiet = run_hmcr("render room.vtp --scene away.json -q -o quiet.png", m_dir);
    EXPECT_EQ(quiet.err, "");
}

TEST_F(DefaultViewCli, InfoBoundsPrintsTheBoxTheUpAxisTheEmittersAndTheView) {
    const CliRun r = run_hmcr("info --bounds room.obj", m_dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* line :
         {"room: bounding box (0, 0, 0) to (4, 3, 2.5), 4 x 3 x 2.5 m\n",
          "up: +z (the emitters' centre is at 100% of the box along z)\n",
          "patches: 54 (54 two-sided)\n",
          "views: none of its own; the default view, inside the scene:\n  default: from ("}) {
        EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
    }
    const CliRun j = run_hmcr("info --bounds room.obj --json", m_dir);
    ASSERT_EQ(j.exit_code, 0) << j.err;
    const auto json = nlohmann::json::parse(j.out);
    EXPECT_EQ(json["up"], "+z");
    EXPECT_EQ(json["patches"], 54);
    EXPECT_EQ(json["emitters"], 1);
    EXPECT_EQ(json["hi"], nlohmann::json({4, 3, 2.5}));
    EXPECT_TRUE(json["default_view"].get<bool>());
    EXPECT_EQ(json["views"][0]["up"], nlohmann::json({0, 0, 1}));
    const CliRun vtp = run_hmcr("info --bounds room.vtp", m_dir);
    EXPECT_EQ(vtp.exit_code, 2);
    EXPECT_NE(vtp.err.find("--bounds takes a scene, not a solution"), std::string::npos);
}

}  // namespace
}  // namespace hmcr::test
