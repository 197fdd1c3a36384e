// SPDX-License-Identifier: Apache-2.0
// A ParaView state file (.pvsm) that opens a solution as hmcr means it to be seen: the .vtp
// through ParaView's XMLPolyDataReader, coloured by RadiosityColor with Map Scalars off (the
// array is already sRGB), Gouraud interpolation, and no lighting (ambient 1, diffuse 0, the
// light kit off), so that the colours on screen are the radiosity; the camera is a view of the
// scene, and the view is held at its image size (preview mode), so that ParaView frames it as
// `hmcr render` does. `paraview --state=out/cornell.pvsm` opens it.
//
// Only the proxies and properties that differ from ParaView's defaults are written; ParaView
// (checked with 5.11) fills in the rest when it loads the state.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "meshes/scene.h"

namespace hmcr {

// The state XML for the solution file (named by its absolute path: ParaView reads a state's
// file names as they are) seen from the view; `cull_backfaces` for a solution with two-sided
// patches, whose back polygons lie on their fronts.
std::string paraview_state(const std::filesystem::path& vtp, const View& view,
                           bool cull_backfaces = false);

// Writes paraview_state() atomically.
void write_paraview_state(const std::filesystem::path& pvsm, const std::filesystem::path& vtp,
                          const View& view, bool cull_backfaces = false);

// One solution of a state of several (a study's meshes): its file, its name in ParaView's
// pipeline browser, and whether it is shown when the state opens (the eye beside the name
// shows or hides it).
struct StateSource {
    std::filesystem::path vtp;
    std::string name;
    bool visible = false;
};

// The state of several solutions of one scene, each coloured as above, seen from the view.
std::string paraview_state(const std::vector<StateSource>& sources, const View& view,
                           bool cull_backfaces);
void write_paraview_state(const std::filesystem::path& pvsm,
                          const std::vector<StateSource>& sources, const View& view,
                          bool cull_backfaces);

// Characters of text that XML gives a meaning (& < > " ') as entities.
std::string xml_escape(const std::string& text);

}  // namespace hmcr
