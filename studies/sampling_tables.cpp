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

// One column of table.md: its name, a view's value, how it prints, which way is better (0: not
// an error).
struct Column {
    const char* key;
    const char* title;
    std::function<double(const SamplingView&)> value;
    NumberStyle style;
    int better;
};

constexpr NumberStyle kTwoDecimals{2, false}, kOneDecimal{1, false}, kNoDecimals{0, false};

std::vector<Column> columns() {
    return {
        {"rmse_a", "RMSEa", [](const SamplingView& v) { return v.errors.rmse_a; }, kTwoDecimals,
         -1},
        {"rmse_p", "RMSEp", [](const SamplingView& v) { return v.errors.rmse_p; }, kTwoDecimals,
         -1},
        {"psnr_a", "PSNRa (dB)", [](const SamplingView& v) { return v.errors.psnr_a; },
         kTwoDecimals, 1},
        {"psnr_p", "PSNRp (dB)", [](const SamplingView& v) { return v.errors.psnr_p; },
         kTwoDecimals, 1},
        {"spp", "spp", [](const SamplingView& v) { return v.spp; }, kOneDecimal, 0},
        {"max_spp", "max spp", [](const SamplingView& v) { return double(v.max_spp); }, kNoDecimals,
         0},
        {"rays", "rays (M)", [](const SamplingView& v) { return 1e-6 * double(v.rays); },
         kOneDecimal, 0},
        {"seconds", "seconds", [](const SamplingView& v) { return v.seconds; }, kOneDecimal, 0},
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
    for (const Column& col : cols)
        table.columns.push_back({col.key, col.title, col.style, col.better});
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
    table.columns = {{"bias_rmse_p", "bias RMSEp", kTwoDecimals, 0},
                     {"noise_rmse_p", "noise RMSEp", kTwoDecimals, 0}};
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
        "{} samples per pixel (±{}%), {} from {}, path estimator {}, at most {} bounces, "
        "criteria on {}{}{}, reference {}. Mean ± standard error over the seeds whose searches "
        "succeeded (seeds column); a mean alone is of one seed (a standard error needs two or "
        "more) or of seeds that agree exactly. RMSE on the 0–255 scale and PSNR in dB against "
        "the reference at its exposure; spp: the mean reached; rays: traced, the threshold "
        "search's included. {}",
        spp, 100 * o.trace.spp_tolerance, counted(std::size_t(o.seeds), "seed"), o.trace.seed,
        estimator_name(o.trace.path.estimator), o.trace.path.max_depth,
        o.display_criteria ? "display values" : "radiance",
        o.trace.allocation == Allocation::map
            ? ", adaptive samples allocated from a map of 8 uniform samples per pixel"
            : "",
        o.trace.fresh ? ", adaptive images from fresh samples" : "", o.reference.string(),
        kBoldRule);
}

constexpr const char* kSplitText =
    "RMSEp split as E[MSE of one image] = bias² + noise² and E[MSE of the mean of the k seeds' "
    "images] = bias² + noise²/k (RMS over the views). The bias includes the reference's own "
    "noise and the 8-bit rounding, which every sampler shares; an unbiased sampler shows only "
    "that.";

// The Markdown document of the cells at one spp; `keys`: the columns of its tables per sampler.
std::string md_document(const std::string& scene, const SamplingStudyOptions& o, double spp,
                        const std::vector<std::string>& views,
                        const std::vector<SamplingCell>& cells, const ErrorSplits& splits,
                        const std::vector<std::string>& keys) {
    std::string out =
        fmt::format("# Sampling study: {}\n\n{}\n\n## Mean over the views ({})\n\n{}\n", scene,
                    description(o, spp), fmt::join(views, ", "),
                    markdown(with_columns(summary(cells, ""), keys)));
    if (!splits.empty()) {
        out += fmt::format("## Bias and noise\n\n{}\n\n{}\n", kSplitText,
                           markdown(split_summary(splits, sampler_order(cells))));
    }
    for (const std::string& v : views) {
        out +=
            fmt::format("## View {}\n\n{}\n", v, markdown(with_columns(summary(cells, v), keys)));
    }
    return out;
}

// table.tex's floats of the cells at one spp; `at` names the spp in captions and labels when the
// study has several; `keys`: the columns of the tables per sampler.
std::string tex_floats(const std::string& scene, double spp, bool several,
                       const std::vector<std::string>& views,
                       const std::vector<SamplingCell>& cells, const ErrorSplits& splits,
                       const std::vector<std::string>& keys) {
    const std::string name = latex_text(scene);
    const std::string at = several ? fmt::format(" at {:g} spp", spp) : "";
    const std::string label =
        "tab:" + latex_label(scene) + "-sampling" + (several ? fmt::format("-spp{:g}", spp) : "");
    const SummaryTable mean = with_columns(summary(cells, ""), keys);
    std::string out = latex_float(fmt::format("Sampling study of {}{}, the mean over the views. {}",
                                              name, at, latex_text(legend(mean))),
                                  label, mean);
    if (!splits.empty()) {
        out +=
            latex_float(fmt::format("Sampling study of {}{}: RMSEp split into bias and noise. {}",
                                    name, at, latex_text(kSplitText)),
                        label + "-split", split_summary(splits, sampler_order(cells)));
    }
    for (const std::string& v : views) {
        const SummaryTable view = with_columns(summary(cells, v), keys);
        out += latex_float(fmt::format("Sampling study of {}{}, view {}. {}", name, at,
                                       latex_text(v), latex_text(legend(view))),
                           label + "-" + latex_label(v), view);
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

TableColumns sampling_table_columns() {
    TableColumns out{{"seeds"}, {"seeds", "rmse_p", "psnr_p", "spp", "rays"}};
    for (const Column& col : columns()) out.all.emplace_back(col.key);
    return out;
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
    const TableColumns columns = sampling_table_columns();
    const ColumnChoice keys = column_choice(o.columns, columns, "sampling");
    std::string md, tex;
    const bool several = o.spps.size() > 1;
    for (double spp : o.spps) {
        std::vector<SamplingCell> at_spp;
        for (const SamplingCell& c : cells)
            if (c.spp == spp) at_spp.push_back(c);
        static const ErrorSplits kNone;
        const auto it = splits.find(spp);
        const ErrorSplits& split = it == splits.end() ? kNone : it->second;
        md += (md.empty() ? "" : "\n") +
              md_document(scene, o, spp, views, at_spp, split, keys.markdown);
        tex += tex_floats(scene, spp, several, views, at_spp, split, keys.latex);
    }
    write_text_atomically(out.temp(o.output / "table.md"), md);
    write_text_atomically(out.temp(o.output / "table.tex"),
                          fmt::format("% Sampling study: {} (hmcr). Needs \\usepackage{{booktabs}} "
                                      "and \\usepackage{{graphicx}}.\n% {}\n{}{}",
                                      latex_text(scene), latex_text(description(o, o.spps.front())),
                                      latex_columns_comment(keys.latex, columns), tex));
    write_text_atomically(out.temp(plot_data_file(o.output)),
                          plot_data_text(sampling_plot_data(scene, cells, splits)));
}

}  // namespace hmcr
