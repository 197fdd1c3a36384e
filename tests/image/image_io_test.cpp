// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>
#include <zlib.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "image/image.h"
#include "image/tone_map.h"
#include "tests/support/image_checks.h"
#include "tests/support/temp_dir.h"

namespace hmcr {
namespace {

using test::read_file;
using test::TempDir;

// A 3 x 2 image whose every value is distinct and float-representable (so a PFM round trip is
// exact), with the top row brighter than the bottom one.
Image test_image() {
    Image im(3, 2);
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) im.at(x, y) = Rgb(x + 0.5, 0.25 * y, 4 - x - y) / 8;
    }
    return im;
}

Image8 test_image8() {
    Image8 im(3, 2);
    for (std::size_t i = 0; i < im.pixels.size(); ++i) {
        im.pixels[i] = {std::uint8_t(40 * i), std::uint8_t(255 - i), std::uint8_t(7 * i + 1)};
    }
    return im;
}

std::string chunk(const std::string& type, const std::string& data) {
    std::string out;
    for (int k = 3; k >= 0; --k) out.push_back(char((data.size() >> (8 * k)) & 0xff));
    const std::string body = type + data;
    out += body;
    const auto crc = crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()));
    for (int k = 3; k >= 0; --k) out.push_back(char((crc >> (8 * k)) & 0xff));
    return out;
}

// A PNG assembled by hand (PNG specification: signature, IHDR, IDAT, IEND; each row prefixed
// with filter type 0), so the reader is checked against the format, not against the writer.
std::string hand_made_png(const Image8& im) {
    std::string raw;
    for (int y = 0; y < im.height; ++y) {  // PNG rows run top to bottom
        raw.push_back(0);
        for (int x = 0; x < im.width; ++x) raw.append(im.at(x, y).begin(), im.at(x, y).end());
    }
    std::string z(compressBound(uLong(raw.size())), '\0');
    uLongf z_size = uLongf(z.size());
    EXPECT_EQ(compress(reinterpret_cast<Bytef*>(z.data()), &z_size,
                       reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size())),
              Z_OK);
    z.resize(z_size);
    std::string ihdr;
    for (const int v : {im.width, im.height}) {
        for (int k = 3; k >= 0; --k) ihdr.push_back(char((v >> (8 * k)) & 0xff));
    }
    ihdr += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, no interlace
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", z) +
           chunk("IEND", "");
}

void append_float(std::string& out, float f, bool little_endian) {
    const auto bits = std::bit_cast<std::uint32_t>(f);
    for (int k = 0; k < 4; ++k) out.push_back(char(bits >> (8 * (little_endian ? k : 3 - k))));
}

// A PFM assembled by hand: bottom row first, as the format says.
std::string hand_made_pfm(const Image& im, bool little_endian) {
    std::string out = "PF\n" + std::to_string(im.width) + " " + std::to_string(im.height) +
                      (little_endian ? "\n-1.0\n" : "\n1.0\n");
    for (int y = im.height - 1; y >= 0; --y) {
        for (int x = 0; x < im.width; ++x) {
            for (int k = 0; k < 3; ++k) append_float(out, float(im.at(x, y)[k]), little_endian);
        }
    }
    return out;
}

TEST(ImageIo, PngReaderFollowsTheFormat) {
    TempDir dir;
    const auto file = dir.write("hand.png", hand_made_png(test_image8()));
    const Image8 read = read_png(file);
    EXPECT_EQ(read.width, 3);
    EXPECT_EQ(read.height, 2);
    EXPECT_EQ(read.pixels, test_image8().pixels);  // top row first in memory and in the file
}

TEST(ImageIo, PngRoundTripIsExact) {
    TempDir dir;
    write_png(dir.path() / "out" / "a.png", test_image8());
    EXPECT_EQ(read_png(dir.path() / "out" / "a.png").pixels, test_image8().pixels);
    EXPECT_EQ(dir.files(), std::vector<std::string>{"out/a.png"});  // no temp file left
    // From a linear image: the quantised pixels, exposure included.
    write_png(dir.path() / "b.png", test_image(), 2.0);
    const Image8 read = read_png(dir.path() / "b.png");
    EXPECT_EQ(read.pixels, quantise(test_image(), 2.0).pixels);
    EXPECT_EQ(read.at(2, 1), to_srgb8(test_image().at(2, 1), 2.0));
}

TEST(ImageIo, PfmReaderFollowsTheFormatInBothByteOrders) {
    TempDir dir;
    for (const bool little : {true, false}) {
        const Image read = read_pfm(dir.write("hand.pfm", hand_made_pfm(test_image(), little)));
        EXPECT_EQ(read.width, 3);
        EXPECT_EQ(read.height, 2);
        EXPECT_TRUE(test::identical(read, test_image())) << "little endian: " << little;
    }
}

TEST(ImageIo, PfmRoundTripIsExactAndLittleEndian) {
    TempDir dir;
    const auto file = dir.path() / "a.pfm";
    write_pfm(file, test_image());
    EXPECT_EQ(read_file(file), hand_made_pfm(test_image(), true));
    EXPECT_TRUE(test::identical(read_pfm(file), test_image()));
    EXPECT_EQ(dir.files(), std::vector<std::string>{"a.pfm"});
}

TEST(ImageIo, FailedWritesThrowAndLeaveNothing) {
    TempDir dir;
    const auto blocker = dir.write("file", "x");  // a regular file where a folder should be
    EXPECT_THROW(write_png(blocker / "a.png", test_image8()), std::exception);
    EXPECT_THROW(write_pfm(blocker / "a.pfm", test_image()), std::exception);
    // The target is a folder: the temp file is written, the rename fails, the temp file goes.
    std::filesystem::create_directories(dir.path() / "folder");
    EXPECT_THROW(write_png(dir.path() / "folder", test_image8()), std::exception);
    EXPECT_THROW(write_pfm(dir.path() / "folder", test_image()), std::exception);
    EXPECT_EQ(dir.files(), std::vector<std::string>{"file"});
    EXPECT_THROW(write_pfm(dir.path() / "empty.pfm", Image{}), std::invalid_argument);
}

TEST(ImageIo, BadFilesAreReportedWithTheirName) {
    TempDir dir;
    const auto text = dir.write("a.png", "not a png");
    EXPECT_THROW(read_png(text), std::runtime_error);
    EXPECT_THROW(read_png(dir.path() / "missing.png"), std::runtime_error);
    EXPECT_THROW(read_pfm(dir.write("b.pfm", "PF\n2 2\n-1.0\nshort")), std::runtime_error);
    try {
        read_pfm(dir.write("c.pfm", "P6\n1 1\n255\nabc"));
        FAIL() << "a PPM was read as a PFM";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("c.pfm"), std::string::npos) << e.what();
    }
}

// A reference image is radiance: a NaN, an infinity or a negative value can only be a broken
// file, and would otherwise turn every error measured against it into NaN.
TEST(ImageIo, PfmPixelsMustBeFiniteAndNotNegative) {
    TempDir dir;
    for (const float bad : {std::nanf(""), INFINITY, -0.5f}) {
        Image im = test_image();
        im.at(1, 0)[2] = bad;
        try {
            read_pfm(dir.write("bad.pfm", hand_made_pfm(im, true)));
            FAIL() << "read a pixel of " << bad;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("bad.pfm"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("pixel (1, 0)"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace hmcr
