// SPDX-License-Identifier: Apache-2.0
// Hostile scenes: every class of bad scene docs/usage.md#bad-input lists, and the cases that once
// hung, crashed or went unnoticed.
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

// One bad OBJ per class of error of docs/usage.md#bad-input.
TEST_F(Hostile, EveryClassOfBadObjIsRefusedWithItsLine) {
    const std::pair<std::string, std::string> cases[] = {
        {with(kPlatesObj, "v 0 0 0", "v 0 nan 0"), "plates.obj:2: 'nan' is not a finite number"},
        {with(kPlatesObj, "v 0 0 0", "v 0 0 zero"), "plates.obj:2: cannot parse number"},
        {with(kPlatesObj, "f 1 2 3 4", "f 1 2 3 9"), "plates.obj:11: vertex reference '9'"},
        {with(kPlatesObj, "f 1 2 3 4", "f 1/5 2 3 4"), "texture coordinate reference '1/5'"},
        {with(kPlatesObj, "f 1 2 3 4", "f 1//2 2 3 4"), "normal reference '1//2'"},
        // The light's only face has no area: the repairs drop it, leaving no light.
        {with(kPlatesObj, "f 1 2 3 4", "f 1 2 2"), "plates.obj: no face emits light"},
        // The receiver, its back, and a third face on its corners.
        {std::string(kPlatesObj) + "f 6 7 8 5\nusemtl emitter\nf 5 8 7 6\n",
         "plates.obj:16: a third face on the same vertices as the faces on lines 13 and 14"},
        {with(kPlatesObj, "f 1 2 3 4", "f 1 3 2 4"), "plates.obj:11: self-intersecting"},
        {with(kPlatesObj, "usemtl emitter\n", ""), "plates.obj:10: face has no material"},
        {with(kPlatesObj, "usemtl emitter", "usemtl emiter"), "material 'emiter', which no"},
        {with(kPlatesObj, "mtllib plates.mtl", "mtllib none.mtl"),
         "plates.obj:1: cannot read "
         "material library 'none.mtl'"},
        {with(kPlatesObj, "v 0 0 0", "vv 0 0 0"), "plates.obj:2: unknown OBJ statement 'vv'"},
        {"", "plates.obj: no faces"},
    };
    for (const auto& [obj, needle] : cases) {
        plates(obj);
        refused("solve plates.obj -o out.vtp", needle);
    }
}

// What the repairs fix (docs/usage.md#repairs) is refused as before with --strict, or a scene
// file's "strict": true.
TEST_F(Hostile, StrictRefusesWhatTheRepairsFix) {
    const std::pair<std::string, std::string> cases[] = {
        {with(kPlatesObj, "f 1 2 3 4", "f 1 2 2"), "plates.obj:11: degenerate face"},
        {with(kPlatesObj, "v 0 1 0", "v 0 1 0.5"), "plates.obj:11: non-planar quad"},
        {with(kPlatesObj, "v 0 1 0", "v 0.8 0.2 0"), "plates.obj:11: non-convex quad"},
        {with(kPlatesObj, "f 1 2 3 4", "f 1 2 3 4 5"), "plates.obj:11: polygon with 5 vertices"},
        {std::string(kPlatesObj) + "f 1 2 3 4\n", "plates.obj:14: duplicate face"},
    };
    for (const auto& [obj, needle] : cases) {
        plates(obj);
        refused("solve plates.obj --strict -o out.vtp", needle);
    }
    plates(kPlatesObj, with(kPlatesMtl, "Kd 0.5 0.5 0.5", "Kd 1 1 1"));
    refused("solve plates.obj --strict -o out.vtp", "plates.mtl:5: reflectance 1 of material");
    plates(with(kPlatesObj, "v 0 1 0", "v 0 1 0.5"), kPlatesMtl,
           with(kPlatesJson, R"({"mesh": "plates.obj", )",
                R"({"mesh": "plates.obj", "strict": true, )"));
    refused("solve plates.json -o out.vtp", "plates.obj:11: non-planar quad");
}

