// SPDX-License-Identifier: Apache-2.0
// A higher-order solution's output: every leaf on its own n x n sub-cells, every point holding
// the leaf's polynomial exactly, and the tracer evaluating it exactly anywhere inside a cell.
#include "radiosity/polynomial_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "radiosity/solver.h"
#include "tests/support/shaded_scenes.h"
#include "tests/support/test_scenes.h"
#include "viz/shaded_tracer.h"

namespace hmcr::test {
namespace {

// |x - y| within `tol` of the larger magnitude (and of 1, for values near 0).
testing::AssertionResult close_relative(const Rgb& x, const Rgb& y, double tol) {
    for (int k = 0; k < 3; ++k) {
        const double scale = std::max({std::abs(x[k]), std::abs(y[k]), 1e-300});
        if (std::abs(x[k] - y[k]) > tol * scale) {
            return testing::AssertionFailure() << "channel " << k << ": " << x[k] << " vs " << y[k]
                                               << " (difference " << std::abs(x[k] - y[k]) << ")";
        }
    }
    return testing::AssertionSuccess();
}

// A hierarchy on `basis` with leaves of every kind (a triangle's inverted middle child among
// them, at depth 2), each with a polynomial of its own: a mean of 2 to 3 per channel, the
// other coefficients from -0.2 to 0.2, so that B stays well above 0.
struct PolynomialScene {
    MeshHierarchy s;
    std::vector<const Element*> leaves;  // in canonical order

