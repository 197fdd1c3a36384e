// SPDX-License-Identifier: Apache-2.0
// What VTK's XML reader would allocate for a .vtp, checked before it runs: VTK trusts the
// sizes a file declares (a damaged block count in an appended section makes it allocate
// gigabytes), so every declared count and every appended array's header must fit the
// bytes that are really there.
#pragma once

#include <filesystem>

namespace hmcr {

// Throws InputError naming the file when its XML part is refused (viz/vtp_header.h: among
// others a count attribute, NumberOfPoints, NumberOfTuples, ..., beyond what zlib's largest
// ratio, 1032:1, could expand the file to) or an appended array's header or blocks run past
// the file's end.
void check_vtp_envelope(const std::filesystem::path& path);

}  // namespace hmcr
