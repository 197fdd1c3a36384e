// SPDX-License-Identifier: Apache-2.0
#include "information/scene_information.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "information/form_factors.h"

namespace hmcr {
namespace {

constexpr std::size_t kChunk = 64;  // patches per parallel task (fixed reduction order)

// Row sums of one batch (or all rays): -sum F log F and sum F log(F / a_j), in bits.
struct RowTerms {
    double entropy = 0, mutual = 0;
};

RowTerms row_terms(const std::vector<FormFactorEntry>& row, double rays,
                   const std::vector<double>& a) {
    RowTerms t;
    for (const FormFactorEntry& e : row) {
        const double f = e.count / rays;
        t.entropy -= f * std::log2(f);
        t.mutual += f * std::log2(f / a[e.patch]);
    }
    return t;
}

// sum_i a_i (row terms of i) for all samples (slot 0) and every batch (slot 1 + b). A row
// without samples (a patch no line crossed, or none in that batch) is left out.
std::vector<RowTerms> channel_terms(const ChannelSamples& samples, const std::vector<double>& a) {
    const std::size_t n = a.size(), slots = samples.batches + 1;
    const std::size_t chunks = (n + kChunk - 1) / kChunk;
    std::vector<RowTerms> partial(chunks * slots);
    tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
        for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
            for (std::size_t s = 0; s < slots; ++s) {
                const auto targets =
                    s == 0 ? samples.targets(i) : samples.targets(i, std::uint32_t(s - 1));
                if (targets.empty()) continue;
                const RowTerms t = row_terms(form_factor_row(targets), double(targets.size()), a);
                partial[c * slots + s].entropy += a[i] * t.entropy;
                partial[c * slots + s].mutual += a[i] * t.mutual;
            }
        }
    });
    std::vector<RowTerms> total(slots);
    for (std::size_t c = 0; c < chunks; ++c) {
        for (std::size_t s = 0; s < slots; ++s) {
            total[s].entropy += partial[c * slots + s].entropy;
            total[s].mutual += partial[c * slots + s].mutual;
        }
    }
    return total;
}

// The estimate from all lines, the standard error from the batch values (sd / sqrt(B)), and
// the bias from how far the batches (B times fewer lines each) sit from the estimate.
InformationMeasures::Value batch_value(double estimate, const std::vector<double>& batch) {
    const double b = double(batch.size());
    if (batch.size() < 2) return {estimate, 0.0, 0.0};
    double mean = 0, sq = 0;
    for (double v : batch) mean += v / b;
    for (double v : batch) sq += (v - mean) * (v - mean);
    return {estimate, std::sqrt(sq / (b - 1) / b), (mean - estimate) / (b - 1)};
}

}  // namespace

InformationMeasures scene_information(const PatchSet& patches, const LineOptions& options,
                                      Progress& progress) {
    return scene_information(patch_states(patches), options, progress);
}

InformationMeasures scene_information(const ChannelStates& channels, const LineOptions& options,
                                      Progress& progress) {
    const std::vector<Patch> fronts(
        channels.states.patches.begin(),
        channels.states.patches.begin() + std::ptrdiff_t(channels.fronts()));
    const EmbreeScene scene(fronts);
    return scene_information(
        channels.states,
        trace_lines(channels.states, scene, options, progress, channels.backs.get()),
        options.method);
}

InformationMeasures scene_information(const PatchSet& patches, const ChannelSamples& samples,
                                      LineMethod method) {
    std::vector<double> a(patches.patches.size());
    double h_p = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        a[i] = patches.patches[i].area / patches.total_area;
        if (a[i] > 0) h_p -= a[i] * std::log2(a[i]);
    }
    const std::vector<RowTerms> terms = channel_terms(samples, a);
    const std::size_t b = samples.batches;
    std::vector<double> h_s(b), i_s(b), h_j(b), i_cs(b), error(b);
    double sum = 0;
    std::size_t hits = 0;
    for (std::size_t k = 0; k < b; ++k) {
        h_s[k] = terms[k + 1].entropy;
        i_s[k] = terms[k + 1].mutual;
        h_j[k] = h_p + h_s[k];
        const auto n = samples.log_kernel_count[k];
        i_cs[k] = n > 0 ? samples.log_kernel_sum[k] / double(n) : 0.0;
        error[k] = i_cs[k] - i_s[k];
        sum += samples.log_kernel_sum[k];
        hits += n;
    }
    InformationMeasures m;
    m.method = method;
    m.lines = samples.lines;
    m.samples = samples.samples();
    m.samples_open = std::size_t(
        std::count(samples.target.begin(), samples.target.end(), ChannelSamples::kNoPatch));
    for (std::size_t i = 0; i < a.size(); ++i) m.patches_unsampled += samples.targets(i).empty();
    const double i_cs_all = hits > 0 ? sum / double(hits) : 0.0;
    m.h_p = {h_p, 0.0};
    m.h_s = batch_value(terms[0].entropy, h_s);
    m.i_s = batch_value(terms[0].mutual, i_s);
    m.h_j = batch_value(h_p + terms[0].entropy, h_j);
    m.i_cs = batch_value(i_cs_all, i_cs);
    m.discretisation_error = batch_value(i_cs_all - terms[0].mutual, error);
    return m;
}

nlohmann::json to_json(const InformationMeasures& m) {
    const auto value = [](const InformationMeasures::Value& v) {
        return nlohmann::json{
            {"estimate", v.estimate}, {"standard_error", v.standard_error}, {"bias", v.bias}};
    };
    return {{"units", "bits"},
            {"h_p", value(m.h_p)},
            {"h_s", value(m.h_s)},
            {"i_s", value(m.i_s)},
            {"h_j", value(m.h_j)},
            {"i_cs", value(m.i_cs)},
            {"discretisation_error", value(m.discretisation_error)},
            {"method", line_method_name(m.method)},
            {"lines", m.lines},
            {"samples", m.samples},
            {"samples_open", m.samples_open},
            {"patches_unsampled", m.patches_unsampled}};
}

}  // namespace hmcr
