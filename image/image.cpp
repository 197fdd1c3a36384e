// SPDX-License-Identifier: Apache-2.0
#include "image/image.h"

#include <fmt/format.h>
#include <png.h>

#include <bit>
#include <cmath>
#include <csetjmp>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include "common/atomic_file.h"
#include "common/text_file.h"
#include "image/tone_map.h"

namespace hmcr {
namespace {

void check_shape(int width, int height, std::size_t pixel_count) {
    if (width <= 0 || height <= 0 || pixel_count != std::size_t(width) * std::size_t(height)) {
        throw std::invalid_argument("image of " + std::to_string(width) + " x " +
                                    std::to_string(height) + " with " +
                                    std::to_string(pixel_count) + " pixels");
    }
}

InputError file_error(const std::filesystem::path& path, const std::string& what) {
    return InputError(path.string(), what);
}

// A PFM of 16384 x 16384 pixels is 3 GB; larger files are refused unread.
std::string read_bytes(const std::filesystem::path& path) {
    return read_text_file(path, std::uint64_t(3) << 30);
}

void append_float_le(std::string& out, float f) {
    const auto bits = std::bit_cast<std::uint32_t>(f);
    for (int k = 0; k < 4; ++k) out.push_back(char((bits >> (8 * k)) & 0xff));
}

float float_at(const std::string& bytes, std::size_t at, bool little_endian) {
    std::uint32_t bits = 0;
    for (int k = 0; k < 4; ++k) {
        const auto byte = std::uint32_t(std::uint8_t(bytes[at + k]));
        bits |= byte << (8 * (little_endian ? k : 3 - k));
    }
    return std::bit_cast<float>(bits);
}

// libpng reports an error by a longjmp back to the setjmp of the function that called it. The
// functions below hold only plain values and libpng's own structures across those calls, and
// turn a jump into an exception once they are out of libpng.
void append_png_bytes(png_structp png, png_bytep data, png_size_t size) {
    auto* out = static_cast<std::string*>(png_get_io_ptr(png));
    try {
        out->append(reinterpret_cast<const char*>(data), size);
    } catch (...) {
        png_error(png, "out of memory");
    }
}

// 8-bit RGB, zlib level 5 and libpng's default filters (as VTK's PNG writer sets them).
bool encode_png(const Image8& image, std::string& out) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (png == nullptr) return false;
    png_infop info = png_create_info_struct(png);
    if (info == nullptr) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &out, append_png_bytes, nullptr);
    png_set_compression_level(png, 5);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int row = 0; row < image.height; ++row) {
        png_write_row(png, image.pixels[std::size_t(row) * image.width].data());
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

Image8 quantise(const Image& image, double exposure) {
    check_shape(image.width, image.height, image.pixels.size());
    Image8 out(image.width, image.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        out.pixels[i] = to_srgb8(image.pixels[i], exposure);
    }
    return out;
}

void write_png(const std::filesystem::path& path, const Image8& image) {
    check_shape(image.width, image.height, image.pixels.size());
    std::string bytes;
    if (!encode_png(image, bytes)) throw std::runtime_error("cannot encode " + path.string());
    write_text_atomically(path, bytes);
}

void write_png(const std::filesystem::path& path, const Image& image, double exposure) {
    write_png(path, quantise(image, exposure));
}

// The largest image hmcr makes is 16384 pixels a side; a PNG claiming more would be a
// decompression bomb.
constexpr png_uint_32 kMaxPngSide = 16384;

Image8 read_png(const std::filesystem::path& path) {
    if (!std::filesystem::is_regular_file(path)) throw file_error(path, "no such file");
    const std::string bytes = read_bytes(path);
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size())) {
        throw file_error(path, "not a PNG file");
    }
    // 8-bit RGB or RGBA as written; a grey, palette or 16-bit file is not one of hmcr's images.
    const bool rgb8 = (png.format & PNG_FORMAT_FLAG_COLOR) != 0 &&
                      (png.format & (PNG_FORMAT_FLAG_LINEAR | PNG_FORMAT_FLAG_COLORMAP)) == 0;
    if (!rgb8 || png.width == 0 || png.height == 0 || png.width > kMaxPngSide ||
        png.height > kMaxPngSide) {
        png_image_free(&png);
        throw file_error(path, "not an 8-bit RGB or RGBA PNG");
    }
    png.format = PNG_FORMAT_RGB;
    Image8 out(int(png.width), int(png.height));
    if (!png_image_finish_read(&png, nullptr, out.pixels.data(), 0, nullptr)) {
        png_image_free(&png);
        throw file_error(path, "cannot read the PNG");
    }
    return out;
}

void write_pfm(const std::filesystem::path& path, const Image& image) {
    check_shape(image.width, image.height, image.pixels.size());
    std::string bytes =
        "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    bytes.reserve(bytes.size() + 12 * image.pixels.size());
    for (int row = image.height - 1; row >= 0; --row) {  // PFM stores the bottom row first
        for (int x = 0; x < image.width; ++x) {
            for (int k = 0; k < 3; ++k) append_float_le(bytes, float(image.at(x, row)[k]));
        }
    }
    write_text_atomically(path, bytes);
}

Image read_pfm(const std::filesystem::path& path) {
    const std::string bytes = read_bytes(path);
    std::istringstream header(bytes);
    std::string magic;
    long long width = 0, height = 0;
    double scale = 0;
    header >> magic >> width >> height >> scale;
    if (!header || magic != "PF") throw file_error(path, "not a colour PFM (PF) file");
    if (width <= 0 || height <= 0 || width > (1 << 20) || height > (1 << 20) || scale == 0) {
        throw file_error(path, "bad PFM header");
    }
    // Exactly one whitespace character separates the scale from the raster.
    const auto scale_end = header.tellg();
    if (scale_end < 0) throw file_error(path, "PFM has no raster");
    const std::size_t start = std::size_t(scale_end) + 1;
    const std::size_t count = std::size_t(width) * std::size_t(height);
    if (bytes.size() != start + 12 * count) throw file_error(path, "PFM size does not match");
    Image out{int(width), int(height)};
    std::size_t at = start;
    for (int row = out.height - 1; row >= 0; --row) {
        for (int x = 0; x < out.width; ++x, at += 12) {
            for (int k = 0; k < 3; ++k) {
                const float v = float_at(bytes, at + 4 * k, scale < 0);
                // Radiance is finite and not negative; anything else is a broken file.
                if (!(v >= 0 && std::isfinite(v))) {
                    throw file_error(path,
                                     fmt::format("pixel ({}, {}) has radiance {}", x, row, v));
                }
                out.at(x, row)[k] = v;
            }
        }
    }
    return out;
}

}  // namespace hmcr
