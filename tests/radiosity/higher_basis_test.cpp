// SPDX-License-Identifier: Apache-2.0
// Higher-order bases in the solver (docs/design.md §3.14): the furnace keeps its exact value and
// every coefficient beyond the mean has expectation 0 there; a plate lit by a small emitter holds
// the projection of its exact radiosity rho E F(y) on the basis, coefficient by coefficient, on
// squares and triangles, one way and both ways, for both sequences; and the same bits for any
// thread count, refined or fixed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "radiosity/solver.h"
#include "tests/support/analytic.h"
#include "tests/support/furnace.h"
#include "tests/support/same_leaves.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

constexpr Basis kHigher[] = {Basis::linear, Basis::bilinear, Basis::quadratic, Basis::cubic};

// A closed box of 6 x 4 x 4 leaves, E 1 and rho 0.5 everywhere: B is the K-bounce value on
// every patch (t test per patch), and each leaf's coefficients beyond the mean are 0 in
// expectation (t test per leaf and coefficient over the seeds, Bonferroni over all of them).
TEST(HigherBasis, FurnaceKeepsItsValueAndTermsHaveMeanZero) {
    const double rho = 0.5, e = 1;
    const auto mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(rho), Rgb::Constant(e)));
    for (const Basis basis : kHigher) {
        SCOPED_TRACE(basis_name(basis));
        std::vector<std::vector<double>> terms;  // per leaf and coefficient, one per seed
        expect_furnace_per_patch(
            mesh, rho, e, 10,
            [&](std::uint64_t seed) {
                SolverOptions o;
                o.rays = 40'000;
                o.seed = seed;
                o.uniform_max_area = 1.0 / 16;
                o.basis = basis;
                return o;
            },
            [&](const Solution& sol) {
                const Hierarchy& h = *sol.hierarchy;
                std::size_t k = 0;
                h.for_each_leaf([&](const Element& leaf) {
                    const RgbCoefficients c = h.radiosity_coefficients(leaf);
                    for (int j = 1; j < c.rows(); ++j, ++k) {
                        if (terms.size() <= k) terms.emplace_back();
                        terms[k].push_back(c(j, 1));
                    }
                });
            });
        ASSERT_EQ(terms.size(), 96u * std::size_t(basis_size(basis) - 1));
        for (std::size_t k = 0; k < terms.size(); ++k) {
            EXPECT_TRUE(t_test("term " + std::to_string(k), terms[k], 0, 0, int(terms.size())));
        }
    }
}

// The receiver at z = 0 facing up: the unit square (a quad, or two triangles) or a trapezoid
// (a quad whose map is not affine), reflectance 0.5 and emission 0.5; above it at h = 0.4 an
// emitter over [0.5, 1] x [0.2, 0.6] facing down, E 1, rho 0, placed so that no symmetry of
// the receiver's domain maps the light onto itself. The receiver's B is E_r + rho E F(y) after one
// iteration and stays so: what it shoots is absorbed. Used both ways, its own lines carry the
// emitter's power back to it.
constexpr double kPlateHeight = 0.4, kPlateRho = 0.5, kPlateOwn = 0.5;

enum class Receiver { square, triangles, trapezoid };

PatchMesh lit_plate(Receiver shape) {
    std::vector<TestPolygon> polygons;
    TestPolygon emitter = axis_rectangle(2, kPlateHeight, {0.5, 0.2}, {1, 0.6}, false);
    emitter.emission = Rgb::Ones();
    polygons.push_back(emitter);
    const auto receiver = [&](std::vector<Vec3> corners) {
        TestPolygon p;
        p.corners = std::move(corners);
        p.reflectance = Rgb::Constant(kPlateRho);
        p.emission = Rgb::Constant(kPlateOwn);
        polygons.push_back(p);
    };
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
    if (shape == Receiver::triangles) {
        receiver({a, b, c});
        receiver({a, c, d});
    } else if (shape == Receiver::square) {
        receiver({a, b, c, d});
    } else {
        receiver({a, b, Vec3(0.8, 1, 0), Vec3(0.3, 1, 0)});
    }
    return make_patch_mesh(polygons);
}

