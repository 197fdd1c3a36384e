// SPDX-License-Identifier: Apache-2.0
// The values of a PLY file's elements after its header (meshes/ply_header.h), one instance at a
// time: an ascii instance is one line of numbers, a binary one its values packed in the header's
// order, in the file's byte order. Every problem is an InputError "path:line: why" (ascii) or
// "path: ELEMENT N: why" (binary).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "common/error.h"
#include "meshes/obj_lines.h"
#include "meshes/ply_header.h"
#include "meshes/single_precision.h"

namespace hmcr {

class PlyCursor {
public:
    PlyCursor(std::string_view bytes, const PlyHeader& header, const std::string& path)
        : m_bytes(bytes),
          m_offset(header.data_offset),
          m_line(header.data_line - 1),
          m_format(header.format),
          m_path(path) {}

    bool ascii() const { return m_format == PlyFormat::ascii; }

    // Starts instance `index` (from 0) of the element called noun.
    void begin(const std::string& noun, std::uint64_t index) {
        m_noun = &noun;
        m_index = index;
        if (!ascii()) return;
        do {
            if (m_offset >= m_bytes.size()) fail("the file ends before the header's last element");
            ++m_line;
            const std::size_t end = m_bytes.find('\n', m_offset);
            const std::size_t stop = end == std::string_view::npos ? m_bytes.size() : end;
            m_rest = m_bytes.substr(m_offset, stop - m_offset);
            m_offset = end == std::string_view::npos ? m_bytes.size() : end + 1;
            if (!m_rest.empty() && m_rest.back() == '\r') m_rest.remove_suffix(1);
        } while (next_token_is_empty());
    }

    // Ends the instance: an ascii line must hold nothing more.
    void end() {
        if (ascii() && !token().empty()) fail("more values than the header's properties");
    }

    // The place of the instance: its line (ascii) or its number from 1 (binary).
    std::uint32_t place() const {
        return ascii() ? std::uint32_t(m_line) : std::uint32_t(m_index + 1);
    }

    [[noreturn]] void fail(const std::string& message) const {
        if (ascii()) fail_at_line(m_path, m_line, message);
        throw InputError(m_path, fmt::format("{} {}: {}", *m_noun, m_index + 1, message));
    }

    double scalar(PlyType type) {
        if (ascii()) return ascii_value(type);
        switch (type) {
            case PlyType::int8:
                return binary<std::int8_t>();
            case PlyType::uint8:
                return binary<std::uint8_t>();
            case PlyType::int16:
                return binary<std::int16_t>();
            case PlyType::uint16:
                return binary<std::uint16_t>();
            case PlyType::int32:
                return binary<std::int32_t>();
            case PlyType::uint32:
                return binary<std::uint32_t>();
            case PlyType::float32:
                return finite(widen_float(binary<float>()));
            case PlyType::float64:
                return finite(binary<double>());
        }
        return 0;
    }

    // A list's count, or an index: a non-negative integer.
    std::uint64_t count(PlyType type, const char* what) {
        const double value = scalar(type);
        if (value < 0) fail(fmt::format("negative {} {}", what, value));
        return std::uint64_t(value);
    }

private:
    bool next_token_is_empty() {
        std::size_t i = 0;
        while (i < m_rest.size() && (m_rest[i] == ' ' || m_rest[i] == '\t')) ++i;
        return i == m_rest.size();
    }

    std::string_view token() {
        std::size_t i = 0;
        while (i < m_rest.size() && (m_rest[i] == ' ' || m_rest[i] == '\t')) ++i;
        std::size_t j = i;
        while (j < m_rest.size() && m_rest[j] != ' ' && m_rest[j] != '\t') ++j;
        const std::string_view t = m_rest.substr(i, j - i);
        m_rest.remove_prefix(j);
        return t;
    }

    double finite(double value) const {
        if (!std::isfinite(value)) fail("a value that is not a finite number");
        return value;
    }

    double ascii_value(PlyType type) {
        const std::string_view t = token();
        if (t.empty()) fail("fewer values than the header's properties");
        if (!is_ply_integer(type)) return parse_obj_number(t, m_path, m_line);
        long long value = 0;
        const char* end = t.data() + t.size();
        const auto [ptr, ec] = std::from_chars(t.data() + (t[0] == '+' ? 1 : 0), end, value);
        const int bits = 8 * ply_type_bytes(type);
        const bool is_signed =
            type == PlyType::int8 || type == PlyType::int16 || type == PlyType::int32;
        const long long low = is_signed ? -(1LL << (bits - 1)) : 0;
        const long long high = is_signed ? (1LL << (bits - 1)) - 1 : (1LL << bits) - 1;
        if (ec != std::errc{} || ptr != end || value < low || value > high) {
            fail(fmt::format("{} is not a value of type {}", quote(t), ply_type_name(type)));
        }
        return double(value);
    }

    template <class T>
    double binary() {
        if (m_bytes.size() - m_offset < sizeof(T)) {
            fail("the file ends before the header's last element");
        }
        std::array<char, sizeof(T)> raw;
        std::memcpy(raw.data(), m_bytes.data() + m_offset, sizeof(T));
        m_offset += sizeof(T);
        const bool big = m_format == PlyFormat::binary_big_endian;
        if (big != (std::endian::native == std::endian::big)) std::reverse(raw.begin(), raw.end());
        T value;
        std::memcpy(&value, raw.data(), sizeof(T));
        return double(value);
    }

    std::string_view m_bytes;
    std::size_t m_offset;
    int m_line;
    PlyFormat m_format;
    const std::string& m_path;
    std::string_view m_rest;  // ascii: the rest of the instance's line
    const std::string* m_noun = nullptr;
    std::uint64_t m_index = 0;
};

}  // namespace hmcr
