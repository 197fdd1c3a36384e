// SPDX-License-Identifier: Apache-2.0
// Images of the renderer and the study: linear radiance (Image) and 8-bit sRGB (Image8), with
// their files. Pixels are row-major, top row first, in memory; each format's own row order is
// handled by its reader and writer. Every write goes through write_file_atomically.
//
// PNG: 8-bit RGB through libpng. PFM (Portable Float Map, "PF"):
// three little-endian float32 per pixel, bottom row first, scale -1.0 in the header; values are
// stored as float, so a round trip is exact for float-representable radiance.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "common/types.h"

namespace hmcr {

// Linear radiance, W sr^-1 m^-2, per pixel.
struct Image {
    int width = 0, height = 0;
    std::vector<Rgb> pixels;  // width * height, row-major, top row first

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(std::size_t(w) * h, Rgb::Zero()) {}
    Rgb& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
    const Rgb& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

using Srgb8 = std::array<std::uint8_t, 3>;

// 8-bit sRGB-encoded colours, the images the docs/design.md §6 metrics compare.
struct Image8 {
    int width = 0, height = 0;
    std::vector<Srgb8> pixels;  // width * height, row-major, top row first

    Image8() = default;
    Image8(int w, int h) : width(w), height(h), pixels(std::size_t(w) * h, Srgb8{0, 0, 0}) {}
    Srgb8& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
    const Srgb8& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

// to_srgb8(pixel, exposure) of every pixel: exposure, clamp to 1, sRGB, rounding to 8 bits.
Image8 quantise(const Image& image, double exposure);

// Throw std::runtime_error naming the file on any I/O or format problem, and
// std::invalid_argument on an empty image or one whose pixel count is not width * height.
void write_png(const std::filesystem::path& path, const Image8& image);
void write_png(const std::filesystem::path& path, const Image& image, double exposure);
Image8 read_png(const std::filesystem::path& path);  // 8-bit RGB or RGBA (alpha dropped)

void write_pfm(const std::filesystem::path& path, const Image& image);
Image read_pfm(const std::filesystem::path& path);  // "PF" files of either byte order

}  // namespace hmcr
