// SPDX-License-Identifier: Apache-2.0
// The refinement oracle interface (docs/design.md §4). An oracle sees plain numbers about one
// candidate link, receiver element i and source element j, never a mesh or a ray tracer.
//
// The value of a link is w_ij * geometric_factor(pair), with w_ij = max_c rho_i,c * B_j,c and
// B_j the source's unshot or total radiosity (the solve's link weight, docs/design.md §4.4).
// The geometric factor depends only on the element pair and its sampled lines, so the engine
// may compute it once per (receiver, source) pair and cache it (docs/design.md §4.3). The link is
// accepted when value / Phi_max < epsilon.
#pragma once

#include <span>
#include <string_view>

namespace hmcr {

struct LinkGeometry {
    double receiver_area = 0;        // A_i
    double source_area = 0;          // A_j
    double total_area = 0;           // A_T
    double centre_distance = 0;      // d, between the element centres
    double receiver_cos = 0;         // cos of the receiver normal with the centre line, >= 0
    double source_cos = 0;           // the same at the source, >= 0
    std::span<const double> kernel;  // F_k = F(x_k, y_k) of the N_s lines; empty if unused
};

class Oracle {
public:
    virtual ~Oracle() = default;
    virtual std::string_view name() const = 0;
    virtual std::string_view description() const = 0;  // one line, for `hmcr oracles`
    virtual double default_epsilon() const = 0;
    virtual bool uses_lines() const = 0;  // whether geometric_factor needs LinkGeometry::kernel
    virtual double geometric_factor(const LinkGeometry& g) const = 0;
};

// The fixed parts of an oracle (name, description, default epsilon, whether it samples the
// kernel), so that an oracle's file holds its formula and little else.
class NamedOracle : public Oracle {
public:
    NamedOracle(std::string_view name, std::string_view description, double default_epsilon,
                bool uses_lines)
        : m_name(name),
          m_description(description),
          m_epsilon(default_epsilon),
          m_lines(uses_lines) {}
    std::string_view name() const override { return m_name; }
    std::string_view description() const override { return m_description; }
    double default_epsilon() const override { return m_epsilon; }
    bool uses_lines() const override { return m_lines; }

private:
    std::string_view m_name, m_description;
    double m_epsilon;
    bool m_lines;
};

}  // namespace hmcr
