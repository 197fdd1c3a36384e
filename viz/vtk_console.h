// SPDX-License-Identifier: Apache-2.0
// VTK prints its errors and warnings to the console by itself (with its own source file and
// line); hmcr reports failures in one line of its own, so VTK is kept quiet.
#pragma once

namespace hmcr {

// Turns VTK's console output off for the whole process; every VTK reader and writer of hmcr
// calls it first.
void silence_vtk_console();

}  // namespace hmcr
