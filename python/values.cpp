// SPDX-License-Identifier: Apache-2.0
#include "python/values.h"

#include <fmt/format.h>

#include "common/error.h"
#include "radiosity/solver_settings.h"

namespace hmcr::python {

using nlohmann::json;

json keyword_json(const py::handle& value) {
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
    if (py::isinstance<py::int_>(value)) {
        const py::int_ i = value.cast<py::int_>();
        if (i < py::int_(0)) return value.cast<std::int64_t>();
        return value.cast<std::uint64_t>();
    }
    if (py::isinstance<py::float_>(value)) return value.cast<double>();
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    throw InputError(fmt::format("a setting must be a number or a string, got a {}",
                                 std::string(py::str(value.get_type().attr("__name__")))));
}

SolverOptions solve_options(const Scene& scene, const py::kwargs& keywords, SolverOptions base,
                            const std::set<std::string>& not_from_scene) {
    json from_scene = scene.solver_defaults;
    for (const std::string& key : not_from_scene) from_scene.erase(key);
    apply_scene_settings(from_scene, scene.source.string(), base);
    json values = json::object();
    for (const auto& [key, value] : keywords) values[py::str(key)] = keyword_json(value);
    apply_settings(values, base);  // each value checked as it is set
    return base;
}

py::object python_json(const json& j) {
    return py::module_::import("json").attr("loads")(j.dump());
}

py::array_t<double> image_array(const Image& image) {
    py::array_t<double> a({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(3)});
    auto m = a.mutable_unchecked<3>();
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) m(y, x, c) = image.at(x, y)[c];
        }
    }
    return a;
}

}  // namespace hmcr::python
