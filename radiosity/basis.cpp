// SPDX-License-Identifier: Apache-2.0
// PolynomialBasis (basis.h): the Gram matrix of the monomials from their exact means, its
// Cholesky factor, and the child transforms by a quadrature exact for them.
#include "radiosity/basis.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <vector>

#include "rays/domain.h"

namespace hmcr {
namespace {

// The monomials each basis spans, by degree: linear, quadratic and cubic take the first 3, 6 or
// 10 of the full polynomials; bilinear takes 1, a, b and ab.
constexpr std::array<std::array<int, 2>, kMaxBasisSize> kByDegree = {
    {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}, {3, 0}, {2, 1}, {1, 2}, {0, 3}}};
constexpr std::array<std::array<int, 2>, kMaxBasisSize> kBilinear = {
    {{0, 0}, {1, 0}, {0, 1}, {1, 1}}};

double factorial(int n) {
    double f = 1;
    for (int k = 2; k <= n; ++k) f *= k;
    return f;
}

// The mean of a^i b^j over the unit square or the unit triangle (of area 1/2).
double monomial_mean(bool quad, int i, int j) {
    if (quad) return 1.0 / double((i + 1) * (j + 1));
    return 2 * factorial(i) * factorial(j) / factorial(i + j + 2);
}

}  // namespace

int basis_size(Basis basis) {
    static constexpr std::array<int, 5> kSizes = {1, 3, 4, 6, 10};
    return kSizes[std::size_t(basis)];
}

std::span<const QuadraturePoint> domain_quadrature(bool quad) {
    // 4-point Gauss-Legendre on [0, 1]: exact to degree 7.
    static const auto gauss = [] {
        const double inner = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(6.0 / 5));
        const double outer = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(6.0 / 5));
        const double w_inner = (18 + std::sqrt(30.0)) / 36, w_outer = (18 - std::sqrt(30.0)) / 36;
        const std::array<double, 4> t = {-outer, -inner, inner, outer};
        const std::array<double, 4> w = {w_outer, w_inner, w_inner, w_outer};
        std::array<std::array<double, 2>, 4> g{};
        for (std::size_t k = 0; k < 4; ++k) g[k] = {(1 + t[k]) / 2, w[k] / 2};
        return g;
    }();
    static const auto points = [] {
        std::array<std::array<QuadraturePoint, 16>, 2> p{};  // [triangle, square]
        for (std::size_t i = 0; i < 4; ++i) {
            for (std::size_t j = 0; j < 4; ++j) {
                const auto [x, wx] = gauss[i];
                const auto [y, wy] = gauss[j];
                p[1][4 * i + j] = {x, y, wx * wy};
                // Twice the square's measure times the map's Jacobian 1 - x: a mean over the
                // triangle of area 1/2.
                p[0][4 * i + j] = {x, y * (1 - x), 2 * wx * wy * (1 - x)};
            }
        }
        return p;
    }();
    return points[quad ? 1 : 0];
}

PolynomialBasis::PolynomialBasis(Basis basis, bool quad)
    : m_basis(basis), m_quad(quad), m_size(basis_size(basis)) {
    m_exponents = basis == Basis::bilinear ? kBilinear : kByDegree;
    Transform gram(m_size, m_size);
    for (int m = 0; m < m_size; ++m) {
        for (int n = 0; n < m_size; ++n) {
            gram(m, n) = monomial_mean(quad, m_exponents[m][0] + m_exponents[n][0],
                                       m_exponents[m][1] + m_exponents[n][1]);
        }
    }
    // gram = L L^T; the rows of L^-1 are orthonormal combinations, the first the constant 1.
    const Eigen::LLT<Transform> cholesky(gram);
    m_orthonormal = cholesky.matrixL().solve(Transform::Identity(m_size, m_size));
    for (int k = 0; k < m_size; ++k)
        m_bound[std::size_t(k)] = m_orthonormal.row(k).cwiseAbs().sum();
    const Domain root = Domain::root();
    for (int k = 0; k < 4; ++k) {
        const Domain child = root.child(quad, k);
        Transform& t = m_transform[std::size_t(k)];
        t.setZero(m_size, m_size);
        for (const QuadraturePoint& q : domain_quadrature(quad)) {
            const Coefficients parent =
                evaluate(child.u0 + child.s * q.a, child.v0 + child.s * q.b);
            t += q.weight * parent * evaluate(q.a, q.b).transpose();
        }
    }
}

PolynomialBasis::Coefficients PolynomialBasis::monomials(double a, double b) const {
    // Powers by products, not std::pow: every landed ray evaluates its receiver's basis.
    const std::array<double, 4> pa = {1, a, a * a, a * a * a}, pb = {1, b, b * b, b * b * b};
    Coefficients m(m_size);
    for (int k = 0; k < m_size; ++k) {
        m[k] = pa[std::size_t(m_exponents[k][0])] * pb[std::size_t(m_exponents[k][1])];
    }
    return m;
}

PolynomialBasis::Coefficients PolynomialBasis::evaluate(double a, double b) const {
    // L^-1 is lower triangular: the zeros above its diagonal are skipped, and the loop is
    // written out (Eigen's products of dynamic size were a tenth of a linear solve).
    const Coefficients m = monomials(a, b);
    Coefficients psi(m_size);
    for (int k = 0; k < m_size; ++k) {
        double sum = 0;
        for (int j = 0; j <= k; ++j) sum += m_orthonormal(k, j) * m[j];
        psi[k] = sum;
    }
    return psi;
}

double PolynomialBasis::value(const Coefficients& c, double a, double b) const {
    return c.dot(evaluate(a, b));
}

PolynomialBasis::Coefficients PolynomialBasis::to_child(int k, const Coefficients& parent) const {
    return transform(k).transpose() * parent;
}

PolynomialBasis::Coefficients PolynomialBasis::from_children(
    const std::array<Coefficients, 4>& children) const {
    Coefficients p = Coefficients::Zero(m_size);
    for (int k = 0; k < 4; ++k) p += transform(k) * children[std::size_t(k)];
    return p / 4;
}

const PolynomialBasis& polynomial_basis(Basis basis, bool quad) {
    static const std::vector<PolynomialBasis> table = [] {
        std::vector<PolynomialBasis> t;
        for (int b = 0; b < 5; ++b) {
            for (const bool q : {false, true}) t.emplace_back(Basis(b), q);
        }
        return t;
    }();
    return table[2 * std::size_t(basis) + (quad ? 1 : 0)];
}

double term_bound(Basis basis) {
    double most = 1;
    for (const bool quad : {false, true}) {
        const PolynomialBasis& b = polynomial_basis(basis, quad);
        for (int k = 1; k < b.size(); ++k) most = std::max(most, b.bound(k));
    }
    return most;
}

}  // namespace hmcr
