// SPDX-License-Identifier: Apache-2.0
// The study's cell files and tables (studies/study.h): JSON per cell, the long-form table.json
// and table.csv, and the paper's tables table.md and table.tex.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "common/atomic_file.h"
#include "studies/cell_errors.h"
#include "studies/mean_se.h"
#include "studies/object_error_json.h"
#include "studies/plot_data.h"
#include "studies/reference_resolution.h"
#include "studies/study.h"
#include "studies/summary_table.h"
#include "studies/table_fields.h"

namespace hmcr {
namespace {

// One column of table.md: its name, how a cell gives its value, how it prints, which way is
// better.
struct MeshingColumn {
    const char* key;
    const char* title;
    std::function<double(const CellResult&)> value;
    NumberStyle style;
    int better;  // -1: lower is better, +1: higher, 0: not an error column
};

constexpr NumberStyle kDecimals2{2, false}, kDecimals1{1, false}, kWhole{0, false},
    kSignificant3{3, true};

std::vector<MeshingColumn> md_columns() {
    return {
        {"rmse_a", "RMSEa", [](const CellResult& c) { return view_mean(c, &ImageErrors::rmse_a); },
         kDecimals2, -1},
        {"rmse_p", "RMSEp", [](const CellResult& c) { return view_mean(c, &ImageErrors::rmse_p); },
         kDecimals2, -1},
        {"psnr_a", "PSNRa (dB)",
         [](const CellResult& c) { return view_mean(c, &ImageErrors::psnr_a); }, kDecimals2, 1},
        {"psnr_p", "PSNRp (dB)",
         [](const CellResult& c) { return view_mean(c, &ImageErrors::psnr_p); }, kDecimals2, 1},
        {"object_error", "object error",
         [](const CellResult& c) { return c.object_error.relative_l2; }, kSignificant3, -1},
        {"mesh_psnr_p", "mesh PSNRp (dB)",
         [](const CellResult& c) { return mesh_view_mean(c, &ImageErrors::psnr_p); }, kDecimals2,
         1},
        {"mesh_object_error", "mesh object error", mesh_object_error, kSignificant3, -1},
        {"finer_share", "finer (%)", [](const CellResult& c) { return 100 * c.finer_share; },
         kDecimals1, 0},
        {"leaves", "leaves", [](const CellResult& c) { return double(c.leaves); }, kWhole, 0},
        {"epsilon", "ε", [](const CellResult& c) { return c.epsilon; }, kSignificant3, 0},
        {"seconds", "seconds", [](const CellResult& c) { return c.seconds; }, kDecimals1, 0},
    };
}

std::size_t select_budget(const std::vector<CellResult>& cells, std::size_t budget) {
    return std::size_t(std::count_if(cells.begin(), cells.end(),
                                     [&](const CellResult& c) { return c.budget == budget; }));
}

std::vector<const CellResult*> select(const std::vector<CellResult>& cells, std::size_t budget,
                                      const std::string& oracle, bool ok_only) {
    std::vector<const CellResult*> out;
    for (const CellResult& c : cells)
        if (c.budget == budget && c.oracle == oracle && (!ok_only || c.ok())) out.push_back(&c);
    return out;
}

std::vector<std::string> oracle_order(const std::vector<CellResult>& cells) {
    std::vector<std::string> out;
    for (const CellResult& c : cells)
        if (std::find(out.begin(), out.end(), c.oracle) == out.end()) out.push_back(c.oracle);
    return out;
}

// One budget's table: a row per oracle, mean ± se of every column over its successful seeds.
SummaryTable budget_table(std::size_t budget, const std::vector<CellResult>& cells) {
    const std::vector<MeshingColumn> columns = md_columns();
    SummaryTable table;
    table.row_title = "oracle";
    for (const MeshingColumn& col : columns)
        table.columns.push_back({col.key, col.title, col.style, col.better});
    for (const std::string& oracle : oracle_order(cells)) {
        SummaryRow row{oracle, "", {}};
        for (const MeshingColumn& col : columns) {
            std::vector<double> v;
            for (const CellResult* c : select(cells, budget, oracle, true))
                if (const double x = col.value(*c); !std::isnan(x)) v.push_back(x);
            row.values.push_back(mean_se(v));
        }
        row.seeds =
            fmt::format("{}/{}", row.values[0].n, select(cells, budget, oracle, false).size());
        table.rows.push_back(std::move(row));
    }
    return table;
}

// What every table of the study shows: the paragraph above table.md's tables.
std::string description(const StudyOptions& o, const std::vector<std::string>& views) {
    const std::string rays = o.rays_per_leaf > 0
                                 ? fmt::format("{} rays per leaf of the budget", o.rays_per_leaf)
                                 : fmt::format("{} rays", o.solver.rays);
    const std::string frozen = "mesh: the same errors of the cell's final mesh solved again frozen";
    const std::string mesh =
        !o.mesh_rays ? fmt::format("{} with {} times the cell's rays, the error of the mesh itself",
                                   frozen, kMeshRaysPerCellRay)
        : *o.mesh_rays > 0
            ? fmt::format("{} with {} rays, the error of the mesh itself", frozen, *o.mesh_rays)
            : std::string("mesh: not measured (--mesh-rays 0)");
    return fmt::format(
        "{}, N_s = {}, link weight {}, refine share {}{}{}{}{}{}, budget tolerance {}%, {} from "
        "{}. "
        "Mean ± standard error over the seeds whose budget search succeeded (seeds column); a "
        "mean alone is of one seed (a standard error needs two or more) or of seeds that agree "
        "exactly. RMSE on the 0–255 scale and PSNR in dB, each averaged over {} ({}); object "
        "error: the area-weighted relative L2 error of the reflected radiosity against the "
        "reference (– against a traced reference, which has neither mesh nor points); {}; finer: "
        "the share of the area in leaves finer than the reference resolves (above {:.0f}% a "
        "cell's errors are bounded below by the reference's); seconds: the budget search. {}",
        rays, o.solver.lines, name(o.solver.link_weight), o.solver.refine_share,
        // Named only when not the default, so that the tables of plain studies keep their bytes.
        o.solver.control_variate == ControlVariate::none
            ? std::string()
            : fmt::format(", control variate {}", name(o.solver.control_variate)),
        o.solver.importance == Importance::none
            ? std::string()
            : fmt::format(", importance {}", name(o.solver.importance)),
        o.solver.sequence == SolverOptions{}.sequence
            ? std::string()
            : fmt::format(", sequence {}", name(o.solver.sequence)),
        o.solver.bidirectional == Bidirectional::no ? std::string()
                                                    : std::string(", lines both ways"),
        o.solver.basis == Basis::constant ? std::string()
                                          : fmt::format(", {} basis", name(o.solver.basis)),
        100 * o.budget_tolerance, counted(std::size_t(o.seeds), "seed"), o.solver.seed,
        counted(views.size(), "view"), fmt::join(views, ", "), mesh, 100 * kFinerShareLimit,
        kBoldRule);
}

}  // namespace

std::string finer_warning(const std::vector<CellResult>& cells, std::size_t budget) {
    std::vector<std::string> finer;
    for (const CellResult& c : cells) {
        if (c.budget == budget && c.ok() && c.finer_share > kFinerShareLimit) {
            finer.push_back(
                fmt::format("{} seed {} ({:.0f}%)", c.oracle, c.seed, 100 * c.finer_share));
        }
    }
    if (finer.empty()) return "";
    return fmt::format(
        "{} of {} cells have more than {:.0f}% of their area in leaves finer than "
        "the reference resolves ({}): their errors are bounded below by the reference's; "
        "measure them against a finer one (hmcr reference --for-budget {}).",
        finer.size(), select_budget(cells, budget), 100 * kFinerShareLimit, fmt::join(finer, ", "),
        budget);
}

namespace {

std::string md_table(const std::string& scene, const StudyOptions& o,
                     const std::vector<std::string>& views, const std::vector<CellResult>& cells) {
    const std::vector<std::string> keys =
        column_choice(o.columns, study_table_columns(), "meshing").markdown;
    std::string out = fmt::format("# Meshing study: {}\n\n{}\n\n", scene, description(o, views));
    for (std::size_t b : o.budgets) {
        out += fmt::format("## {} leaves\n\n{}\n", b,
                           markdown(with_columns(budget_table(b, cells), keys)));
        if (const std::string w = finer_warning(cells, b); !w.empty()) {
            out += "**Warning:** " + w + "\n\n";
        }
    }
    return out;
}

// table.tex: one table float per budget, to \input into a paper with booktabs.
std::string tex_table(const std::string& scene, const StudyOptions& o,
                      const std::vector<std::string>& views, const std::vector<CellResult>& cells) {
    const TableColumns columns = study_table_columns();
    const std::vector<std::string> keys = column_choice(o.columns, columns, "meshing").latex;
    std::string out = fmt::format(
        "% Meshing study: {} (hmcr). Needs \\usepackage{{booktabs}} and "
        "\\usepackage{{graphicx}}.\n% {}\n{}",
        latex_text(scene), latex_text(description(o, views)), latex_columns_comment(keys, columns));
    for (std::size_t b : o.budgets) {
        const SummaryTable table = with_columns(budget_table(b, cells), keys);
        out += latex_float(fmt::format("Meshing study of {} at {} leaves. {}", latex_text(scene), b,
                                       latex_text(legend(table))),
                           fmt::format("tab:{}-{}", latex_label(scene), b), table);
    }
    return out;
}

constexpr const char* kCsvHeader =
    "scene,oracle,budget,seed,status,epsilon,leaves,probes,seconds,view,rmse_a,rmse_p,psnr_a,"
    "psnr_p,object_error,object_error_se,object_samples,object_unmatched,object_unlit,"
    "finer_share,largest_patch,largest_side,largest_share,rays,mesh_rays,mesh_rmse_a,"
    "mesh_rmse_p,mesh_psnr_a,mesh_psnr_p,mesh_object_error,message";

std::string csv_table(const std::vector<std::string>& views, const std::vector<CellResult>& cells) {
    std::string out = std::string(kCsvHeader) + "\n";
    for (const CellResult& c : cells) {
        for (const std::string& view : views) {
            const auto it = c.views.find(view);
            const ImageErrors e =
                it != c.views.end() ? it->second : ImageErrors{kNaN, kNaN, kNaN, kNaN};
            const auto mit = c.mesh_views.find(view);
            const ImageErrors m =
                mit != c.mesh_views.end() ? mit->second : ImageErrors{kNaN, kNaN, kNaN, kNaN};
            const ObjectError& o = c.object_error;
            const double object = c.ok() ? o.relative_l2 : kNaN;
            const bool listed = c.ok() && !o.largest.empty();
            out += fmt::format(
                "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},"
                "{},{},{},{}\n",
                csv_text(c.scene), c.oracle, c.budget, c.seed, c.status, csv_number(c.epsilon),
                c.leaves, c.probes.size(), csv_number(c.seconds), csv_text(view),
                csv_number(e.rmse_a), csv_number(e.rmse_p), csv_number(e.psnr_a),
                csv_number(e.psnr_p), csv_number(object), csv_number(o.standard_error), o.samples,
                o.unmatched, o.unlit, csv_number(c.finer_share),
                listed ? std::to_string(o.largest[0].patch) : "",
                listed ? (o.largest[0].side == kBack ? "back" : "front") : "",
                listed ? csv_number(o.largest[0].share) : "", c.rays, c.mesh_rays,
                csv_number(m.rmse_a), csv_number(m.rmse_p), csv_number(m.psnr_a),
                csv_number(m.psnr_p), csv_number(c.ok() ? mesh_object_error(c) : kNaN),
                csv_text(c.message));
        }
    }
    return out;
}

std::map<std::string, ImageErrors> views_from_json(const nlohmann::json& views) {
    std::map<std::string, ImageErrors> out;
    for (const auto& [name, e] : views.items()) out[name] = e.get<ImageErrors>();
    return out;
}

// patches.csv: for every cell, the patch sides holding the largest shares of its squared object
// error, of the solution and of the frozen mesh.
std::string patches_csv(const std::vector<CellResult>& cells) {
    std::string out = "scene,oracle,budget,seed,of,rank,patch,side,share\n";
    for (const CellResult& c : cells) {
        if (!c.ok()) continue;
        const auto rows = [&](const char* of, const ObjectError& e) {
            for (std::size_t k = 0; k < e.largest.size(); ++k) {
                const PatchError& p = e.largest[k];
                out += fmt::format("{},{},{},{},{},{},{},{},{}\n", csv_text(c.scene), c.oracle,
                                   c.budget, c.seed, of, k + 1, p.patch,
                                   p.side == kBack ? "back" : "front", csv_number(p.share));
            }
        };
        rows("solution", c.object_error);
        if (c.mesh_rays > 0) rows("mesh", c.mesh_object_error);
    }
    return out;
}

}  // namespace

nlohmann::json cell_to_json(const CellResult& c) {
    return {{"scene", c.scene},
            {"oracle", c.oracle},
            {"budget", c.budget},
            {"seed", c.seed},
            {"settings", c.settings},
            {"status", c.status},
            {"message", c.message},
            {"epsilon", c.epsilon},
            {"leaves", c.leaves},
            {"probes", c.probes.size()},
            {"probe_history", nlohmann::json(c.probes)},
            {"seconds", c.seconds},
            {"views", nlohmann::json(c.views)},
            {"object_error", object_error_json(c.object_error)},
            {"finer_share", json_finite_or_null(c.finer_share)},
            {"rays", c.rays},
            {"mesh_rays", c.mesh_rays},
            // Not measured (--mesh-rays 0): null, not a perfect 0.
            {"mesh_views", c.mesh_rays > 0 ? nlohmann::json(c.mesh_views) : nlohmann::json()},
            {"mesh_object_error",
             c.mesh_rays > 0 ? object_error_json(c.mesh_object_error) : nlohmann::json()}};
}

CellResult cell_from_json(const nlohmann::json& j) {
    CellResult c;
    c.scene = j.at("scene").get<std::string>();
    c.oracle = j.at("oracle").get<std::string>();
    c.budget = json_count(j, "budget");
    c.seed = json_count(j, "seed");
    c.settings = j.value("settings", nlohmann::json());
    c.status = json_status(j);
    c.message = j.value("message", "");
    c.epsilon = json_non_negative(j, "epsilon", kNaN);
    c.leaves = json_count(j, "leaves");
    for (const auto& p : j.at("probe_history"))
        c.probes.push_back({json_non_negative(p, "epsilon", kNaN), json_count(p, "leaves"),
                            json_non_negative(p, "seconds", kNaN)});
    c.seconds = json_non_negative(j, "seconds", kNaN);
    c.views = views_from_json(j.at("views"));
    c.object_error = object_error_from_json(j.at("object_error"));
    c.finer_share = json_non_negative(j, "finer_share", kNaN);
    if (c.finer_share > 1)
        throw InputError(fmt::format("finer_share: {} is above 1", c.finer_share));
    c.rays = json_count(j, "rays");
    c.mesh_rays = json_count(j, "mesh_rays");
    if (c.mesh_rays > 0) {
        c.mesh_views = views_from_json(j.at("mesh_views"));
        c.mesh_object_error = object_error_from_json(j.at("mesh_object_error"));
    }
    return c;
}

TableColumns study_table_columns() {
    TableColumns out{{"seeds"}, {"seeds", "psnr_p", "object_error", "mesh_object_error"}};
    for (const MeshingColumn& col : md_columns()) out.all.emplace_back(col.key);
    return out;
}

void write_study_tables(OutputSet& out, const std::string& scene, const StudyOptions& o,
                        const std::vector<std::string>& views,
                        const std::vector<CellResult>& cells) {
    nlohmann::json all = nlohmann::json::array();
    for (const CellResult& c : cells) all.push_back(cell_to_json(c));
    nlohmann::json table = {{"scene", scene},
                            {"options",
                             {{"budgets", o.budgets},
                              {"oracles", oracle_order(cells)},
                              {"seeds", o.seeds},
                              {"first_seed", o.solver.seed},
                              {"rays", o.solver.rays},
                              {"rays_per_leaf", o.rays_per_leaf},
                              {"mesh_rays", mesh_rays_json(o)},
                              {"link_weight", name(o.solver.link_weight)},
                              {"refine_share", o.solver.refine_share},
                              {"lines", o.solver.lines},
                              {"budget_tolerance", o.budget_tolerance},
                              {"samples_per_axis", o.samples_per_axis},
                              {"reference", o.reference.string()}}},
                            {"views", views},
                            {"cells", all}};
    nlohmann::json& options = table["options"];
    if (o.solver.control_variate != ControlVariate::none) {
        options["control_variate"] = name(o.solver.control_variate);
    }
    if (o.solver.importance != Importance::none) {
        options["importance"] = name(o.solver.importance);
    }
    if (o.solver.sequence != SolverOptions{}.sequence)
        options["sequence"] = name(o.solver.sequence);
    if (o.solver.bidirectional != Bidirectional::no) {
        options["bidirectional"] = name(o.solver.bidirectional);
    }
    if (o.solver.basis != Basis::constant) options["basis"] = name(o.solver.basis);
    write_text_atomically(out.temp(o.output / "table.json"), table.dump(2) + "\n");
    write_text_atomically(out.temp(o.output / "table.csv"), csv_table(views, cells));
    write_text_atomically(out.temp(o.output / "patches.csv"), patches_csv(cells));
    write_text_atomically(out.temp(o.output / "table.md"), md_table(scene, o, views, cells));
    write_text_atomically(out.temp(o.output / "table.tex"), tex_table(scene, o, views, cells));
    write_text_atomically(out.temp(plot_data_file(o.output)),
                          plot_data_text(meshing_plot_data(scene, cells)));
}

}  // namespace hmcr
