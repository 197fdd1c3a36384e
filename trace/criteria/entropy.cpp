// SPDX-License-Identifier: Apache-2.0
// entropy: the entropy contrast of a quadtree node, channel entropies normalised by log n.
// Rigau, Feixas, Sbert, "Entropy-based adaptive supersampling", 2003, eqs. 7, 10, 18, 19.
//
//   C_i = 1 - H(p) / ln n,  p_k = c_k / sum c_k  (n samples of one channel, or of cos/d^2)
//
// and 1 - H(p) / ln n = D(p||uniform) / ln n, since D(p||uniform) = ln n - H(p): the
// Kullback-Leibler divergence the oracles use (oracles/divergences.h). Combined into eq. 19 by
// trace/criteria/entropy_contrast.h. When to use it: edges and shadow contours, with a depth-
// limited subpixel tree that spends samples inside the pixel where they vary.
#include <cmath>
#include <memory>

#include "oracles/divergences.h"
#include "trace/criteria/criterion.h"
#include "trace/criteria/entropy_contrast.h"

namespace hmcr {
namespace {

double normalised_entropy_contrast(std::span<const double> values, double sum) {
    if (values.size() < 2) return 0;
    return kl_divergence(values, sum) / std::log(double(values.size()));
}

class EntropyCriterion final : public NamedCriterion {
public:
    EntropyCriterion()
        : NamedCriterion("entropy",
                         "colour and geometric entropy contrast on a subpixel "
                         "quadtree (Rigau 2003)",
                         Scheme::quadtree) {}

    double value(std::span<const PixelSample> samples, double area) const override {
        return entropy_contrast(samples, area, normalised_entropy_contrast);
    }
};

}  // namespace

std::unique_ptr<Criterion> make_entropy_criterion() { return std::make_unique<EntropyCriterion>(); }

}  // namespace hmcr
