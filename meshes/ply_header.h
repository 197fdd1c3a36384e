// SPDX-License-Identifier: Apache-2.0
// The header of a PLY file (the Stanford polygon file format; docs/design.md §11.11): its format
// (ascii, binary little or big endian), its elements with their counts and properties, and where
// the data after `end_header` starts. The counts are checked against the bytes that follow
// before anything is allocated for them: a header of a few lines may declare 10^12 faces.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hmcr {

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

// PLY's scalar types (char, uchar, short, ushort, int, uint, float, double and their sized
// names int8 ... float64).
enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

// Bytes of one value of the type in a binary file.
int ply_type_bytes(PlyType type);
bool is_ply_integer(PlyType type);
// The type's name as PLY's original specification spells it ("uchar").
std::string_view ply_type_name(PlyType type);

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::float32;  // a list's items' type
    bool list = false;
    PlyType count_type = PlyType::uint8;  // a list's count (an integer type)
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    int line = 0;  // of its `element` statement
    std::vector<PlyProperty> properties;

    // The index of the property called name, or -1.
    int find(std::string_view property) const;
};

struct PlyHeader {
    PlyFormat format = PlyFormat::ascii;
    std::vector<PlyElement> elements;
    std::size_t data_offset = 0;  // the first byte after the `end_header` line
    int data_line = 0;            // the line that byte starts (ascii)
};

// Parses the header at the start of `bytes` (the whole file). Throws InputError "path:line: why"
// for anything that is not a PLY header hmcr reads, and for element counts that the bytes after
// the header cannot hold (each value takes at least one byte and a separator in ascii, its
// type's size in binary).
PlyHeader read_ply_header(std::string_view bytes, const std::string& path);

}  // namespace hmcr
