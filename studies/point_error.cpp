// SPDX-License-Identifier: Apache-2.0
#include "studies/point_error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "rays/embree_scene.h"
#include "studies/point_reference.h"
#include "studies/solution_probe.h"

namespace hmcr {
namespace {

// One point's terms of N and D and of their variances and covariance (see the header).
struct Terms {
    double n = 0, d = 0, var_n = 0, var_d = 0, cov = 0;
    SolutionProbe::Found found = SolutionProbe::Found::ray;
};

Terms point_terms(const SolutionProbe& probe, const PointTarget& t, std::size_t i) {
    const SurfacePoint& p = t.points.points[i];
    const SolutionProbe::Value s =
        probe.value(p.position, t.normal[i], int(p.patch), p.side, t.emission[i]);
    const Rgb b = t.points.mean(i), v = t.points.mean_variance(i);
    const Rgb x = s.radiosity - b, r = b - t.emission[i];
    const double w = p.weight, w2 = w * w;
    Terms out;
    out.found = s.found;
    out.n = w * (x.matrix().squaredNorm() - v.sum());
    out.d = w * (r.matrix().squaredNorm() - v.sum());
    for (int c = 0; c < 3; ++c) {
        const double x2 = std::max(0.0, x[c] * x[c] - v[c]), r2 = std::max(0.0, r[c] * r[c] - v[c]);
        // x and r move with the same noise in opposite directions: E[x r] = x0 r0 - v.
        const double xr = x[c] * r[c] + v[c];
        out.var_n += w2 * (4 * x2 * v[c] + 2 * v[c] * v[c]);
        out.var_d += w2 * (4 * r2 * v[c] + 2 * v[c] * v[c]);
        out.cov += w2 * (-4 * xr * v[c] + 2 * v[c] * v[c]);
    }
    return out;
}

struct Sums {
    double n = 0, d = 0, var_n = 0, var_d = 0, cov = 0;
    std::size_t unmatched = 0, nearest = 0, unlit = 0;

    void add(const Terms& t) {
        n += t.n;
        d += t.d;
        var_n += t.var_n;
        var_d += t.var_d;
        cov += t.cov;
        unmatched += t.found == SolutionProbe::Found::unmatched;
        nearest += t.found == SolutionProbe::Found::nearest;
        unlit += t.found == SolutionProbe::Found::unlit;
    }
};

}  // namespace

PointTarget point_target(PointRadiosity points, const PatchSet& set) {
    PointTarget t;
    t.emission = point_emission(set, points.points);
    t.normal.resize(points.points.size());
    for (std::size_t i = 0; i < points.points.size(); ++i) {
        const SurfacePoint& p = points.points[i];
        t.normal[i] = side_normal(set.patches[p.patch], p.side);
    }
    t.points = std::move(points);
    return t;
}

ObjectError point_object_error(const ShadedTracer& tracer, const ShadedMesh& solution,
                               const PointTarget& reference) {
    const std::size_t n = reference.points.points.size();
    const SolutionProbe probe(tracer, solution);
    std::vector<Terms> terms(n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
        set_tracing_float_mode();
        terms[i] = point_terms(probe, reference, i);
    });
    // Summed in point order: the same bits for any thread count.
    Sums sum;
    SideErrors by_side;
    for (std::size_t i = 0; i < n; ++i) {
        sum.add(terms[i]);
        by_side.add(reference.points.points[i].patch, reference.points.points[i].side, terms[i].n);
    }
    ObjectError out;
    out.samples = n;
    out.unmatched = sum.unmatched;
    out.nearest = sum.nearest;
    out.unlit = sum.unlit;
    out.largest = by_side.largest(sum.n);
    if (!(sum.d > 0)) {
        out.relative_l2 = sum.n > 0 ? std::numeric_limits<double>::infinity() : 0;
        return out;
    }
    const double q = sum.n / sum.d;  // e^2
    out.relative_l2 = std::sqrt(std::max(0.0, q));
    const double noise = std::max(0.0, sum.var_n - 2 * q * sum.cov + q * q * sum.var_d);
    // The quadrature's own variance, from neighbouring points taken as one stratum of two
    // (collapsed strata): each point's influence on q is (n_i - q d_i) / D.
    double quadrature = 0;
    for (std::size_t i = 0; i + 1 < n; i += 2) {
        const double a = terms[i].n - q * terms[i].d, b = terms[i + 1].n - q * terms[i + 1].d;
        quadrature += (a - b) * (a - b);
    }
    const double var_q = (noise + quadrature) / (sum.d * sum.d);
    const double se_q = std::sqrt(var_q);
    // se(e) = se(e^2) / (2 e) where e is well above its noise; near 0, e^2's noise sets the scale.
    out.standard_error = se_q / (2 * std::max(out.relative_l2, std::sqrt(se_q)));
    return out;
}

}  // namespace hmcr
