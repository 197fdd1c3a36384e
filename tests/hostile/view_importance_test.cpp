// SPDX-License-Identifier: Apache-2.0
// View importance on views of millions of pixels: it traces them in batches, so its memory does
// not grow with the views' pixels, and it hears SIGTERM between batches
// (docs/usage.md#bad-input).
#include <signal.h>

#include <chrono>
#include <thread>

#include "tests/hostile/hostile.h"
#include "tests/support/hmcr_child.h"

namespace hmcr::test {
namespace {

// The plates seen from between them, the receiver filling a view of `size` x `size` pixels.
std::string covered_view(int size) {
    return R"({"mesh": "plates.obj", "views": [{"name": "up", "position": [0.5, 0.5, 0.1],
        "look_at": [0.5, 0.5, 1], "up": [0, 1, 0], "fov": 40, "width": )" +
           std::to_string(size) + R"(, "height": )" + std::to_string(size) + "}]}";
}

// 25 million pixels that all meet the receiver: each was 4 bytes kept until the view was
// traced (100 MB); in batches the solve's peak is that of the same solve without importance.
TEST_F(Hostile, ViewImportanceMemoryDoesNotGrowWithThePixels) {
    plates(kPlatesObj, kPlatesMtl, covered_view(5000));
    ChildExit e[2];
    const char* importance[2] = {"none", "views"};
    for (int k = 0; k < 2; ++k) {
        HmcrChild child(
            std::string("solve plates.json --rays 20000 -q -o x.vtp --importance ") + importance[k],
            dir(), 60);
        e[k] = child.wait();
        ASSERT_EQ(e[k].code, 0) << e[k].err;
    }
    EXPECT_LT(double(e[1].peak_bytes), double(e[0].peak_bytes) + 24e6)
        << e[0].peak_bytes << " bytes without importance, " << e[1].peak_bytes << " with";
}

// 268 million pixels: minutes of tracing, ended within 2 s of SIGTERM with nothing written.
TEST_F(Hostile, ViewImportanceEndsSoonAfterSigterm) {
    plates(kPlatesObj, kPlatesMtl, covered_view(16384));
    const auto before = snapshot(dir());
    HmcrChild child("solve plates.json --rays 20000 -q -o x.vtp --importance views", dir(), 60);
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
    child.signal(SIGTERM);
    const ChildExit e = child.wait();
    EXPECT_EQ(e.code, 128 + SIGTERM) << e.err;
    EXPECT_LT(e.seconds, 2.0);
    EXPECT_TRUE(snapshot(dir()) == before);
}

}  // namespace
}  // namespace hmcr::test
