// SPDX-License-Identifier: Apache-2.0
// Scenes from files and from arrays.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "meshes/polygon_soup.h"
#include "python/bindings.h"

namespace hmcr::python {
namespace {

using nlohmann::json;

// The polygons of arrays as a soup of one file, "<arrays>", whose items are faces: a face's
// problem is reported as "<arrays>: face N" (1-based).
PolygonSoup arrays_soup(const py::array_t<double, py::array::c_style | py::array::forcecast>& v,
                        const py::sequence& faces,
                        const py::array_t<double, py::array::c_style | py::array::forcecast>& rho,
                        const py::array_t<double, py::array::c_style | py::array::forcecast>& e,
                        int sides) {
    if (v.ndim() != 2 || v.shape(1) != 3) throw InputError("vertices must be an N x 3 array");
    const auto per_face = [&](const auto& a, const char* what) {
        const bool one = a.ndim() == 1 && a.shape(0) == 3;
        if (!one &&
            !(a.ndim() == 2 && a.shape(1) == 3 && a.shape(0) == py::ssize_t(py::len(faces)))) {
            throw InputError(fmt::format("{} must be 3 values or one row of 3 per face", what));
        }
        return one;
    };
    const bool one_rho = per_face(rho, "reflectance"), one_e = per_face(e, "emission");
    if (sides != 1 && sides != 2)
        throw InputError(fmt::format("sides must be 1 or 2, got {}", sides));
    PolygonSoup soup;
    soup.files.emplace_back("<arrays>");
    soup.item_names[0] = "face";
    const auto vertices = v.unchecked<2>();
    for (py::ssize_t i = 0; i < vertices.shape(0); ++i)
        soup.positions.emplace_back(vertices(i, 0), vertices(i, 1), vertices(i, 2));
    const auto colour = [](const auto& a, bool one, std::size_t f) {
        const double* p = a.data() + (one ? 0 : 3 * f);
        return Eigen::Vector3d(p[0], p[1], p[2]);
    };
    std::size_t f = 0;
    for (const py::handle face : faces) {
        const SourcePlace at{0, std::uint32_t(f + 1)};
        std::vector<std::uint32_t> ids;
        for (const py::handle corner : face.cast<py::sequence>()) {
            const auto id = corner.cast<std::int64_t>();
            if (id < 0 || id >= std::int64_t(soup.positions.size())) {
                throw InputError(soup.where(at), fmt::format("corner {} is not a vertex (0 to {})",
                                                             id, soup.positions.size() - 1));
            }
            ids.push_back(std::uint32_t(id));
        }
        SoupMaterial m;
        m.material.name = fmt::format("face {}", f + 1);
        m.material.kd = colour(rho, one_rho, f);
        m.material.ke = colour(e, one_e, f) / std::numbers::pi;  // E = pi Ke
        m.kd = m.ke = m.ks = at;
        m.sides = sides;
        soup.materials.push_back(m);
        soup.add_polygon(ids, std::int32_t(f), at);
        ++f;
    }
    return soup;
}

}  // namespace

void bind_scenes(py::module_& m) {
    py::class_<Scene>(m, "Scene", "a scene as loaded: its patches, materials and views")
        .def_readonly("name", &Scene::name)
        .def_property_readonly("patch_count",
                               [](const Scene& s) { return std::size_t(s.mesh.n_faces()); })
        .def_readonly("warnings", &Scene::warnings)
        .def_property_readonly("views", [](const Scene& s) {
            std::vector<std::string> names;
            for (const View& v : s.views) names.push_back(v.name);
            return names;
        });

    m.def(
        "load_scene",
        [](const std::string& name_or_path, bool strict, int sides) {
            LoadOptions options;
            options.strict = strict;
            if (sides != 0) options.sides = sides;
            const py::gil_scoped_release released;
            return new Scene(load_scene(name_or_path, options));
        },
        py::arg("scene"), py::arg("strict") = false, py::arg("sides") = 0,
        "a bundled scene's name, a scene .json or a mesh file, loaded as `hmcr solve` loads it");

    m.def(
        "scene_from_arrays",
        [](const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
           const py::sequence& faces,
           const py::array_t<double, py::array::c_style | py::array::forcecast>& reflectance,
           const py::array_t<double, py::array::c_style | py::array::forcecast>& emission,
           int sides, const std::string& name, bool strict, const py::object& views) {
            PolygonSoup soup = arrays_soup(vertices, faces, reflectance, emission, sides);
            std::vector<View> given;
            if (!views.is_none()) {  // as a scene file's "views" array
                const std::string text = py::str(py::module_::import("json").attr("dumps")(views));
                given = read_views(json::parse(text), "<arrays>");
            }
            LoadOptions options;
            options.strict = strict;
            std::unique_ptr<Scene> scene;
            {
                const py::gil_scoped_release released;
                scene.reset(new Scene(load_soup_scene(name, std::move(soup), options)));
            }
            if (!given.empty()) {
                scene->views = std::move(given);
                scene->default_views = false;
            }
            return scene;
        },
        py::arg("vertices"), py::arg("faces"), py::arg("reflectance"), py::arg("emission"),
        py::arg("sides") = 2, py::arg("name") = "arrays", py::arg("strict") = false,
        py::arg("views") = py::none(),
        "a scene of polygons given as arrays; views as a scene file's \"views\" (a list of "
        "dicts), else the default view");
}

}  // namespace hmcr::python
