// SPDX-License-Identifier: Apache-2.0
// Hostile specular materials and the flags of the papers' protocol: each refused in one line
// `file:line: why` with exit code 2 and nothing written (docs/usage.md#bad-input); and the
// radiosity commands say once that they absorb specular light.
#include "tests/hostile/hostile.h"

namespace hmcr::test::hostile_specular {
namespace {

std::string with(std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return text;
}

// The plates' receiver (plates.mtl lines 4-6) given a specular part.
std::string receiver(const std::string& lines) {
    return with(kPlatesMtl, "Kd 0.5 0.5 0.5\n", "Kd 0.5 0.5 0.5\n" + lines);
}

TEST_F(Hostile, BadSpecularMtlIsRefusedWithItsLine) {
    const std::pair<std::string, std::string> cases[] = {
        {receiver("illum 3\nKs 0.6 0.6 0.6\n"),
         "plates.mtl:7: diffuse + specular reflectance 1.1 of material 'receiver' is above 1"},
        {receiver("illum 4\n"), "plates.mtl:6: illum 4 is not supported"},
        {receiver("illum 9\n"), "plates.mtl:6: illum 9 is not supported"},
        {receiver("illum 3\nKs 0.2 -0.2 0.2\n"), "plates.mtl:7: specular reflectance -0.2"},
    };
    for (const auto& [mtl, needle] : cases) {
        plates(kPlatesObj, mtl);
        refused("solve plates.obj -o out.vtp", needle);
        refused("trace plates.json -o out.png", needle);
    }
    plates(kPlatesObj, receiver("illum 3\nKs 0.5 0.5 0.5\n"));
    refused("trace plates.json --strict -o out.png",
            "plates.mtl:7: diffuse + specular reflectance 1 of material 'receiver' is not below 1");
}

// The plates as MGF, one-sided, the receiver's material on lines 4-6.
constexpr const char* kPlatesMgf =
    "m emitter =\n ed 1\n sides 1\nm receiver =\n rd 0.5\n sides 1\n"
    "v a =\n p 0 0 0\nv b =\n p 1 0 0\nv c =\n p 1 1 0\nv d =\n p 0 1 0\n"
    "v e =\n p 0 0 1\nv f =\n p 1 0 1\nv g =\n p 1 1 1\nv h =\n p 0 1 1\n"
    "m emitter\nf a b c d\nm receiver\nf e h g f\n";

TEST_F(Hostile, BadSpecularMgfIsRefusedWithItsLine) {
    const std::pair<std::string, std::string> cases[] = {
        {with(kPlatesMgf, " rd 0.5\n", " rd 0.5\n rs 0.4 -0.05\n"),
         "plates.mgf:6: rs roughness -0.05 is not in [0, 1] (0: a mirror)"},
        {with(kPlatesMgf, " rd 0.5\n", " rd 0.5\n rs 2 0.1\n"), "plates.mgf:6: rs 2 is not in"},
    };
    for (const auto& [mgf, needle] : cases) {
        m_temp.write("plates.mgf", mgf);
        refused("solve plates.mgf -o out.vtp", needle);
        refused("trace plates.mgf -o out.png", needle);
    }
    // rd + rs above 1 is a repair (a smaller rs) that a strict load refuses.
    m_temp.write("plates.mgf", with(kPlatesMgf, " rd 0.5\n", " rd 0.5\n rs 0.6 0.1\n"));
    refused("solve plates.mgf --strict -o out.vtp",
            "plates.mgf:6: diffuse + specular reflectance 1.1 of material 'receiver' is not "
            "below 1");
}

TEST_F(Hostile, BadAllocationAndSppListsAreRefused) {
    plates();
    refused("trace plates.json -o out.png --sampler kl --allocation maps",
            "allocation must be refine or map, got 'maps'");
    accepted("trace-reference plates.json --spp 8 --width 8 -o ref -q");
    const std::pair<std::string, std::string> cases[] = {
        {"--spp 16,16", "study: spp 16 is given twice"},
        {"--spp 16,,32", "empty item in the list"},
        {"--spp 16,abc", "spp: 'abc' is not a positive number"},
        {"--spp 0", "spp: '0' is not a positive number"},
        {"--spp 4", "spp must be in 8..32 for sampler kl"},
    };
    for (const auto& [flags, needle] : cases)
        refused("study plates.json --reference ref --samplers kl -o study " + flags, needle);
}

// A radiosity command on a scene with mirrors says once that the engine absorbs their light.
TEST_F(Hostile, RadiosityCommandsWarnOnceAboutSpecularSurfaces) {
    plates(kPlatesObj,
           with(kPlatesMtl, "Kd 0.5 0.5 0.5\n", "Kd 0.2 0.2 0.2\nillum 3\nKs 0.7 0.7 0.7\n"));
    const CliRun solve = accepted("solve plates.json --rays 2000 -o out.vtp");
    const std::string warning = "hmcr: warning: 1 of 2 patches of plates reflect specularly";
    EXPECT_NE(solve.err.find(warning), std::string::npos) << solve.err;
    EXPECT_EQ(solve.err.find(warning), solve.err.rfind(warning)) << solve.err;
    const CliRun render = accepted("render out.vtp --scene plates.json -o out.png");
    EXPECT_NE(render.err.find("this image shows them with their diffuse radiosity alone"),
              std::string::npos)
        << render.err;
    const CliRun trace = accepted("trace plates.json --spp 8 --width 8 -o trace.png");
    EXPECT_EQ(trace.err.find("reflect specularly"), std::string::npos) << trace.err;
}

}  // namespace
}  // namespace hmcr::test::hostile_specular