    PolynomialScene(PatchMesh mesh, Basis basis) : s(std::move(mesh)) {
        s.h->set_basis(basis);
        s.at(0, {3, 1});
        s.at(0, {2});
        s.at(1, {0, 3});
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> mean(2, 3), term(-0.2, 0.2);
        s.h->for_each_leaf([&](const Element& e) {
            auto& leaf = const_cast<Element&>(e);
            leaf.radiosity = Rgb(mean(rng), mean(rng), mean(rng));
            TermSlot* slots = s.h->terms(e);
            for (int k = 1; k < basis_size(basis); ++k) {
                slots[k - 1].radiosity = Rgb(term(rng), term(rng), term(rng));
            }
            leaves.push_back(&e);
        });
    }
    // The leaf polynomial's value at (a, b), channel by channel through PolynomialBasis::value.
    Rgb value(const Element& e, const Vec2& ab) const {
        const RgbCoefficients c = s.h->radiosity_coefficients(e);
        const PolynomialBasis& basis = s.h->polynomial(e);
        Rgb b;
        for (int k = 0; k < 3; ++k) {
            b[k] = basis.value(PolynomialBasis::Coefficients(c.col(k)), ab.x(), ab.y());
        }
        return b;
    }
    Vec3 position(const Element& e, const Vec2& ab) const {
        return s.h->patch(e).point(
            Vec2(e.domain.u0 + ab.x() * e.domain.s, e.domain.v0 + ab.y() * e.domain.s));
    }
};

struct BasisCase {
    Basis basis;
    bool quads;
};

std::string case_name(const testing::TestParamInfo<BasisCase>& info) {
    return std::string(basis_name(info.param.basis)) + (info.param.quads ? "Quads" : "Triangles");
}

// Named, not printed as bytes (its padding's among them).
void PrintTo(const BasisCase& c, std::ostream* os) {
    *os << basis_name(c.basis) << (c.quads ? " quads" : " triangles");
}

class PolynomialMesh : public testing::TestWithParam<BasisCase> {
protected:
    PolynomialScene scene() const {
        return PolynomialScene(GetParam().quads ? two_quads(false) : two_triangles(),
                               GetParam().basis);
    }
};

TEST_P(PolynomialMesh, EveryPointHoldsItsLeafsPolynomial) {
    const PolynomialScene p = scene();
    const ShadedMesh m = p.s.shade();
    const int n = polynomial_subdivisions(GetParam().basis);
    const std::size_t stride = 3 * std::size_t(basis_size(GetParam().basis));
    ASSERT_EQ(m.basis, GetParam().basis);
    ASSERT_EQ(m.cell_count(), p.leaves.size() * std::size_t(n * n));
    ASSERT_EQ(m.leaf_count(), p.leaves.size());
    ASSERT_EQ(m.leaf_index.size(), m.cell_count());
    ASSERT_EQ(m.coefficients.size(), stride * m.cell_count());
    ASSERT_EQ(m.leaf_coordinates.size(), m.points.size());
    ASSERT_EQ(m.point_radiosity.size(), m.points.size());
    std::vector<double> area(p.leaves.size(), 0.0);
    std::vector<int> uses(m.points.size(), 0);
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        ASSERT_LT(std::size_t(m.leaf_index[c]), p.leaves.size());
        if (c > 0) {
            EXPECT_LE(m.leaf_index[c - 1], m.leaf_index[c]);
        }
        const Element& e = *p.leaves[std::size_t(m.leaf_index[c])];
        EXPECT_EQ(m.patch_id[c], int(e.id.patch));
        EXPECT_EQ(m.hierarchy_level[c], int(e.id.depth));
        EXPECT_EQ(m.side[c], kFront);
        EXPECT_TRUE((m.element_radiosity[c] == e.radiosity).all());
        const RgbCoefficients coefficients = p.s.h->radiosity_coefficients(e);
        for (int k = 0; k < basis_size(m.basis); ++k) {
            for (int channel = 0; channel < 3; ++channel) {
                EXPECT_EQ(m.coefficients[stride * c + 3 * std::size_t(k) + std::size_t(channel)],
                          coefficients(k, channel));
            }
        }
        const Vec3 vector_area = polygon_area(m, std::int64_t(c));
        EXPECT_NEAR(vector_area.dot(p.s.h->patch(e).normal), m.element_area[c], 1e-12);
        area[std::size_t(m.leaf_index[c])] += m.element_area[c];
        EXPECT_EQ(m.offsets[c + 1] - m.offsets[c], GetParam().quads ? 4 : 3);
        for (auto k = m.offsets[c]; k < m.offsets[c + 1]; ++k) {
            const auto point = std::size_t(m.connectivity[std::size_t(k)]);
            ++uses[point];
            const Vec2& ab = m.leaf_coordinates[point];
            // On the lattice of (i / n, j / n), in the leaf's unit domain.
            EXPECT_EQ(ab * n, (ab * n).array().round().matrix());
            EXPECT_LE(ab.sum(), GetParam().quads ? 2.0 : 1.0);
            EXPECT_TRUE(m.points[point].isApprox(p.position(e, ab), 1e-14));
            EXPECT_TRUE(close_relative(m.point_radiosity[point], p.value(e, ab), 1e-12))
                << "cell " << c << " point " << point;
            EXPECT_TRUE(close_relative(polynomial_radiosity(m, c, ab), p.value(e, ab), 1e-12));
        }
    }
    for (std::size_t l = 0; l < p.leaves.size(); ++l) {
        EXPECT_NEAR(area[l], p.leaves[l]->area, 1e-14) << "leaf " << l;
    }
    // No point is shared between leaves, and every point is some cell's.
    std::vector<int> leaf_of(m.points.size(), -1);
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        for (auto k = m.offsets[c]; k < m.offsets[c + 1]; ++k) {
            int& owner = leaf_of[std::size_t(m.connectivity[std::size_t(k)])];
            if (owner >= 0) {
                EXPECT_EQ(owner, m.leaf_index[c]);
            }
            owner = m.leaf_index[c];
        }
    }
    for (std::size_t i = 0; i < m.points.size(); ++i) EXPECT_GT(uses[i], 0) << "point " << i;
}

