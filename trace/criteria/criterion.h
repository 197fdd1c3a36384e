// SPDX-License-Identifier: Apache-2.0
// Pixel sampling criteria: whether a pixel, or a region of one, has enough samples.
// Like the refinement oracles (oracles/oracle.h) they see plain numbers, the samples' radiance
// and geometry, never a scene or a ray; each is one file of trace/criteria/ plus one line of
// trace/criteria/registry.cpp.
//
// A criterion's scheme says how its samples are laid out (trace/pixel_runs.h runs them):
//   uniform   every pixel gets exactly the target number of samples; value() is not asked.
//   batches   a first batch of 8 stratified samples (2 x 4 strata), then further batches of 8
//             while value() of all the pixel's samples exceeds the threshold, up to the pixel's
//             maximum (Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences",
//             EGSR 2003, section 4.1).
//   quadtree  4 stratified samples (2 x 2) per node, starting at the pixel; a node whose value()
//             exceeds the threshold is split into 4 children (above the depth limit), each
//             keeping the parent's sample that lies in it and adding 3 (Rigau, Feixas, Sbert,
//             "Entropy-based adaptive supersampling", 2003, section 3.2 and Figure 5).
//   passes    Blender Cycles' scheme: a first batch of 8 stratified samples in every pixel,
//             then passes over the image, each giving one more batch of 8 to every pixel still
//             unconverged; after a pass a pixel is unconverged while value() of all its samples
//             exceeds the threshold or that of one of its 8 neighbours does (trace/pass_runs.h).
//             A pixel that stopped never starts again.
#pragma once

#include <span>
#include <string_view>

#include "common/types.h"

namespace hmcr {

struct PixelSample {
    Rgb radiance = Rgb::Zero();  // W sr^-1 m^-2
    double geometry = 0;         // cos(theta) / d^2 of the first hit seen from the eye; 0: none
};

enum class Scheme { uniform, batches, quadtree, passes };

class Criterion {
public:
    virtual ~Criterion() = default;
    virtual std::string_view name() const = 0;
    virtual std::string_view description() const = 0;  // one line, with its paper
    virtual Scheme scheme() const = 0;
    // The refinement value of the samples of a region covering `area` of its pixel (1 for the
    // whole pixel): the region gets more samples while the value exceeds the threshold. Not
    // negative; 0 for samples that are all equal.
    virtual double value(std::span<const PixelSample> samples, double area) const = 0;
};

// The fixed parts of a criterion, so that its file holds its formula and little else.
class NamedCriterion : public Criterion {
public:
    NamedCriterion(std::string_view name, std::string_view description, Scheme scheme)
        : m_name(name), m_description(description), m_scheme(scheme) {}
    std::string_view name() const override { return m_name; }
    std::string_view description() const override { return m_description; }
    Scheme scheme() const override { return m_scheme; }

private:
    std::string_view m_name, m_description;
    Scheme m_scheme;
};

}  // namespace hmcr
