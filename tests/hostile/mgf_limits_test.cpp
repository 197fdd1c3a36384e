// SPDX-License-Identifier: Apache-2.0
// Hostile MGF files: a few lines that ask for unbounded work (deep nesting, huge arrays) or for
// geometry beyond what hmcr can trace, each refused in one line naming its place, quickly and in
// little memory (docs/usage.md#bad-input).
#include <string>

#include "tests/hostile/hostile.h"
#include "tests/support/hmcr_child.h"

namespace hmcr::test {
namespace {

// A light and the vertex c at the origin (lines 1-4), for the cases to build on.
constexpr const char* kLamp = "m lamp =\ned 100\nv c =\np 0 0 0\n";

std::string nested(int depth, const std::string& inside) {
    std::string text = kLamp;
    for (int i = 0; i < depth; ++i) text += "xf -t 0 0 0\n";
    text += inside;
    for (int i = 0; i < depth; ++i) text += "xf\n";
    return text;
}

// 20,000 nested transformations (450 kB) once overflowed the stack: exit 139, no message.
TEST_F(Hostile, DeeplyNestedTransformationsAreRefusedWithTheirLine) {
    m_temp.write("deep.mgf", nested(20000, "sph c 1\n"));
    // Line 5 opens the first xf; the 1,001st opens on line 1,005.
    refused("info deep.mgf", "deep.mgf:1005: transformations and includes nested more than 1000");
    refused("solve deep.mgf -o out.vtp", "deep.mgf:1005: transformations and includes nested");
    // 1,000 levels are read.
    m_temp.write("deep.mgf", nested(1000, "sph c 1\n"));
    accepted("info deep.mgf --lines 1000");
}

// Nesting through includes counts too: each file adds its level to the transformations.
TEST_F(Hostile, NestingThroughIncludesIsCountedTogether) {
    m_temp.write("part.mgf", nested(600, "sph c 1\n"));
    m_temp.write("top.mgf", nested(600, "i part.mgf\n"));
    refused("info top.mgf", "part.mgf:404: transformations and includes nested more than 1000");
}

// Three lines asking for 10^8 spheres took 7.2 GB and 26 s before "more than 50000000
// polygons": the array's polygons are now counted before any is built.
TEST_F(Hostile, AnArrayIsCountedBeforeItIsBuilt) {
    m_temp.write("array.mgf", std::string(kLamp) + "xf -a 100000000 -t 0.001 0 0\nsph c 1\nxf\n");
    const auto before = snapshot(dir());
    HmcrChild child("info array.mgf", dir(), 20);
    const ChildExit e = child.wait();
    EXPECT_EQ(e.code, 2) << e.err;
    EXPECT_NE(e.err.find("array.mgf:5: more than 50000000 polygons: the array makes "
                         "28800000000 (100000000 instances of 288)"),
              std::string::npos)
        << e.err;
    EXPECT_LT(e.seconds, 2.0);
    EXPECT_LT(e.peak_bytes, 500u << 20);
    EXPECT_TRUE(snapshot(dir()) == before);
}

// Arrays within arrays, and arrays of included files, are counted whole at the outer array.
TEST_F(Hostile, ArraysOfArraysAndOfIncludesAreCountedWhole) {
    m_temp.write("inner.mgf",
                 std::string(kLamp) + "xf -a 100000 -t 0.001 0 0\nsph c 1\nxf\n");  // 2.9e7
    m_temp.write("two.mgf", "xf -a 2 -t 0 5 0\ni inner.mgf\nxf\n");
    refused("info two.mgf", "two.mgf:1: more than 50000000 polygons: the array makes 57600000");
    m_temp.write("twice.mgf", "i inner.mgf -a 2 -t 0 5 0\n");
    refused("info twice.mgf", "twice.mgf:1: more than 50000000 polygons");
}

// A sphere of radius 1e300 was "self-intersecting": its coordinates are beyond what the ray
// tracer's single-precision arithmetic holds, and that is what is said.
TEST_F(Hostile, CoordinatesBeyondTheTracersRangeAreRefused) {
    m_temp.write("huge.mgf", std::string(kLamp) + "sph c 1e300\n");
    refused("info huge.mgf", "huge.mgf:5: coordinate -2.58819e+299 is out of range");
    m_temp.write("far.mgf", std::string(kLamp) + "xf -t 2e12 0 0\nsph c 1\nxf\n");
    refused("solve far.mgf -o out.vtp", "far.mgf:6: coordinate 2e+12 is out of range");
    m_temp.write("large.mgf", std::string(kLamp) + "sph c 1e11\n");
    accepted("info large.mgf --lines 1000");
}

}  // namespace
}  // namespace hmcr::test