// The exact B at a point of the receiver.
double exact_radiosity(const Vec3& y) {
    return kPlateOwn + kPlateRho * point_to_parallel_rectangle(0.5 - y.x(), 1 - y.x(), 0.2 - y.y(),
                                                               0.6 - y.y(), kPlateHeight);
}

// Coefficient j of the projection of the exact B on leaf e's basis: the mean over its domain of
// B psi_j, by 8 x 8 sub-squares (sub-triangles) of the 4 x 4 point rule each (the integrand is
// smooth: the rule's error is far below the Monte Carlo noise). Coefficient 0 is B's mean by
// area, the others its means over the domain (docs/design.md §3.14): they differ where the
// patch's Jacobian J is not constant.
double projected(const Hierarchy& h, const Element& e, int j) {
    const PolynomialBasis& basis = h.polynomial(e);
    const Patch& p = h.patch(e);
    const bool quad = p.is_quad();
    double sum = 0, area = 0;
    Domain root = Domain::root();
    std::vector<Domain> parts{root};
    for (int level = 0; level < 3; ++level) {
        std::vector<Domain> next;
        for (const Domain& d : parts) {
            for (int k = 0; k < 4; ++k) next.push_back(d.child(quad, k));
        }
        parts = next;
    }
    for (const Domain& d : parts) {
        for (const QuadraturePoint& q : domain_quadrature(quad)) {
            const double a = d.u0 + d.s * q.a, b = d.v0 + d.s * q.b;
            const Vec2 uv(e.domain.u0 + e.domain.s * a, e.domain.v0 + e.domain.s * b);
            const double w = q.weight / double(parts.size()) * (j == 0 ? p.jacobian(uv) : 1);
            sum += w * exact_radiosity(p.point(uv)) * basis.evaluate(a, b)[j];
            area += w;
        }
    }
    return sum / area;
}

struct PlateCase {
    Basis basis;
    Receiver shape;
    RaySequence sequence;
    Bidirectional bidirectional;
};

class LitPlate : public testing::TestWithParam<PlateCase> {};

// Every coefficient of every receiver leaf (4 per patch) against the projection of the exact
// B: a t test over 12 seeds, Bonferroni over the leaves (4 of the square, 8 of the triangles)
// and coefficients.
TEST_P(LitPlate, HoldsTheProjectionOfTheExactRadiosity) {
    const PlateCase c = GetParam();
    const PatchMesh mesh = lit_plate(c.shape);
    const bool triangles = c.shape == Receiver::triangles;
    std::vector<std::vector<double>> samples;
    std::vector<double> expected;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        SolverOptions o;
        o.rays = 200'000;
        o.seed = seed;
        o.uniform_max_area = triangles ? 0.125 : 0.25;
        o.basis = c.basis;
        o.sequence = c.sequence;
        o.bidirectional = c.bidirectional;
        const Solution sol = solve(mesh, o);
        const Hierarchy& h = *sol.hierarchy;
        std::size_t k = 0;
        h.for_each_leaf([&](const Element& leaf) {
            if (leaf.id.patch == 0) return;  // the emitter
            const RgbCoefficients coefficients = h.radiosity_coefficients(leaf);
            for (int j = 0; j < coefficients.rows(); ++j, ++k) {
                if (seed == 1) {
                    samples.emplace_back();
                    expected.push_back(projected(h, leaf, j));
                }
                samples[k].push_back(coefficients(j, 0));
            }
        });
    }
    ASSERT_EQ(samples.size(), (triangles ? 8u : 4u) * std::size_t(basis_size(c.basis)));
    for (std::size_t k = 0; k < samples.size(); ++k) {
        EXPECT_TRUE(t_test("coefficient " + std::to_string(k), samples[k], expected[k], 0,
                           int(samples.size())));
    }
}

std::string plate_case_name(const testing::TestParamInfo<PlateCase>& info) {
    constexpr const char* kShapes[] = {"Square", "Triangles", "Trapezoid"};
    const PlateCase& c = info.param;
    std::string n(basis_name(c.basis));
    n += kShapes[int(c.shape)];
    n += c.sequence == RaySequence::sobol ? "Sobol" : "Random";
    if (c.bidirectional == Bidirectional::yes) n += "BothWays";
    return n;
}

