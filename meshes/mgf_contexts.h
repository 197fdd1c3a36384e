// SPDX-License-Identifier: Apache-2.0
// MGF's named contexts (mgf_reader.cpp): the vertex and material values, and the scratch-space
// selection rule shared by c, m and v.
#pragma once

#include <fmt/format.h>

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "common/error.h"
#include "meshes/polygon_soup.h"

namespace hmcr {

struct MgfVertex {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    Eigen::Vector3d n = Eigen::Vector3d::Zero();  // zero: no normal
};

struct MgfMaterial {
    std::string name = "(unnamed)";
    Eigen::Vector3d kd = Eigen::Vector3d::Zero();       // diffuse reflectance, RGB
    Eigen::Vector3d emitted = Eigen::Vector3d::Zero();  // E, RGB
    Eigen::Vector3d ks = Eigen::Vector3d::Zero();       // specular reflectance (rs), RGB
    double roughness = 0;                               // rs's RMS facet slope
    double rd = 0, rs = 0;                              // the luminances rd and rs stated
    int sides = 2;
    SourcePlace kd_at, ed_at, ks_at;
    std::int32_t soup = -1;  // its soup material; -1 when changed since last used
};

// A named context of type T: the selected one is a named entry or the unnamed scratch value.
template <typename T>
class Contexts {
public:
    // c/m/v with 0 to 3 arguments: `c` resets the unnamed context, `c id` selects a defined
    // one, `c id =` defines one with the defaults, `c id = template` with the template's values.
    void select(const std::vector<std::string>& w, const std::string& where, const T& fresh) {
        if (w.size() == 1) {
            m_unnamed = fresh;
            m_current = &m_unnamed;
        } else if (w.size() == 2) {
            m_current = &find(w[1], where);
        } else if (w[2] == "=" && w.size() <= 4) {
            T value = w.size() == 4 ? find(w[3], where) : fresh;
            m_current = &(m_named[w[1]] = std::move(value));
        } else {
            throw InputError(where, fmt::format("'{}' takes [name [= [template]]]", w[0]));
        }
    }
    T& current() { return *m_current; }
    // The named context, without selecting it.
    const T& get(const std::string& name, const std::string& where) const {
        auto it = m_named.find(name);
        if (it == m_named.end())
            throw InputError(where, fmt::format("undefined name {}", quote(name)));
        return it->second;
    }

private:
    T& find(const std::string& name, const std::string& where) {
        auto it = m_named.find(name);
        if (it == m_named.end())
            throw InputError(where, fmt::format("undefined name {}", quote(name)));
        return it->second;
    }

    std::map<std::string, T> m_named;
    T m_unnamed{};
    T* m_current = &m_unnamed;
};

}  // namespace hmcr
