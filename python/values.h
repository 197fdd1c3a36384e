// SPDX-License-Identifier: Apache-2.0
// Values between Python and hmcr: keywords as settings, JSON as Python data, vectors and images
// as numpy arrays.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "image/image.h"
#include "meshes/scene.h"
#include "radiosity/solver_options.h"

namespace hmcr::python {

namespace py = pybind11;

// A keyword's value as the JSON a scene file's "solver" object would hold.
nlohmann::json keyword_json(const py::handle& value);

// The options of a solve of `scene`: `base`, then the scene file's "solver" object but for the
// keys in `not_from_scene`, then the keywords, as `hmcr solve` takes its flags over the scene
// file; each value checked as it is set, with the command line's messages.
SolverOptions solve_options(const Scene& scene, const py::kwargs& keywords, SolverOptions base = {},
                            const std::set<std::string>& not_from_scene = {});

// JSON as the Python data json.loads makes of it.
py::object python_json(const nlohmann::json& j);

// An image as an H x W x 3 array of linear radiance, W sr^-1 m^-2, the top row first.
py::array_t<double> image_array(const Image& image);

template <class T>
py::array_t<T> vector_array(const std::vector<T>& v) {
    return py::array_t<T>(py::ssize_t(v.size()), v.data());
}

// An N x 3 array of the vectors or colours.
template <class V>
py::array_t<double> rows3(const std::vector<V>& v) {
    py::array_t<double> a({py::ssize_t(v.size()), py::ssize_t(3)});
    auto m = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < v.size(); ++i) {
        for (int c = 0; c < 3; ++c) m(py::ssize_t(i), c) = v[i][c];
    }
    return a;
}

}  // namespace hmcr::python