// Without --strict the same files are repaired and solved, and the repairs are said in one line
// on stderr and counted in the summary.
TEST_F(Hostile, RepairsAreMadeAndSaidInOneLine) {
    const std::pair<std::string, std::string> cases[] = {
        {with(kPlatesObj, "v 0 1 0", "v 0 1 0.5"), "1 non-planar quad split (plates.obj:11)"},
        {with(kPlatesObj, "v 0 1 0", "v 0.8 0.2 0"), "1 polygon triangulated (plates.obj:11)"},
        {std::string(kPlatesObj) + "f 5 8 7 6\n", "1 duplicate face dropped (plates.obj:14)"},
    };
    for (const auto& [obj, what] : cases) {
        plates(obj);
        const CliRun r = accepted("solve plates.obj --rays 2000 -o out.vtp");
        EXPECT_NE(r.err.find("hmcr: repaired plates.obj: " + what + " (--strict refuses them)\n"),
                  std::string::npos)
            << r.err;
        const auto summary = nlohmann::json::parse(read_file(dir() / "out.json"));
        EXPECT_EQ(summary["scene"]["repairs"]["count"], 1) << what;
        EXPECT_EQ(summary["scene"]["strict"], false);
    }
    plates(kPlatesObj, with(kPlatesMtl, "Kd 0.5 0.5 0.5", "Kd 1 1 1"));
    const CliRun r = accepted("solve plates.obj --rays 2000 -o out.vtp");
    EXPECT_NE(r.err.find("warning: plates.mtl:5: reflectance 1 of material 'receiver' accepted"),
              std::string::npos)
        << r.err;
}

// A repair line names the mesh one way, its folder and its first place alike, however the path to
// the scene file or the mesh went.
TEST_F(Hostile, ARepairLineNamesTheFileOneWay) {
    plates(with(kPlatesObj, "v 0 1 0", "v 0 1 0.5"));
    m_temp.write("scenes/p.json",
                 with(kPlatesJson, R"({"mesh": "plates.obj", )", R"({"mesh": "../plates.obj", )"));
    for (const char* scene : {"scenes/p.json", "./scenes/../plates.obj"}) {
        const CliRun r = accepted(std::string("solve ") + scene + " --rays 2000 -o out.vtp");
        EXPECT_NE(r.err.find("hmcr: repaired plates.obj: 1 non-planar quad split (plates.obj:11) "
                             "(--strict refuses them)\n"),
                  std::string::npos)
            << scene << "\n"
            << r.err;
    }
}

// A face on another's corners facing the other way is its back side (docs/usage.md#repairs):
// joined with or without --strict, said in one line without the note that --strict refuses it.
TEST_F(Hostile, OppositeFacesAreJoinedAlsoUnderStrict) {
    plates(std::string(kPlatesObj) + "f 6 7 8 5\n");
    for (const char* strict : {"", " --strict"}) {
        const CliRun r = accepted(std::string("solve plates.obj --rays 2000 -o out.vtp") + strict);
        EXPECT_NE(r.err.find("hmcr: repaired plates.obj: 1 face facing away from a coincident one "
                             "joined as its back side (plates.obj:14)\n"),
                  std::string::npos)
            << r.err;
        const auto summary = nlohmann::json::parse(read_file(dir() / "out.json"));
        EXPECT_EQ(summary["scene"]["patches"], 2);
        EXPECT_EQ(summary["scene"]["repairs"]["sides_joined"]["count"], 1) << strict;
    }
}

// Sides are 1 or 2, on the command line, in a scene file and in MGF.
TEST_F(Hostile, SidesOtherThanOneOrTwoAreRefused) {
    plates();
    refused("solve plates.obj -o out.vtp --sides 3", "--sides");
    refused("solve plates.obj -o out.vtp --sides 0", "--sides");
    plates(
        kPlatesObj, kPlatesMtl,
        with(kPlatesJson, R"({"mesh": "plates.obj", )", R"({"mesh": "plates.obj", "sides": 3, )"));
    refused("info plates.json", "plates.json: sides: must be 1 or 2");
    m_temp.write("sides.mgf", "m lamp =\n ed 100\n sides 3\n");
    refused("info sides.mgf", "sides.mgf:3: sides 3 is not 1 or 2");
    m_temp.write("sides.mgf", "m lamp =\n ed 100\n sides 1.5\n");
    refused("info sides.mgf", "sides.mgf:3: sides 1.5 is not 1 or 2");
}

