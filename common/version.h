// SPDX-License-Identifier: Apache-2.0
// The part of hmcr's version that names a result's bits (docs/design.md §9): versions with the
// same major and minor numbers give the same bits for the same inputs, settings and seed.
#pragma once

#include <string_view>

namespace hmcr {

constexpr std::string_view bits_version() {
    constexpr std::string_view version = HMCR_VERSION;
    return version.substr(0, version.rfind('.'));
}

}  // namespace hmcr
