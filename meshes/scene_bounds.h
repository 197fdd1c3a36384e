// SPDX-License-Identifier: Apache-2.0
// What a scene's geometry tells someone writing a view for it (`hmcr info --bounds`): its
// bounding box, which axis is probably up, its patches and emitters; and the view that a scene
// without views gets (docs/usage.md#naming-a-scene).
//
// Up: along the axis where the centre of the emitting area lies farthest from the box's middle
// (by more than 10% of the box), towards it: lights hang high. Else against the way most of the
// emitting area faces along an axis (they shine down); else +y, OBJ's convention.
// The default view: inside the room where there is one, else from outside. Inside: from 35% of
// the way from the box's middle to each corner of its floor plan looking across the middle, and
// from the middle looking at each corner, all at mid-height, level, with 60 degrees of vertical
// field. A position counts where each of the six axis rays from it meets a lit side (a front, or
// a two-sided patch's back), the two along up at least half the box's height apart (not inside
// a cupboard); of those views, the one whose 3 x 3 rays across the field go farthest before a
// lit side wins. Outside: from the side of the box (of the six, +z first among near equals)
// towards which the most lit area faces (projected, occlusion ignored), looking at the middle
// with 40 degrees, far enough for the bounding sphere to fit. The hundred-odd rays meet the
// patches by brute force (docs/usage.md#naming-a-scene says what that costs).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>

#include "meshes/patch_mesh.h"
#include "meshes/view.h"

namespace hmcr {

struct SceneBounds {
    Eigen::Vector3d lo{0, 0, 0}, hi{0, 0, 0};  // the bounding box of the vertices, metres
    Eigen::Vector3d up{0, 1, 0};               // the guessed up direction: +-x, +-y or +-z
    std::string up_reason;                     // why: "the emitters face -z", ...
    std::size_t patches = 0, two_sided = 0;
    std::size_t emitters = 0;                // patches with an emitting side
    double emitting_area = 0;                // of their emitting sides, m^2
    Eigen::Vector3d emitted_power{0, 0, 0};  // E * area over the emitting sides, W
};

SceneBounds scene_bounds(const PatchMesh& mesh);

// The view named "default" of a scene without views (see the opening comment); whether it
// stands inside the scene.
struct DefaultView {
    View view;
    bool inside = false;
};
DefaultView default_view(const PatchMesh& mesh, const SceneBounds& bounds);
inline View default_view(const PatchMesh& mesh) {
    return default_view(mesh, scene_bounds(mesh)).view;
}

// "+z", "-x": an axis direction's name.
std::string axis_name(const Eigen::Vector3d& axis);

}  // namespace hmcr