// A third face on the corners of a face and its back, in MGF: one line naming all three.
TEST_F(Hostile, AThirdMgfFaceOnTheCornersOfTwoIsRefused) {
    m_temp.write("third.mgf",
                 "m lamp =\n ed 100\nv a =\n p 0 0 0\nv b =\n p 1 0 0\nv c =\n p 0 1 0\n"
                 "f a b c\nf c b a\nm grey =\n rd 0.5\nf b c a\n");
    refused("solve third.mgf -o out.vtp",
            "third.mgf:13: a third face on the same vertices as the faces on lines 9 and 10: a "
            "surface has two sides");
}

TEST_F(Hostile, EveryClassOfBadMaterialIsRefusedWithItsLine) {
    const std::pair<std::string, std::string> cases[] = {
        {with(kPlatesMtl, "Kd 0.5 0.5 0.5", "Kd 1.2 0.5 0.5"), "plates.mtl:5: reflectance 1.2"},
        {with(kPlatesMtl, "Kd 0.5 0.5 0.5", "Kd 1.0001 0.5 0.5"),
         "plates.mtl:5: reflectance 1.0001 of material 'receiver' is above 1"},
        {with(kPlatesMtl, "Ke 0.3 0.3 0.3", "Ke -1 0.3 0.3"), "plates.mtl:3: emission -1"},
        {with(kPlatesMtl, "Ke 0.3 0.3 0.3", "Ke 0 0 0"), "plates.obj: no face emits light"},
        // Once a solve that never ended: the powers overflowed to infinity.
        {with(kPlatesMtl, "Ke 0.3 0.3 0.3", "Ke 1e300 1 1"), "plates.mtl:3: emission 1e+300"},
        {with(kPlatesMtl, "Kd 0 0 0", "Kd 0 0"), "plates.mtl:2: 'Kd' needs three numbers"},
        {std::string(kPlatesMtl) + "newmtl receiver\n",
         "plates.mtl:7: material 'receiver' is "
         "defined again (first at"},
    };
    for (const auto& [mtl, needle] : cases) {
        plates(kPlatesObj, mtl);
        refused("solve plates.obj -o out.vtp", needle);
    }
}

// A typo that turns a light off is named before the scene is refused for having no light.
TEST_F(Hostile, UnknownMtlStatementIsNamedWithItsLine) {
    plates(kPlatesObj, with(kPlatesMtl, "Ke 0.3 0.3 0.3", "KE 0.3 0.3 0.3"));
    const CliRun r = run_hmcr("solve plates.obj -o out.vtp", dir());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("warning: plates.mtl:3: unknown MTL statement 'KE' ignored"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("no face emits light"), std::string::npos) << r.err;
}

// What other tools write and hmcr once refused: a byte-order mark, comments after data.
TEST_F(Hostile, ByteOrderMarksAndTrailingCommentsAreRead) {
    plates("\xEF\xBB\xBF" + std::string(kPlatesObj),
           "\xEF\xBB\xBF" + with(kPlatesMtl, "Kd 0.5 0.5 0.5", "Kd 0.5 0.5 0.5 # grey"));
    accepted("solve plates.obj --rays 2000 -q -o out.vtp");
    const auto summary = nlohmann::json::parse(read_file(dir() / "out.json"));
    EXPECT_EQ(summary["scene"]["patches"], 2);
}