TEST_P(PolynomialMesh, TheTracerEvaluatesThePolynomialInsideEveryCell) {
    const PolynomialScene p = scene();
    const ShadedMesh m = p.s.shade();
    const ShadedTracer tracer(m);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> inner(0.05, 0.95);
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        const Element& e = *p.leaves[std::size_t(m.leaf_index[c])];
        const auto first = m.offsets[c];
        const auto ab_of = [&](int k) {
            return m.leaf_coordinates[std::size_t(m.connectivity[std::size_t(first + k)])];
        };
        for (int trial = 0; trial < 8; ++trial) {
            Vec2 ab;
            if (m.offsets[c + 1] - first == 4) {  // bilinear across the sub-square
                const double x = inner(rng), y = inner(rng);
                ab = (1 - x) * (1 - y) * ab_of(0) + x * (1 - y) * ab_of(1) + x * y * ab_of(2) +
                     (1 - x) * y * ab_of(3);
            } else {  // barycentric weights of at least 0.05
                double x = inner(rng), y = inner(rng);
                if (x + y > 0.95) x = 1 - x, y = 1 - y;
                x = std::max(x, 0.05), y = std::max(y, 0.05);
                if (x + y > 0.95) continue;
                ab = (1 - x - y) * ab_of(0) + x * ab_of(1) + y * ab_of(2);
            }
            const Vec3 target = p.position(e, ab), normal = p.s.h->normal(e);
            const auto hit = tracer.hit_along(target + 0.5 * normal, -normal);
            ASSERT_TRUE(hit) << "cell " << c;
            EXPECT_EQ(m.leaf_index[hit->cell], m.leaf_index[c]);
            EXPECT_TRUE(hit->facing);
            EXPECT_TRUE(close_relative(hit->radiosity, p.value(e, ab), 1e-9))
                << "cell " << c << " at (" << ab.transpose() << ")";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    Bases, PolynomialMesh,
    testing::Values(BasisCase{Basis::linear, true}, BasisCase{Basis::linear, false},
                    BasisCase{Basis::bilinear, true}, BasisCase{Basis::quadratic, false},
                    BasisCase{Basis::cubic, true}, BasisCase{Basis::cubic, false}),
    case_name);

// A solved box, linear and cubic: the same exactness on the solver's own coefficients.
TEST(PolynomialMeshSolved, EveryPointHoldsItsLeafsPolynomial) {
    const PatchMesh mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(0.5), Rgb::Constant(1)));
    for (const Basis basis : {Basis::linear, Basis::cubic}) {
        SolverOptions o;
        o.basis = basis;
        o.rays = 20'000;
        const Solution sol = solve(mesh, o);
        const Hierarchy& h = *sol.hierarchy;
        std::vector<const Element*> leaves;
        h.for_each_leaf([&](const Element& e) { leaves.push_back(&e); });
        const ShadedMesh m = build_shaded_mesh(h);
        const int n = polynomial_subdivisions(basis);
        ASSERT_EQ(m.cell_count(), leaves.size() * std::size_t(n * n));
        ASSERT_EQ(m.leaf_count(), sol.stats.faces);
        bool varies = false;  // some leaf's polynomial is not its mean
        for (std::size_t c = 0; c < m.cell_count(); ++c) {
            const Element& e = *leaves[std::size_t(m.leaf_index[c])];
            const RgbCoefficients coefficients = h.radiosity_coefficients(e);
            varies = varies || coefficients.bottomRows(coefficients.rows() - 1).norm() > 0;
            for (auto k = m.offsets[c]; k < m.offsets[c + 1]; ++k) {
                const auto point = std::size_t(m.connectivity[std::size_t(k)]);
                const Vec2& ab = m.leaf_coordinates[point];
                // Relative to the sum of the terms' magnitudes: where a dark leaf's B is near 0,
                // the terms cancel, and no evaluation of the sum is closer than its rounding.
                const PolynomialBasis::Coefficients psi = h.polynomial(e).evaluate(ab);
                for (int channel = 0; channel < 3; ++channel) {
                    const double want = h.polynomial(e).value(
                        PolynomialBasis::Coefficients(coefficients.col(channel)), ab.x(), ab.y());
                    const double terms =
                        (coefficients.col(channel).array() * psi.array()).abs().sum();
                    EXPECT_LE(std::abs(m.point_radiosity[point][channel] - want), 1e-12 * terms)
                        << basis_name(basis) << " cell " << c << " point " << point;
                }
            }
        }
        EXPECT_TRUE(varies) << basis_name(basis);
    }
}

TEST(PolynomialMeshSubdivisions, AreTheBasissDegreesOfFreedomAlongAnEdge) {
    EXPECT_EQ(polynomial_subdivisions(Basis::linear), 1);
    EXPECT_EQ(polynomial_subdivisions(Basis::bilinear), 2);
    EXPECT_EQ(polynomial_subdivisions(Basis::quadratic), 3);
    EXPECT_EQ(polynomial_subdivisions(Basis::cubic), 4);
}

// The constant basis keeps its conforming Gouraud mesh, without the higher-order arrays.
TEST(PolynomialMeshSubdivisions, TheConstantBasisKeepsItsMesh) {
    MeshHierarchy s(two_quads(true));
    s.at(0, {1});
    const ShadedMesh m = s.shade();
    EXPECT_EQ(m.basis, Basis::constant);
    EXPECT_EQ(m.cell_count(), s.h->leaf_count());
    EXPECT_EQ(m.leaf_count(), m.cell_count());
    EXPECT_TRUE(m.leaf_coordinates.empty());
    EXPECT_TRUE(m.coefficients.empty());
    EXPECT_TRUE(m.leaf_index.empty());
    EXPECT_TRUE(conforming(m));
}

}  // namespace
}  // namespace hmcr::test
