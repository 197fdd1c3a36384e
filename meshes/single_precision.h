// SPDX-License-Identifier: Apache-2.0
// Numbers a file holds in single precision (glTF's positions and colours, a binary PLY's float
// properties), read as doubles (docs/design.md §11.12).
#pragma once

namespace hmcr {

// The double nearest to the shortest decimal that rounds to `value` (0.1f is 0.1, not
// 0.100000001490116...): what writing the float as text, as an OBJ exporter does, and reading
// that back gives. A model exported to OBJ and to glTF or PLY then has the same coordinates.
double widen_float(float value);

}  // namespace hmcr
