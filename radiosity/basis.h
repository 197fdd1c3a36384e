// SPDX-License-Identifier: Apache-2.0
// Polynomial bases on an element (docs/design.md §3.14): the functions a higher-order element's
// radiosity is a sum of, orthonormal over the element's unit domain (the square or the triangle
// of its local coordinates (a, b) = ((u - u0) / s, (v - v0) / s), rays/domain.h), and the
// matrices that carry a polynomial from an element to its children and back.
#pragma once

#include <Eigen/Core>
#include <array>
#include <span>
#include <string_view>

#include "common/types.h"

namespace hmcr {

// RenderPark's approximations: the polynomials an element's radiosity is taken from.
enum class Basis { constant, linear, bilinear, quadratic, cubic };

inline constexpr int kMaxBasisSize = 10;  // cubic's
inline constexpr std::array<std::string_view, 5> kBasisNames = {"constant", "linear", "bilinear",
                                                                "quadratic", "cubic"};

// The number of functions of a basis: 1, 3, 4, 6 or 10, on squares and triangles alike.
int basis_size(Basis basis);
inline std::string_view basis_name(Basis basis) { return kBasisNames[std::size_t(basis)]; }

// A point of a quadrature over an element's unit domain, with its share of the domain's
// measure (the shares sum to 1: a sum over the points is a mean over the domain).
struct QuadraturePoint {
    double a = 0, b = 0, weight = 0;
};

// A quadrature exact for every polynomial of degree 7 in each of a and b (the square: 4 x 4
// Gauss-Legendre points) or of total degree 6 (the triangle: 4 x 4 points of the square mapped
// onto it, (a, b) = (x, y (1 - x))): enough for the product of two cubics, and on a square for
// that times the bilinear Jacobian of a quad patch.
std::span<const QuadraturePoint> domain_quadrature(bool quad);

// The basis `basis` on the unit square (quad) or the unit triangle: the monomials it spans
// (constant 1; linear 1, a, b; bilinear those and ab; quadratic 1, a, b, a², ab, b²; cubic those
// and a³, a²b, ab², b³) made orthonormal in the mean over the domain,
// mean(ψ_i ψ_j) = δ_ij, by the Cholesky factor of their Gram matrix, so that ψ_0 = 1 and the
// first coefficient of a function is its mean.
class PolynomialBasis {
public:
    using Coefficients = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxBasisSize, 1>;
    using Transform =
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxBasisSize, kMaxBasisSize>;

    PolynomialBasis(Basis basis, bool quad);

    Basis basis() const { return m_basis; }
    bool quad() const { return m_quad; }
    int size() const { return m_size; }

    // ψ_0(a, b) ... ψ_(size-1)(a, b).
    Coefficients evaluate(double a, double b) const;
    Coefficients evaluate(const Vec2& ab) const { return evaluate(ab.x(), ab.y()); }
    // Σ_k c_k ψ_k(a, b).
    double value(const Coefficients& c, double a, double b) const;

    // The coefficients, in child k's basis, of the function whose coefficients in this
    // element's are `parent` (push-pull's push): exact, since a child's local coordinates are
    // an affine image of its parent's and every basis is closed under those maps.
    Coefficients to_child(int k, const Coefficients& parent) const;
    // The projection onto this element's basis of the function that is `children[k]` on child k
    // (push-pull's pull): the mean of the four children's transforms, each child a quarter of
    // the domain. The identity after to_child.
    Coefficients from_children(const std::array<Coefficients, 4>& children) const;

    // Row i, column j: the mean over child k's domain of ψ_i of the parent times ψ_j of the
    // child, the coordinates of parent function i in child k's basis.
    const Transform& transform(int k) const { return m_transform[std::size_t(k)]; }

    // A bound on |ψ_k| over the domain: the sum of the magnitudes of its monomials'
    // coefficients, since every monomial is at most 1 there.
    double bound(int k) const { return m_bound[std::size_t(k)]; }

private:
    Coefficients monomials(double a, double b) const;

    Basis m_basis;
    bool m_quad;
    int m_size;
    std::array<std::array<int, 2>, kMaxBasisSize> m_exponents{};  // of a and b, per monomial
    Transform m_orthonormal;  // row k: ψ_k's coefficients on the monomials
    std::array<Transform, 4> m_transform;
    std::array<double, kMaxBasisSize> m_bound{};
};

// The basis for (basis, quad), made once.
const PolynomialBasis& polynomial_basis(Basis basis, bool quad);

// The largest bound(k) of the functions beyond the first of `basis`, on squares and triangles
// (1 for the constant basis): what a deposit toward one of them can be, relative to the
// deposit's power.
double term_bound(Basis basis);

}  // namespace hmcr