INSTANTIATE_TEST_SUITE_P(
    Bases, LitPlate,
    testing::Values(
        PlateCase{Basis::linear, Receiver::square, RaySequence::random, Bidirectional::no},
        PlateCase{Basis::linear, Receiver::triangles, RaySequence::random, Bidirectional::no},
        PlateCase{Basis::bilinear, Receiver::square, RaySequence::sobol, Bidirectional::no},
        PlateCase{Basis::quadratic, Receiver::triangles, RaySequence::sobol, Bidirectional::yes},
        PlateCase{Basis::quadratic, Receiver::trapezoid, RaySequence::random, Bidirectional::no},
        PlateCase{Basis::cubic, Receiver::square, RaySequence::random, Bidirectional::yes},
        PlateCase{Basis::cubic, Receiver::triangles, RaySequence::sobol, Bidirectional::no}),
    plate_case_name);

// A patch's polynomials projected on its root's basis, from its leaves up: exact, by the child
// projections (on triangles and parallelograms the parameter and area means agree).
RgbCoefficients on_root(const Hierarchy& h, const Element& e) {
    const Element* c = e.children();
    if (!c) return h.radiosity_coefficients(e);
    std::array<PolynomialBasis::Coefficients, 4> children;
    RgbCoefficients out(basis_size(h.basis()), 3);
    for (int channel = 0; channel < 3; ++channel) {
        for (int k = 0; k < 4; ++k) children[std::size_t(k)] = on_root(h, c[k]).col(channel);
        out.col(channel) = h.polynomial(e).from_children(children);
    }
    return out;
}

// A refined solve, all its rays refining (no frozen pass): its deposits land on elements at
// every level and are pushed to the leaves as polynomials. The leaves differ from seed to seed,
// so each receiver patch's leaves are projected on the patch's basis and t-tested against the
// exact B's projection there, over 12 seeds.
TEST(HigherBasis, RefinedSolveHoldsTheProjectionOnEachPatch) {
    for (const Receiver shape : {Receiver::square, Receiver::triangles}) {
        for (const Basis basis : {Basis::linear, Basis::quadratic}) {
            SCOPED_TRACE(testing::Message() << basis_name(basis) << ", shape " << int(shape));
            const PatchMesh mesh = lit_plate(shape);
            std::vector<std::vector<double>> samples;
            std::vector<double> expected;
            std::size_t most_leaves = 0;
            for (std::uint64_t seed = 1; seed <= 12; ++seed) {
                SolverOptions o;
                o.rays = 200'000;
                o.seed = seed;
                o.basis = basis;
                o.refine_share = 1;
                o.epsilon = 1e-3;
                const Solution sol = solve(mesh, o);
                const Hierarchy& h = *sol.hierarchy;
                most_leaves = std::max(most_leaves, sol.stats.leaves);
                std::size_t k = 0;
                for (std::size_t p = 1; p < h.patch_count(); ++p) {
                    const RgbCoefficients c = on_root(h, h.root(p));
                    for (int j = 0; j < c.rows(); ++j, ++k) {
                        if (seed == 1) {
                            samples.emplace_back();
                            expected.push_back(projected(h, h.root(p), j));
                        }
                        samples[k].push_back(c(j, 0));
                    }
                }
            }
            EXPECT_GT(most_leaves, 3 * mesh.n_faces()) << "the solves refined";
            for (std::size_t k = 0; k < samples.size(); ++k) {
                EXPECT_TRUE(t_test("coefficient " + std::to_string(k), samples[k], expected[k], 0,
                                   int(samples.size())));
            }
        }
    }
}

