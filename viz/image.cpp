#include "viz/image.h"

#include <fmt/format.h>
#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include "common/atomic_file.h"
#include "common/text_file.h"
#include "viz/tone_map.h"
#include "viz/vtk_console.h"

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

// VTK images have their origin at the bottom left: memory row r is VTK row height - 1 - r.
std::size_t vtk_index(int width, int height, int x, int row) {
    return std::size_t(height - 1 - row) * width + x;
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
    silence_vtk_console();
    check_shape(image.width, image.height, image.pixels.size());
    vtkNew<vtkImageData> data;
    data->SetDimensions(image.width, image.height, 1);
    data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* scalars = static_cast<unsigned char*>(data->GetScalarPointer());
    for (int row = 0; row < image.height; ++row) {
        for (int x = 0; x < image.width; ++x) {
            std::memcpy(scalars + 3 * vtk_index(image.width, image.height, x, row),
                        image.at(x, row).data(), 3);
        }
    }
    write_file_atomically(path, [&](const std::filesystem::path& tmp) {
        vtkNew<vtkPNGWriter> writer;
        writer->SetFileName(tmp.string().c_str());
        writer->SetInputData(data);
        writer->Write();
        if (writer->GetErrorCode() != 0) {
            throw InputError("cannot write " + path.string(),
                             vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode()));
        }
    });
}

void write_png(const std::filesystem::path& path, const Image& image, double exposure) {
    write_png(path, quantise(image, exposure));
}

Image8 read_png(const std::filesystem::path& path) {
    silence_vtk_console();
    if (!std::filesystem::is_regular_file(path)) throw file_error(path, "no such file");
    vtkNew<vtkPNGReader> reader;
    if (!reader->CanReadFile(path.string().c_str())) throw file_error(path, "not a PNG file");
    reader->SetFileName(path.string().c_str());
    reader->Update();
    vtkImageData* data = reader->GetOutput();
    int dims[3] = {0, 0, 0};
    data->GetDimensions(dims);
    const int channels = data->GetNumberOfScalarComponents();
    if (reader->GetErrorCode() != 0 || dims[0] <= 0 || dims[1] <= 0 || dims[2] != 1) {
        throw file_error(path, "cannot read the PNG");
    }
    if (data->GetScalarType() != VTK_UNSIGNED_CHAR || (channels != 3 && channels != 4)) {
        throw file_error(path, "not an 8-bit RGB or RGBA PNG");
    }
    const auto* scalars = static_cast<const unsigned char*>(data->GetScalarPointer());
    Image8 out(dims[0], dims[1]);
    for (int row = 0; row < out.height; ++row) {
        for (int x = 0; x < out.width; ++x) {
            std::memcpy(out.at(x, row).data(),
                        scalars + channels * vtk_index(out.width, out.height, x, row), 3);
        }
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
                    throw file_error(path, fmt::format("pixel ({}, {}) has radiance {}", x, row, v));
                }
                out.at(x, row)[k] = v;
            }
        }
    }
    return out;
}

}  // namespace hmcr
