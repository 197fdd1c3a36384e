// SPDX-License-Identifier: Apache-2.0
// The sampling study's cell files and tables (studies/sampling_study.h).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "common/atomic_file.h"
#include "studies/mean_se.h"
#include "studies/plot_data.h"
#include "studies/sampling_study.h"
#include "studies/summary_table.h"
#include "studies/table_fields.h"

namespace hmcr {
namespace {

// One column of table.md: a view's value, its format, which way is better (0: not an error).
struct Column {
    const char* title;
    std::function<double(const SamplingView&)> value;
    const char* format;
    int better;
};

std::vector<Column> columns() {
    return {
        {"RMSEa", [](const SamplingView& v) { return v.errors.rmse_a; }, "{:.2f}", -1},
        {"RMSEp", [](const SamplingView& v) { return v.errors.rmse_p; }, "{:.2f}", -1},
        {"PSNRa (dB)", [](const SamplingView& v) { return v.errors.psnr_a; }, "{:.2f}", 1},
        {"PSNRp (dB)", [](const SamplingView& v) { return v.errors.psnr_p; }, "{:.2f}", 1},
        {"spp", [](const SamplingView& v) { return v.spp; }, "{:.1f}", 0},
        {"max spp", [](const SamplingView& v) { return double(v.max_spp); }, "{:.0f}", 0},
        {"rays (M)", [](const SamplingView& v) { return 1e-6 * double(v.rays); }, "{:.1f}", 0},
        {"seconds", [](const SamplingView& v) { return v.seconds; }, "{:.1f}", 0},
    };
}

std::vector<std::string> sampler_order(const std::vector<SamplingCell>& cells) {
    std::vector<std::string> out;
    for (const SamplingCell& c : cells)
        if (std::find(out.begin(), out.end(), c.sampler) == out.end()) out.push_back(c.sampler);
    return out;
}

// A cell's value of a column: one view's, or the mean over the views (views empty).
double cell_value(const SamplingCell& c, const Column& col, const std::string& view) {
    if (!view.empty()) return col.value(c.views.at(view));
    double sum = 0;
    for (const auto& [name, v] : c.views) sum += col.value(v);
    return sum / double(c.views.size());
}

// A row per sampler: mean ± se over its successful seeds of every column, of one view or of the
// mean over the views (view empty).
SummaryTable summary(const std::vector<SamplingCell>& cells, const std::string& view) {
    const std::vector<Column> cols = columns();
    SummaryTable table;
    table.row_title = "sampler";
    for (const Column& col : cols) table.columns.push_back({col.title, col.format, col.better});
    for (const std::string& s : sampler_order(cells)) {
        SummaryRow row{s, "", {}};
        std::size_t runs = 0;
        for (const Column& col : cols) {
            std::vector<double> v;
            for (const SamplingCell& c : cells) {
                if (c.sampler == s && c.ok()) v.push_back(cell_value(c, col, view));
                if (c.sampler == s && &col == &cols[0]) ++runs;
            }
            row.values.push_back(mean_se(v));
        }
        row.seeds = fmt::format("{}/{}", row.values[0].n, runs);
        table.rows.push_back(std::move(row));
    }
    return table;
}

// sampler | bias | noise, each the RMS over the views of the per-view parts.
SummaryTable split_summary(const ErrorSplits& splits, const std::vector<std::string>& samplers) {
    SummaryTable table;
    table.row_title = "sampler";
    table.seeds_column = false;
    table.columns = {{"bias RMSEp", "{:.2f}", 0}, {"noise RMSEp", "{:.2f}", 0}};
    for (const std::string& s : samplers) {
        const auto it = splits.find(s);
        if (it == splits.end() || it->second.empty()) continue;
        const ErrorSplit e = rms_over_views(it->second);
        table.rows.push_back({s, "", {mean_se({e.bias}), mean_se({e.noise})}});
    }
    return table;
}

// The paragraph above the tables of one spp value.
std::string description(const SamplingStudyOptions& o, double spp) {
    return fmt::format(
        "{} samples per pixel (±{}%), {} seeds from {}, path estimator {}, at most {} bounces, "
        "criteria on {}{}{}, reference {}. Mean ± "
        "standard error over the seeds whose searches succeeded (seeds column). RMSE on the "
        "0–255 scale and PSNR in dB against the reference at its exposure; spp: the mean "
        "reached; rays: traced, the threshold search's included. The best mean of each error "
        "column is in bold.",
        spp, 100 * o.trace.spp_tolerance, o.seeds, o.trace.seed,
        estimator_name(o.trace.path.estimator), o.trace.path.max_depth,
        o.display_criteria ? "display values" : "radiance",
        o.trace.allocation == Allocation::map
            ? ", adaptive samples allocated from a map of 8 uniform samples per pixel"
            : "",
        o.trace.fresh ? ", adaptive images from fresh samples" : "", o.reference.string());
}

constexpr const char* kSplitText =
    "RMSEp split as E[MSE of one image] = bias² + noise² and E[MSE of the mean of the k seeds' "
    "images] = bias² + noise²/k (RMS over the views). The bias includes the reference's own "
    "noise and the 8-bit rounding, which every sampler shares; an unbiased sampler shows only "
    "that.";

// The Markdown document of the cells at one spp.
std::string md_document(const std::string& scene, const SamplingStudyOptions& o, double spp,
                        const std::vector<std::string>& views,
                        const std::vector<SamplingCell>& cells, const ErrorSplits& splits) {
    std::string out =
        fmt::format("# Sampling study: {}\n\n{}\n\n## Mean over the views ({})\n\n{}\n", scene,
                    description(o, spp), fmt::join(views, ", "), markdown(summary(cells, "")));
    if (!splits.empty()) {
        out += fmt::format("## Bias and noise\n\n{}\n\n{}\n", kSplitText,
                           markdown(split_summary(splits, sampler_order(cells))));
    }
    for (const std::string& v : views)
        out += fmt::format("## View {}\n\n{}\n", v, markdown(summary(cells, v)));
    return out;
}

// table.tex's floats of the cells at one spp; `at` names the spp in captions and labels when the
// study has several.
std::string tex_floats(const std::string& scene, double spp, bool several,
                       const std::vector<std::string>& views,
                       const std::vector<SamplingCell>& cells, const ErrorSplits& splits) {
    const std::string name = latex_text(scene);
    const std::string at = several ? fmt::format(" at {:g} spp", spp) : "";
    const std::string label =
        "tab:" + latex_label(scene) + "-sampling" + (several ? fmt::format("-spp{:g}", spp) : "");
    const std::string what =
        "mean $\\pm$ standard error over the seeds; the best mean of each "
        "error column in bold.";
    std::string out = latex_float(
        fmt::format("Sampling study of {}{}, the mean over the views: {}", name, at, what), label,
        summary(cells, ""));
    if (!splits.empty()) {
        out +=
            latex_float(fmt::format("Sampling study of {}{}: RMSEp split into bias and noise. {}",
                                    name, at, latex_text(kSplitText)),
                        label + "-split", split_summary(splits, sampler_order(cells)));
    }
    for (const std::string& v : views) {
        out += latex_float(
            fmt::format("Sampling study of {}{}, view {}: {}", name, at, latex_text(v), what),
            label + "-" + latex_label(v), summary(cells, v));
    }
    return out;
}

std::string csv_table(const std::vector<std::string>& views,
                      const std::vector<SamplingCell>& cells) {
    std::string out =
        "scene,sampler,spp_target,seed,status,view,spp,min_spp,max_spp,threshold,rays,seconds,"
        "rmse_a,rmse_p,psnr_a,psnr_p,message\n";
    for (const SamplingCell& c : cells) {
        for (const std::string& name : views) {
            const auto it = c.views.find(name);
            const SamplingView v =
                it != c.views.end()
                    ? it->second
                    : SamplingView{{kNaN, kNaN, kNaN, kNaN}, kNaN, 0, 0, kNaN, 0, kNaN};
            out += fmt::format(
                "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", csv_text(c.scene),
                c.sampler, c.spp, c.seed, c.status, csv_text(name), csv_number(v.spp), v.min_spp,
                v.max_spp, csv_number(v.threshold), v.rays, csv_number(v.seconds),
                csv_number(v.errors.rmse_a), csv_number(v.errors.rmse_p),
                csv_number(v.errors.psnr_a), csv_number(v.errors.psnr_p), csv_text(c.message));
        }
    }
    return out;
}

nlohmann::json view_to_json(const SamplingView& v) {
    return {{"errors", v.errors},       {"spp", v.spp},
            {"min_spp", v.min_spp},     {"max_spp", v.max_spp},
            {"threshold", v.threshold}, {"rays", v.rays},
            {"seconds", v.seconds}};
}

SamplingView view_from_json(const nlohmann::json& j) {
    constexpr std::uint32_t kMaxSpp = std::numeric_limits<std::uint32_t>::max();
    return {j.at("errors").get<ImageErrors>(),
            json_non_negative(j, "spp", kNaN),
            std::uint32_t(json_count(j, "min_spp", kMaxSpp)),
            std::uint32_t(json_count(j, "max_spp", kMaxSpp)),
            json_non_negative(j, "threshold", kNaN),
            json_count(j, "rays"),
            json_non_negative(j, "seconds", kNaN)};
}

}  // namespace

ErrorSplit rms_over_views(const std::map<std::string, ErrorSplit>& by_view) {
    double bias2 = 0, noise2 = 0;
    for (const auto& [view, e] : by_view) {
        bias2 += e.bias * e.bias / double(by_view.size());
        noise2 += e.noise * e.noise / double(by_view.size());
    }
    return {std::sqrt(bias2), std::sqrt(noise2)};
}

nlohmann::json sampling_cell_to_json(const SamplingCell& c) {
    nlohmann::json views = nlohmann::json::object();
    for (const auto& [name, v] : c.views) views[name] = view_to_json(v);
    return {{"scene", c.scene},     {"sampler", c.sampler},   {"spp", c.spp},
            {"seed", c.seed},       {"settings", c.settings}, {"status", c.status},
            {"message", c.message}, {"views", views},         {"seconds", c.seconds}};
}

SamplingCell sampling_cell_from_json(const nlohmann::json& j) {
    SamplingCell c;
    c.scene = j.at("scene").get<std::string>();
    c.sampler = j.at("sampler").get<std::string>();
    c.spp = j.at("spp").get<double>();
    if (!(c.spp > 0 && std::isfinite(c.spp))) {
        throw InputError(fmt::format("spp: {} is not a positive number", c.spp));
    }
    c.seed = json_count(j, "seed");
    c.settings = j.value("settings", nlohmann::json());
    c.status = json_status(j);
    c.message = j.value("message", "");
    for (const auto& [name, v] : j.at("views").items()) c.views[name] = view_from_json(v);
    c.seconds = json_non_negative(j, "seconds", kNaN);
    return c;
}

void write_sampling_tables(OutputSet& out, const std::string& scene, const SamplingStudyOptions& o,
                           const std::vector<std::string>& views,
                           const std::vector<SamplingCell>& cells, const SppErrorSplits& splits) {
    // error_split: by sampler and view, and with several spp values by spp first
    nlohmann::json split_json = nlohmann::json::object();
    for (const auto& [spp, by_sampler] : splits)
        for (const auto& [sampler, by_view] : by_sampler)
            for (const auto& [view, e] : by_view) {
                const nlohmann::json part = {{"bias_rmse_p", e.bias}, {"noise_rmse_p", e.noise}};
                if (o.spps.size() == 1) {
                    split_json[sampler][view] = part;
                } else {
                    split_json[fmt::format("{:g}", spp)][sampler][view] = part;
                }
            }
    nlohmann::json all = nlohmann::json::array();
    for (const SamplingCell& c : cells) all.push_back(sampling_cell_to_json(c));
    const nlohmann::json table = {{"scene", scene},
                                  {"options",
                                   {{"spp", o.spps},
                                    {"allocation", allocation_name(o.trace.allocation)},
                                    {"spp_tolerance", o.trace.spp_tolerance},
                                    {"samplers", sampler_order(cells)},
                                    {"seeds", o.seeds},
                                    {"first_seed", o.trace.seed},
                                    {"estimator", estimator_name(o.trace.path.estimator)},
                                    {"max_depth", o.trace.path.max_depth},
                                    {"tree_depth", o.trace.tree_depth},
                                    {"display_criteria", o.display_criteria},
                                    {"fresh", o.trace.fresh},
                                    {"reference", o.reference.string()}}},
                                  {"views", views},
                                  {"error_split", split_json},
                                  {"cells", all}};
    write_text_atomically(out.temp(o.output / "table.json"), table.dump(2) + "\n");
    write_text_atomically(out.temp(o.output / "table.csv"), csv_table(views, cells));
    std::string md, tex;
    const bool several = o.spps.size() > 1;
    for (double spp : o.spps) {
        std::vector<SamplingCell> at_spp;
        for (const SamplingCell& c : cells)
            if (c.spp == spp) at_spp.push_back(c);
        static const ErrorSplits kNone;
        const auto it = splits.find(spp);
        const ErrorSplits& split = it == splits.end() ? kNone : it->second;
        md += (md.empty() ? "" : "\n") + md_document(scene, o, spp, views, at_spp, split);
        tex += tex_floats(scene, spp, several, views, at_spp, split);
    }
    write_text_atomically(out.temp(o.output / "table.md"), md);
    write_text_atomically(
        out.temp(o.output / "table.tex"),
        fmt::format("% Sampling study: {} (hmcr). Needs \\usepackage{{booktabs}} "
                    "and \\usepackage{{graphicx}}.\n% {}\n{}",
                    latex_text(scene), latex_text(description(o, o.spps.front())), tex));
    write_text_atomically(out.temp(plot_data_file(o.output)),
                          plot_data_text(sampling_plot_data(scene, cells, splits)));
}

}  // namespace hmcr
