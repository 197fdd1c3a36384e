// SPDX-License-Identifier: Apache-2.0
// FNV-1a, 64 bits (Fowler, Noll, Vo): fingerprints that are the same on every machine, for
// recognising a scene's geometry or a reference file again. Not for security.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace hmcr {

class Fnv1a {
public:
    void add_byte(unsigned char byte) {
        m_state ^= byte;
        m_state *= 0x100000001b3ULL;
    }
    void add(std::uint64_t word) {
        for (int k = 0; k < 8; ++k) add_byte((word >> (8 * k)) & 0xff);
    }
    void add(std::string_view bytes) {
        for (char c : bytes) add_byte(static_cast<unsigned char>(c));
    }
    std::uint64_t value() const { return m_state; }
    std::string hex() const;  // 16 lowercase hex digits

private:
    std::uint64_t m_state = 0xcbf29ce484222325ULL;
};

// The hex fingerprint of some bytes.
inline std::string text_hash(std::string_view bytes) {
    Fnv1a h;
    h.add(bytes);
    return h.hex();
}

}  // namespace hmcr
