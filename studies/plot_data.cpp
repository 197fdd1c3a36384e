// SPDX-License-Identifier: Apache-2.0
#include "studies/plot_data.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "common/error.h"
#include "common/text_file.h"
#include "radiosity/oracle_registry.h"
#include "studies/cell_errors.h"
#include "studies/mean_se.h"
#include "trace/criteria/registry.h"

namespace hmcr {
namespace {

using nlohmann::json;

template <class Cell, class Name>
std::vector<std::string> names_in_order(const std::vector<Cell>& cells, Name&& name_of) {
    std::vector<std::string> out;
    for (const Cell& c : cells)
        if (std::find(out.begin(), out.end(), name_of(c)) == out.end()) out.push_back(name_of(c));
    return out;
}

// The distinct values of `key` over the cells, ascending; refused beyond kMaxPlotPoints.
template <class Cell, class T>
std::vector<T> distinct(const std::vector<Cell>& cells, T Cell::*key, const char* what) {
    std::set<T> values;
    for (const Cell& c : cells) values.insert(c.*key);
    if (values.size() > kMaxPlotPoints) {
        throw InputError(
            fmt::format("{} {}; a plot shows at most {}", values.size(), what, kMaxPlotPoints));
    }
    return {values.begin(), values.end()};
}

// A value the script can draw, or null (no seed, or one: no standard error).
json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json point(const MeanSe& x, const MeanSe& y) {
    return {{"x", finite_or_null(x.mean)},
            {"x_se", finite_or_null(x.se)},
            {"y", finite_or_null(y.mean)},
            {"y_se", finite_or_null(y.se)},
            {"n", y.n}};
}

json bar(const MeanSe& y) {
    return {{"y", finite_or_null(y.mean)}, {"y_se", finite_or_null(y.se)}, {"n", y.n}};
}

// Error against mean leaves per oracle, one point per budget, over each budget's successful
// cells that measured the error.
json leaves_panel(const std::vector<CellResult>& cells, const std::string& title,
                  const std::string& y_label,
                  const std::function<double(const CellResult&)>& error) {
    const std::vector<std::size_t> budgets = distinct(cells, &CellResult::budget, "budgets");
    json panel = {{"type", "lines"},    {"title", title},     {"x_label", "leaves"},
                  {"y_label", y_label}, {"x_ticks", budgets}, {"series", json::array()}};
    for (const std::string& oracle :
         names_in_order(cells, [](const CellResult& c) { return c.oracle; })) {
        json points = json::array();
        for (std::size_t b : budgets) {
            std::vector<double> leaves, y;
            for (const CellResult& c : cells) {
                if (c.oracle != oracle || c.budget != b || !c.ok() || std::isnan(error(c)))
                    continue;
                leaves.push_back(double(c.leaves));
                y.push_back(error(c));
            }
            if (!y.empty()) points.push_back(point(mean_se(leaves), mean_se(y)));
        }
        panel["series"].push_back({{"name", oracle}, {"points", points}});
    }
    return panel;
}

std::string patch_label(const PatchError& p) {
    return p.side == kBack ? fmt::format("{} back", p.patch) : std::to_string(p.patch);
}

// The shares of the squared object error held by the patches that hold the most of it at one
// budget (by the largest mean share over the oracles), per oracle: a cell that does not list a
// patch among its largest counts it as 0.
json patch_bars(const std::vector<CellResult>& cells, std::size_t budget) {
    constexpr std::size_t kPatchesShown = 8;
    const std::vector<std::string> oracles =
        names_in_order(cells, [](const CellResult& c) { return c.oracle; });
    const auto share = [](const CellResult& c, const std::string& label) {
        for (const PatchError& p : c.object_error.largest)
            if (patch_label(p) == label) return 100 * p.share;
        return 0.0;
    };
    const auto of = [&](const std::string& oracle) {
        std::vector<const CellResult*> out;
        for (const CellResult& c : cells) {
            if (c.oracle == oracle && c.budget == budget && c.ok()) out.push_back(&c);
        }
        return out;
    };
    std::vector<std::string> labels;
    for (const CellResult& c : cells) {
        if (c.budget != budget || !c.ok()) continue;
        for (const PatchError& p : c.object_error.largest) {
            const std::string l = patch_label(p);
            if (std::find(labels.begin(), labels.end(), l) == labels.end()) labels.push_back(l);
        }
    }
    // The largest first, by the largest of the oracles' mean shares; ties by label.
    std::map<std::string, double> largest;
    for (const std::string& l : labels) {
        for (const std::string& o : oracles) {
            std::vector<double> v;
            for (const CellResult* c : of(o)) v.push_back(share(*c, l));
            if (!v.empty()) largest[l] = std::max(largest[l], mean_se(v).mean);
        }
    }
    std::sort(labels.begin(), labels.end(), [&](const std::string& a, const std::string& b) {
        return largest[a] != largest[b] ? largest[a] > largest[b] : a < b;
    });
    if (labels.size() > kPatchesShown) labels.resize(kPatchesShown);
    json groups = json::array();
    for (const std::string& o : oracles) {
        json values = json::array();
        for (const std::string& l : labels) {
            std::vector<double> v;
            for (const CellResult* c : of(o)) v.push_back(share(*c, l));
            values.push_back(bar(mean_se(v)));
        }
        groups.push_back({{"name", o}, {"values", values}});
    }
    return {{"type", "bars"},
            {"title", fmt::format("{} leaves", budget)},
            {"y_label", "share of the squared object error (%)"},
            {"x_label", "patch (PatchId)"},
            {"categories", labels},
            {"groups", groups}};
}

double solution_rmse_p(const CellResult& c) { return view_mean(c, &ImageErrors::rmse_p); }
double mesh_rmse_p(const CellResult& c) { return mesh_view_mean(c, &ImageErrors::rmse_p); }
double solution_object_error(const CellResult& c) { return c.object_error.relative_l2; }

// A sampling cell's value averaged over its views, as table.md's "mean over the views".
double over_views(const SamplingCell& c, const std::function<double(const SamplingView&)>& value) {
    double sum = 0;
    for (const auto& [name, v] : c.views) sum += value(v);
    return sum / double(c.views.size());
}

double cell_rmse_p(const SamplingCell& c) {
    return over_views(c, [](const SamplingView& v) { return v.errors.rmse_p; });
}
double cell_spp(const SamplingCell& c) {
    return over_views(c, [](const SamplingView& v) { return v.spp; });
}

std::vector<const SamplingCell*> successful(const std::vector<SamplingCell>& cells,
                                            const std::string& sampler, double spp) {
    std::vector<const SamplingCell*> out;
    for (const SamplingCell& c : cells)
        if (c.sampler == sampler && c.spp == spp && c.ok() && !c.views.empty()) out.push_back(&c);
    return out;
}

std::vector<double> values(const std::vector<const SamplingCell*>& cells,
                           double (*value)(const SamplingCell&)) {
    std::vector<double> out;
    out.reserve(cells.size());
    for (const SamplingCell* c : cells) out.push_back(value(*c));
    return out;
}

// RMSEp per sampler at one target spp; bias and noise beside it when `splits` are given.
json spp_bars(const std::vector<SamplingCell>& cells, const std::vector<std::string>& samplers,
              double spp, const ErrorSplits* splits) {
    json rmse = {{"name", "RMSEp"}, {"values", json::array()}};
    json bias = {{"name", "bias"}, {"values", json::array()}};
    json noise = {{"name", "noise"}, {"values", json::array()}};
    for (const std::string& s : samplers) {
        rmse["values"].push_back(bar(mean_se(values(successful(cells, s, spp), cell_rmse_p))));
        if (splits == nullptr) continue;
        std::vector<double> b, n;  // empty: too few seeds for a split
        if (const auto it = splits->find(s); it != splits->end() && !it->second.empty()) {
            const ErrorSplit e = rms_over_views(it->second);
            b.push_back(e.bias);
            n.push_back(e.noise);
        }
        bias["values"].push_back(bar(mean_se(b)));
        noise["values"].push_back(bar(mean_se(n)));
    }
    json groups = json::array({rmse});
    if (splits != nullptr) {
        groups.push_back(bias);
        groups.push_back(noise);
    }
    return {{"type", "bars"},
            {"title", fmt::format("{:g} spp", spp)},
            {"y_label", "RMSEp (0–255)"},
            {"categories", samplers},
            {"groups", groups}};
}

// RMSEp against the spp reached, per sampler, one point per target spp.
json spp_lines(const std::vector<SamplingCell>& cells, const std::vector<std::string>& samplers,
               const std::vector<double>& spps) {
    json panel = {{"type", "lines"},
                  {"title", "RMSEp against samples per pixel"},
                  {"x_label", "samples per pixel"},
                  {"y_label", "RMSEp (0–255)"},
                  {"x_ticks", spps},
                  {"series", json::array()}};
    for (const std::string& s : samplers) {
        json points = json::array();
        for (double spp : spps) {
            const auto ok = successful(cells, s, spp);
            if (!ok.empty()) {
                points.push_back(
                    point(mean_se(values(ok, cell_spp)), mean_se(values(ok, cell_rmse_p))));
            }
        }
        panel["series"].push_back({{"name", s}, {"points", points}});
    }
    return panel;
}

ErrorSplits splits_from_json(const json& j) {
    ErrorSplits splits;
    for (const auto& [sampler, by_view] : j.items())
        for (const auto& [view, e] : by_view.items())
            splits[sampler][view] = {e.at("bias_rmse_p").get<double>(),
                                     e.at("noise_rmse_p").get<double>()};
    return splits;
}

// table.json's error_split: by sampler and view for a study of one spp value, else by spp first
// (keyed as the tables name an spp value, {:g}).
SppErrorSplits spp_splits_from_json(const json& j, const std::vector<double>& spps, bool by_spp) {
    SppErrorSplits splits;
    if (!by_spp) {
        for (double spp : spps) splits[spp] = splits_from_json(j);  // one value
        return splits;
    }
    for (double spp : spps) {
        if (const auto it = j.find(fmt::format("{:g}", spp)); it != j.end()) {
            splits[spp] = splits_from_json(*it);
        }
    }
    return splits;
}

template <class Registry, class Cell, class Name>
void check_names(const Registry& registry, const std::vector<Cell>& cells, Name&& name_of) {
    for (const Cell& c : cells) (void)find_named(registry, name_of(c));
}

}  // namespace

json meshing_plot_data(const std::string& scene, const std::vector<CellResult>& cells) {
    const bool object = std::any_of(cells.begin(), cells.end(), [](const CellResult& c) {
        return c.ok() && !std::isnan(c.object_error.relative_l2);
    });
    const bool mesh = std::any_of(cells.begin(), cells.end(),
                                  [](const CellResult& c) { return c.ok() && c.mesh_rays > 0; });
    const std::string y_label = object ? "object error (relative L2)" : "RMSEp (0–255)";
    json panels = json::array({leaves_panel(cells, "solution", y_label,
                                            object ? solution_object_error : solution_rmse_p)});
    if (mesh) {
        panels.push_back(leaves_panel(cells, "mesh (frozen re-solve)", y_label,
                                      object ? mesh_object_error : mesh_rmse_p));
    }
    json figures = json::array({{{"name", "error_vs_elements"}, {"panels", panels}}});
    if (object) {
        json by_patch = json::array();
        for (std::size_t b : distinct(cells, &CellResult::budget, "budgets")) {
            by_patch.push_back(patch_bars(cells, b));
        }
        figures.push_back({{"name", "error_by_patch"}, {"panels", by_patch}});
    }
    return {{"study", "meshing"}, {"scene", scene}, {"figures", figures}};
}

json sampling_plot_data(const std::string& scene, const std::vector<SamplingCell>& cells,
                        const SppErrorSplits& splits) {
    const std::vector<double> spps = distinct(cells, &SamplingCell::spp, "target spp");
    const std::vector<std::string> samplers =
        names_in_order(cells, [](const SamplingCell& c) { return c.sampler; });
    // Each panel's bias and noise are of its own spp's seeds, where any sampler has a split.
    const bool split =
        std::any_of(splits.begin(), splits.end(), [](const auto& s) { return !s.second.empty(); });
    static const ErrorSplits kNone;
    json bars = json::array();
    for (double spp : spps) {
        const auto it = splits.find(spp);
        bars.push_back(spp_bars(cells, samplers, spp,
                                !split               ? nullptr
                                : it == splits.end() ? &kNone
                                                     : &it->second));
    }
    json figures = json::array({{{"name", "error_by_sampler"}, {"panels", bars}}});
    if (spps.size() >= 2) {
        figures.push_back({{"name", "error_vs_spp"},
                           {"panels", json::array({spp_lines(cells, samplers, spps)})}});
    }
    return {{"study", "sampling"}, {"scene", scene}, {"figures", figures}};
}

json plot_data_of_table(const std::filesystem::path& table) {
    return read_json_file(table, [](const json& j) {
        const json& options = j.at("options");
        const std::string scene = j.at("scene").get<std::string>();
        if (options.contains("budgets")) {
            std::vector<CellResult> cells;
            for (const json& c : j.at("cells")) cells.push_back(cell_from_json(c));
            check_names(oracle_registry(), cells, [](const CellResult& c) { return c.oracle; });
            return meshing_plot_data(scene, cells);
        }
        if (options.contains("samplers")) {
            std::vector<SamplingCell> cells;
            for (const json& c : j.at("cells")) cells.push_back(sampling_cell_from_json(c));
            check_names(criterion_registry(), cells,
                        [](const SamplingCell& c) { return c.sampler; });
            const json& spp = options.at("spp");
            const bool by_spp = spp.is_array() && spp.size() > 1;
            return sampling_plot_data(
                scene, cells,
                spp_splits_from_json(j.at("error_split"),
                                     distinct(cells, &SamplingCell::spp, "target spp"), by_spp));
        }
        throw InputError(
            "neither a meshing study's table (options.budgets) nor a sampling "
            "study's (options.samplers)");
    });
}

std::filesystem::path plot_data_file(const std::filesystem::path& study) {
    return study / "plots" / "plot_data.json";
}

std::string plot_data_text(const json& data) { return data.dump(2) + "\n"; }

}  // namespace hmcr