// The square lit plate with one leaf per patch and a small mirror-grey reflector (rho 0.9)
// standing near the receiver's corner at the origin, facing it and the light: from the second
// iteration on, the reflector's lines land on the receiver mostly near that corner, where its
// polynomial is darker than its mean. Used both ways, each such line carries back the
// receiver's Delta B at its end, not its mean: every coefficient keeps the one-way solve's
// expectation. A t test per leaf and coefficient of the difference over 16 seeds.
TEST(HigherBasis, BothWaysKeepTheOneWayExpectation) {
    const PatchMesh mesh = [] {
        TestPolygon emitter = axis_rectangle(2, kPlateHeight, {0.5, 0.2}, {1, 0.6}, false);
        emitter.emission = Rgb::Ones();
        TestPolygon receiver;
        receiver.corners = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
        receiver.reflectance = Rgb::Constant(kPlateRho);
        receiver.emission = Rgb::Constant(kPlateOwn);
        const Vec3 centre(0.1, 0.1, 0.2), along = Vec3(1, -1, 0).normalized() * 0.15,
                                          up(0, 0, 0.15);
        TestPolygon reflector;  // facing (1, 1, 0)
        reflector.corners = {centre + along - up, centre - along - up, centre - along + up,
                             centre + along + up};
        reflector.reflectance = Rgb::Constant(0.9);
        return make_patch_mesh({emitter, receiver, reflector});
    }();
    std::vector<std::vector<double>> difference;
    const auto coefficients = [](const Hierarchy& h) {
        std::vector<double> all;
        h.for_each_leaf([&](const Element& leaf) {
            const RgbCoefficients c = h.radiosity_coefficients(leaf);
            for (int j = 0; j < c.rows(); ++j) all.push_back(c(j, 0));
        });
        return all;
    };
    for (std::uint64_t seed = 1; seed <= 16; ++seed) {
        SolverOptions o;
        o.rays = 100'000;
        o.seed = seed;
        o.uniform_max_area = 1;
        o.basis = Basis::linear;
        o.bidirectional = Bidirectional::yes;
        const Solution both = solve(mesh, o);
        o.bidirectional = Bidirectional::no;
        const Solution one = solve(mesh, o);
        ASSERT_EQ(both.stats.iterations.size(), one.stats.iterations.size());
        const std::vector<double> a = coefficients(*both.hierarchy),
                                  b = coefficients(*one.hierarchy);
        ASSERT_EQ(a.size(), 9u);
        difference.resize(a.size());
        for (std::size_t k = 0; k < a.size(); ++k) difference[k].push_back(a[k] - b[k]);
    }
    for (std::size_t k = 0; k < difference.size(); ++k) {
        EXPECT_TRUE(t_test("leaf " + std::to_string(k / 3) + " coefficient " +
                               std::to_string(k % 3) + ", both ways minus one way",
                           difference[k], 0, 0, int(difference.size())));
    }
}

// The default element limit bounds the same memory on every basis; a limit the user gives is
// the user's.
TEST(HigherBasis, TheDefaultElementLimitCountsTheCoefficients) {
    SolverOptions o;
    EXPECT_EQ(element_limit(o), o.max_elements);
    for (const Basis basis : kHigher) {
        o.basis = basis;
        const double bytes =
            double(sizeof(Element) + std::size_t(basis_size(basis) - 1) * sizeof(TermSlot));
        EXPECT_NEAR(double(element_limit(o)) * bytes, double(o.max_elements) * sizeof(Element),
                    bytes)
            << basis_name(basis);
        EXPECT_LT(element_limit(o), o.max_elements);
    }
    o.max_elements = 1000;
    EXPECT_EQ(element_limit(o), 1000u);
}

// A refined solve (a refining pass, then its mesh frozen), and a fixed one both ways: the same
// leaves, radiosity and coefficients on 1 and 2 threads.
TEST(HigherBasis, SameBitsForOneAndTwoThreads) {
    const PatchMesh mesh = lit_plate(Receiver::triangles);
    for (const Basis basis : {Basis::linear, Basis::cubic}) {
        SolverOptions o;
        o.rays = 100'000;
        o.seed = 3;
        o.basis = basis;
        o.epsilon = 1e-4;
        solve_on_one_and_two_threads(mesh, o);
        o.uniform_max_area = 1.0 / 64;
        o.bidirectional = Bidirectional::yes;
        solve_on_one_and_two_threads(mesh, o);
    }
}

}  // namespace
}  // namespace hmcr::test
