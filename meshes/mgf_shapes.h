// SPDX-License-Identifier: Apache-2.0
// MGF's surface primitives as polygons (docs/usage.md#mgf). A circle is cut into `segments` equal
// segments (--mgf-segments, default 24), a sphere into `segments` around and segments / 2 from
// pole to pole. Corners lie on the true surface, so the polygons' area is below it: by at most
// (pi / segments)^2 of the true area (a sphere: 5/6 of that, 1.4% at 24 segments).
//
// Each polygon is counter-clockwise seen from outside (away from the axis, the centre, or the
// tube's core; for `ring`, from the side its normal points to); the reader reverses it for a
// negative radius or length.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace hmcr {

using MgfPolygon = std::vector<Eigen::Vector3d>;

std::vector<MgfPolygon> tessellate_sphere(const Eigen::Vector3d& centre, double radius,
                                          int segments);
// A cone frustum from a (radius ra) to b (radius rb), open at both ends; a cylinder has
// ra == rb; one radius may be 0 (a point).
std::vector<MgfPolygon> tessellate_cone(const Eigen::Vector3d& a, double ra,
                                        const Eigen::Vector3d& b, double rb, int segments);
// The flat ring rmin <= r <= rmax around the centre, in the plane normal to `normal`.
std::vector<MgfPolygon> tessellate_ring(const Eigen::Vector3d& centre,
                                        const Eigen::Vector3d& normal, double rmin, double rmax,
                                        int segments);
// The torus whose cross-section in a plane through its axis spans rmin to rmax from the axis.
std::vector<MgfPolygon> tessellate_torus(const Eigen::Vector3d& centre,
                                         const Eigen::Vector3d& normal, double rmin, double rmax,
                                         int segments);
// The closed prism over the base polygon, extruded by `length` against its right-hand normal
// (MGF's rule): the base, the far face and one quad per base edge.
std::vector<MgfPolygon> extrude_prism(const MgfPolygon& base, double length);

}  // namespace hmcr
