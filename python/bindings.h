// SPDX-License-Identifier: Apache-2.0
// The module's parts, each binding what it names into hmcr._core (python/module.cpp).
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

#include "information/back_sides.h"

namespace hmcr::python {

namespace py = pybind11;

void bind_scenes(py::module_& m);     // scenes.cpp: Scene, load_scene, scene_from_arrays
void bind_solutions(py::module_& m);  // solutions.cpp: solve, Solution, error, settings
void bind_studies(py::module_& m);    // studies.cpp: references and studies
void bind_measures(py::module_& m);   // measures.cpp: information and the path tracer

// `hmcr info ... --json` of the channel whose states are `states` (a scene's patches, a
// solution's leaves).
py::object channel_information(const ChannelStates& states, std::uint64_t lines,
                               const std::string& method, std::uint64_t seed, py::object progress);

}  // namespace hmcr::python