// A material file that is a device (or a link to one) is refused, not read for ever.
TEST_F(Hostile, SpecialFilesAreRefusedNotRead) {
    plates(with(kPlatesObj, "mtllib plates.mtl", "mtllib zero.mtl"));
    std::filesystem::create_symlink("/dev/zero", dir() / "zero.mtl");
    refused("solve plates.obj -o out.vtp", "is not a regular file");
    refused("info plates.obj", "is not a regular file");
    plates(with(kPlatesObj, "mtllib plates.mtl", "mtllib /dev/zero"));
    refused("solve plates.obj -o out.vtp", "/dev/zero: is not a regular file");
    refused("solve /dev/zero -o out.vtp", "/dev/zero");
}

TEST_F(Hostile, AMegabyteNameGivesAShortMessage) {
    const std::string name(1 << 20, 'x');
    plates(with(kPlatesObj, "usemtl emitter", "usemtl " + name));
    refused("solve plates.obj -o out.vtp", "'xxxxxxxx");
}

TEST_F(Hostile, BadSceneFilesAreRefusedWithFileAndPlace) {
    const std::pair<std::string, std::string> cases[] = {
        {"{\"mesh\": \"plates.obj\",", "plates.json:1: "},
        {R"({"mesh": "plates.obj", "meshh": 1})", "unknown key 'meshh'"},
        {R"({"mesh": "plates.obj", "views": [{"name": "a", "position": [0, 0, 0],
             "look_at": [0, 0, 0]}]})",
         "look_at equals position"},
        {R"({"mesh": "plates.obj", "solver": {"rays": -5}})", "plates.json: solver.rays: "},
        {R"({"mesh": "plates.obj", "solver": {"rays": 1.5}})", "plates.json: solver.rays: "},
        {R"({"mesh": "plates.obj", "solver": {"rays": 1e30}})", "plates.json: solver.rays: "},
        {R"({"mesh": "plates.obj", "solver": {"rays": "abc"}})", "plates.json: solver.rays: "},
        // A long value is cut short (fuzzer: a string of 2,000 characters for rays).
        {R"({"mesh": "plates.obj", "solver": {"rays": ")" + std::string(3000, 'r') + R"("}})",
         "got 'rrrrrrrrrr"},
        {R"({"mesh": "plates.obj", "solver": {"seed": -1}})", "plates.json: solver.seed: "},
        {R"({"mesh": "plates.obj", "solver": {"stop": 2}})", "plates.json: solver.stop: "},
        {R"({"mesh": "plates.obj", "solver": {"threads": 2}})", "unknown setting 'threads'"},
        {R"({"mesh": "none.obj"})", "none.obj: no such file"},
        {R"({"mesh": "plates.stl"})", "hmcr reads meshes of .obj, .mgf, .ply, .gltf, .glb"},
        // JSON strings may hold control characters: the message escapes them and stays one
        // line (found by the scene fuzz target).
        {R"({"mesh": "plates.obj", "descriptio\n": 1})", "unknown key 'descriptio\\n'"},
        {R"({"mesh": "plates.obj", "a\u001b[2Jb": 1})", "unknown key 'a\\x1b[2Jb'"},
        {R"({"mesh": "pla\ntes.obj"})", "pla\\ntes.obj: no such file"},
        // A long key is cut short (fuzzer: a key of a thousand DEL characters).
        {R"({"mesh": "plates.obj", ")" + std::string(2000, 'k') + R"(": 1})", "unknown key 'kkkk"},
        // A long path is cut in the middle, keeping its file name (fuzzer: a mesh of 2,075
        // characters made a message of 2,333).
        {R"({"mesh": ")" + std::string(3000, 'm') + R"(.obj"})", "mmm...mmm"},
        {R"({"mesh": ")" + std::string(3000, 'm') + R"(.obj"})", "mmm.obj: no such file"},
        {R"({"mesh": ")" + std::string(3000, 'm') + R"(.stl"})", "hmcr reads meshes of .obj"},
    };
    for (const auto& [json, needle] : cases) {
        plates(kPlatesObj, kPlatesMtl, json);
        refused("solve plates.json -o out.vtp", needle);
        // The scene file is wrong whatever the command line gives with it.
        refused("solve plates.json --rays 1000 --seed 2 --stop 0.1 -o out.vtp", needle);
    }
}

}  // namespace
}  // namespace hmcr::test
