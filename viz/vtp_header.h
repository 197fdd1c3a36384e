// SPDX-License-Identifier: Apache-2.0
// The XML part of a .vtp (everything before its appended data), read by expat (the parser VTK
// itself uses) before VTK reads the file: what it declares about the appended arrays, and the
// declarations VTK 9.1 would trust or crash on, refused. docs/design.md §11.4.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hmcr {

// An `offsets` or `connectivity` array of a cell section (Verts, Lines, Strips, Polys). VTK
// sizes a cell array's connectivity by the value of its last offset, not by the bytes stored,
// so their values are checked (vtp_envelope.h), not only their sizes.
struct VtpCellArray {
    std::string section;       // "Verts", "Lines", "Strips" or "Polys"
    std::size_t group = 0;     // which section element of the file (one per section and piece)
    bool offsets = false;      // "offsets", else "connectivity"
    std::string type;          // VTK's type name
    std::string format;        // "appended", "binary" or "ascii"
    std::uint64_t offset = 0;  // appended: where in the appended data
    std::string text;          // binary or ascii: the element's character data
};

// A String array. VTK 9.1 sizes it by its declared count but stores every string its values
// hold, writing past its end for values of more strings (found by the fuzzer), so its strings
// are counted (vtp_envelope.h).
struct VtpStringArray {
    std::string name;           // its Name, for messages
    std::string format;         // "appended", "binary" or "ascii"
    std::uint64_t offset = 0;   // appended: where in the appended data
    std::string text;           // binary or ascii: the element's character data
    std::uint64_t strings = 0;  // components times tuples: the strings VTK sizes it for
};

struct VtpHeader {
    bool compressed = false;       // a `compressor` attribute: arrays are in blocks
    std::string compressor;        // its value: VTK's compressor class
    std::size_t header_width = 4;  // bytes of each number of an array's header (UInt32, UInt64)
    bool base64 = false;           // the appended data is base64 text, not raw bytes
    std::size_t data = std::string_view::npos;  // the '_' marker of the appended data, if any
    std::vector<std::uint64_t> offsets;         // every `offset` attribute, in file order
    std::vector<VtpCellArray> cell_arrays;      // in file order
    std::vector<VtpStringArray> string_arrays;  // in file order
};

// Reads the header of the .vtp whose bytes are `bytes`. Throws InputError "path: damaged VTK
// file: why" on XML that is not well-formed, a document type declaration, an element that no
// .vtp of hmcr holds, an array without one of VTK's types, points of other than 3 components, a
// count (`NumberOf...`) or offset that is not a plain number, a count (or components times
// the largest count) beyond what zlib's largest ratio could expand the file to, a cell
// section's offsets or connectivity, or a String array, of a format VTK does not read or
// without its offset, a FieldData String array without NumberOfTuples, and appended data
// without its '_' marker.
VtpHeader read_vtp_header(const std::string& path, std::string_view bytes);

// zlib's largest expansion is about 1032:1; a file declaring more than this many times its size
// cannot hold it.
inline constexpr double kMaxVtpExpansion = 1100;

}  // namespace hmcr
