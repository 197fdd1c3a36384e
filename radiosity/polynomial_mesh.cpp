// SPDX-License-Identifier: Apache-2.0
#include "radiosity/polynomial_mesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace hmcr {
namespace {

// The lattice of a leaf's points: (i / n, j / n) for i, j in 0 .. n on a square, i + j <= n on
// a triangle, row by row (j outer).
class SubCellLattice {
public:
    SubCellLattice(int n, bool quad) : m_n(n), m_quad(quad) {}

    int point_count() const { return m_quad ? (m_n + 1) * (m_n + 1) : (m_n + 1) * (m_n + 2) / 2; }
    // The index of point (i, j) among the leaf's.
    int at(int i, int j) const {
        if (m_quad) return j * (m_n + 1) + i;
        // Rows 0 .. j - 1 hold n + 1, n, ..., n + 2 - j points.
        return j * (m_n + 1) - j * (j - 1) / 2 + i;
    }
    // Calls f(i, j) on every point in index order.
    template <class F>
    void for_each_point(F&& f) const {
        for (int j = 0; j <= m_n; ++j) {
            for (int i = 0; i <= (m_quad ? m_n : m_n - j); ++i) f(i, j);
        }
    }
    // Calls f(corners, count) on every sub-cell, each with its lattice corners counter-clockwise
    // in (a, b), as the leaf's own corners run: on a square the squares row by row; on a
    // triangle, row by row, each upright triangle followed by the inverted one beside it.
    template <class F>
    void for_each_cell(F&& f) const {
        for (int j = 0; j < m_n; ++j) {
            for (int i = 0; i < (m_quad ? m_n : m_n - j); ++i) {
                if (m_quad) {
                    f(std::array<int, 4>{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)},
                      4);
                    continue;
                }
                f(std::array<int, 4>{at(i, j), at(i + 1, j), at(i, j + 1), 0}, 3);
                if (i + j + 1 < m_n) {
                    f(std::array<int, 4>{at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), 0}, 3);
                }
            }
        }
    }

private:
    int m_n;
    bool m_quad;
};

// Sum_k c[3 k + channel] psi_k(a, b): the one evaluation of a cell's polynomial, so that a
// point's value and the tracer's there are the same number.
Rgb evaluate_coefficients(const PolynomialBasis& basis, const double* c, const Vec2& ab) {
    const PolynomialBasis::Coefficients psi = basis.evaluate(ab);
    Rgb b = Rgb::Zero();
    for (int k = 0; k < basis.size(); ++k) {
        for (int channel = 0; channel < 3; ++channel) b[channel] += c[3 * k + channel] * psi[k];
    }
    return b;
}

// Appends one leaf: its points, then its sub-cells with the leaf's data.
class LeafEmitter {
public:
    LeafEmitter(const Hierarchy& h, ShadedMesh& out) : m_h(h), m_out(out) {}

