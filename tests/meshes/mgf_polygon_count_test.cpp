// SPDX-License-Identifier: Apache-2.0
// Counting MGF polygons without making them: each entity's count is what the reader makes, arrays
// and includes multiply, and nesting, cycles and overflow are handled.
#include "meshes/mgf_polygon_count.h"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <memory>

#include "meshes/mgf_reader.h"
#include "tests/meshes/scene_files.h"

namespace hmcr {
namespace {

using test::contains;
using test::scene_error;
using test::SceneFiles;

// Vertices for every entity (lines 1-10): a square q0..q3 in z = 0 with a normal, and q4 above.
constexpr const char* kCountVertices =
    "v q0 =\n p 0 0 0\n n 0 0 1\nv q1 =\n p 1 0 0\nv q2 =\n p 1 1 0\nv q3 =\n p 0 1 0\n"
    "v q4 =\n p 0 0 2\n";

// The files of one folder as the reader reads them, for the counter.
class CountedFiles {
public:
    explicit CountedFiles(const SceneFiles& files) : m_files(files) {}

    const MgfFile& file(const std::string& name) {
        auto& slot = m_read[name];
        if (!slot) slot = std::make_unique<MgfFile>(read_mgf_file(m_files.path() / name, 0));
        return *slot;
    }
    std::uint64_t count(const std::string& name, int segments = 24) {
        MgfPolygonCount counter(
            segments,
            [this](const MgfFile&, const MgfStatement& i, const std::string&) -> const MgfFile& {
                return file(i.words[1]);
            });
        return counter.whole(file(name));
    }

private:
    const SceneFiles& m_files;
    std::map<std::string, std::unique_ptr<MgfFile>> m_read;
};

std::size_t made(const SceneFiles& files, const std::string& name, int segments = 24) {
    MgfOptions options;
    options.curve_segments = segments;
    return read_mgf(files.path() / name, options).polygon_count();
}

TEST(MgfPolygonCount, EachEntityCountsWhatTheReaderMakes) {
    const char* entities[] = {
        "f q0 q1 q2 q3",  "sph q0 1",         "sph q0 -2",           "cyl q0 1 q4",
        "cone q0 1 q4 0", "cone q0 0.5 q4 1", "ring q0 0.5 1",       "ring q0 0 1",
        "torus q0 0.5 1", "prism q0 q1 q2 1", "prism q0 q1 q2 q3 -1"};
    for (int segments : {4, 7, 24, 64}) {
        for (const char* e : entities) {
            SceneFiles files;
            files.write("one.mgf", std::string(kCountVertices) + e + "\n");
            CountedFiles counted(files);
            EXPECT_EQ(counted.count("one.mgf", segments), made(files, "one.mgf", segments))
                << e << " at " << segments;
        }
    }
}

TEST(MgfPolygonCount, ArraysAndIncludesMultiply) {
    SceneFiles files;
    files.write("leg.mgf", std::string(kCountVertices) + "cyl q0 0.1 q4\n");
    files.write("table.mgf", std::string(kCountVertices) +
                                 "prism q0 q1 q2 q3 0.1\n"
                                 "i leg.mgf -a 2 -t 1 0 0 -a 2 -t 0 1 0\n");
    files.write("room.mgf", std::string(kCountVertices) +
                                "xf -a 3 -t 3 0 0\n"
                                "f q0 q1 q2 q3\nxf -rz 90\ni table.mgf\nxf\n"
                                "xf\n"
                                "xf -i 5 -t 0 0 1\nsph q0 1\nxf\n");
    CountedFiles counted(files);
    const std::uint64_t table = 6 + 4 * 24;
    EXPECT_EQ(counted.count("table.mgf"), table);
    EXPECT_EQ(counted.count("room.mgf"), 3 * (1 + table) + 12 * 24);
    EXPECT_EQ(counted.count("room.mgf"), made(files, "room.mgf"));
}

// 10^9 instances nested 10 deep are more than 2^64 polygons: the count saturates.
TEST(MgfPolygonCount, CountsBeyondTwoToTheSixtyFourSaturate) {
    SceneFiles files;
    std::string text = kCountVertices;
    for (int i = 0; i < 10; ++i) text += "xf -a 1000000000 -t 1 0 0\n";
    text += "sph q0 1\n";
    for (int i = 0; i < 10; ++i) text += "xf\n";
    files.write("many.mgf", text);
    CountedFiles counted(files);
    EXPECT_EQ(counted.count("many.mgf"), std::numeric_limits<std::uint64_t>::max());
    EXPECT_TRUE(contains(scene_error([&] { read_mgf(files.path() / "many.mgf"); }),
                         "many.mgf:12: more than 50000000 polygons: the array makes more than "
                         "2^64"));
}

// Nesting far beyond what the reader runs is counted without recursion.
TEST(MgfPolygonCount, DeepNestingIsCountedWithoutRecursion) {
    SceneFiles files;
    std::string text = std::string(kCountVertices) + "xf -a 2 -t 1 0 0\n";
    for (int i = 0; i < 50000; ++i) text += "xf -t 0 0 0\n";
    text += "f q0 q1 q2\n";
    for (int i = 0; i <= 50000; ++i) text += "xf\n";
    files.write("deep.mgf", text);
    CountedFiles counted(files);
    EXPECT_EQ(counted.count("deep.mgf"), 2u);
}

TEST(MgfPolygonCount, IncludeCyclesAreRefused) {
    SceneFiles files;
    files.write("a.mgf", "i b.mgf\n");
    files.write("b.mgf", "f q0 q1 q2\ni a.mgf\n");
    CountedFiles counted(files);
    EXPECT_TRUE(contains(scene_error([&] { counted.count("a.mgf"); }),
                         "b.mgf:2: the file includes itself"));
}

}  // namespace
}  // namespace hmcr