    void emit(const Element& e, std::uint8_t side, std::int32_t leaf) {
        const Patch& patch = m_h.patch(e);
        const bool quad = patch.is_quad();
        const PolynomialBasis& basis = m_h.polynomial(e);
        const RgbCoefficients rows = m_h.radiosity_coefficients(e);
        std::array<double, 3 * kMaxBasisSize> c{};  // coefficient-major
        for (int k = 0; k < basis.size(); ++k) {
            for (int channel = 0; channel < 3; ++channel) {
                c[3 * std::size_t(k) + std::size_t(channel)] = rows(k, channel);
            }
        }
        const int n = polynomial_subdivisions(m_h.basis());
        const SubCellLattice lattice(n, quad);
        const auto first = std::int64_t(m_out.points.size());
        m_uv.clear();
        lattice.for_each_point([&](int i, int j) {
            const Vec2 ab(double(i) / n, double(j) / n);
            const Vec2 uv(e.domain.u0 + ab.x() * e.domain.s, e.domain.v0 + ab.y() * e.domain.s);
            m_uv.push_back(uv);
            m_out.points.push_back(patch.point(uv));
            m_out.leaf_coordinates.push_back(ab);
            m_out.point_radiosity.push_back(evaluate_coefficients(basis, c.data(), ab));
        });
        lattice.for_each_cell([&](const std::array<int, 4>& corners, int count) {
            std::array<Vec2, 4> uv{};
            for (int k = 0; k < count; ++k) uv[std::size_t(k)] = m_uv[std::size_t(corners[k])];
            // A back shows the patch reversed, as the constant basis's polygons do.
            for (int k = 0; k < count; ++k) {
                const int corner = side == kBack ? corners[std::size_t(count - 1 - k)] : corners[k];
                m_out.connectivity.push_back(first + corner);
            }
            m_out.offsets.push_back(std::int64_t(m_out.connectivity.size()));
            m_out.element_radiosity.push_back(e.radiosity);
            m_out.hierarchy_level.push_back(e.id.depth);
            m_out.patch_id.push_back(int(e.id.patch));
            m_out.element_area.push_back(patch.region_area(uv.data(), count));
            m_out.side.push_back(side);
            m_out.leaf_index.push_back(leaf);
            m_out.coefficients.insert(m_out.coefficients.end(), c.begin(),
                                      c.begin() + 3 * basis.size());
        });
    }

private:
    const Hierarchy& m_h;
    ShadedMesh& m_out;
    std::vector<Vec2> m_uv;  // the current leaf's points' parameter points
};

}  // namespace

int polynomial_subdivisions(Basis basis) {
    static constexpr std::array<int, 5> kSubdivisions = {1, 1, 2, 3, 4};
    return kSubdivisions[std::size_t(basis)];
}

ShadedMesh build_polynomial_mesh(const Hierarchy& h) {
    if (h.basis() == Basis::constant) {
        throw std::invalid_argument("build_polynomial_mesh: the hierarchy's basis is constant");
    }
    if (h.leaf_count() > std::size_t(std::numeric_limits<std::int32_t>::max())) {
        throw std::length_error("more than 2^31 leaves in one solution");
    }
    ShadedMesh out;
    out.basis = h.basis();
    const int n = polynomial_subdivisions(h.basis());
    const std::size_t cells = h.leaf_count() * std::size_t(n * n);
    out.offsets.reserve(cells + 1);
    out.element_radiosity.reserve(cells);
    out.hierarchy_level.reserve(cells);
    out.patch_id.reserve(cells);
    out.element_area.reserve(cells);
    out.side.reserve(cells);
    out.leaf_index.reserve(cells);
    out.coefficients.reserve(cells * out.cell_stride());
    LeafEmitter emitter(h, out);
    std::int32_t leaf = 0;
    for (const std::uint8_t side : {kFront, kBack}) {
        h.for_each_leaf_of(side, [&](const Element& e) { emitter.emit(e, side, leaf++); });
    }
    return out;
}

Rgb polynomial_radiosity(Basis basis, bool quad, const double* coefficients, const Vec2& ab) {
    return evaluate_coefficients(polynomial_basis(basis, quad), coefficients, ab);
}

Rgb polynomial_radiosity(const ShadedMesh& mesh, std::size_t cell, const Vec2& ab) {
    const bool quad = mesh.offsets[cell + 1] - mesh.offsets[cell] == 4;
    return evaluate_coefficients(polynomial_basis(mesh.basis, quad),
                                 mesh.coefficients.data() + mesh.cell_stride() * cell, ab);
}

Rgb radiosity_at(const ShadedMesh& mesh, std::size_t cell, const std::array<std::size_t, 3>& points,
                 double w1, double w2) {
    const double w0 = 1 - w1 - w2;
    if (mesh.basis == Basis::constant) {
        const auto& b = mesh.point_radiosity;
        return w0 * b[points[0]] + w1 * b[points[1]] + w2 * b[points[2]];
    }
    const auto& ab = mesh.leaf_coordinates;
    return polynomial_radiosity(mesh, cell,
                                w0 * ab[points[0]] + w1 * ab[points[1]] + w2 * ab[points[2]]);
}

}  // namespace hmcr
