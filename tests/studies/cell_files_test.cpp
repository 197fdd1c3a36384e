// SPDX-License-Identifier: Apache-2.0
// A study's cell files are checked as they are read (studies/table_fields.h): a value no study
// writes is an InputError, and the study computes the cell again instead of tabling it.
#include "studies/cell_files.h"

#include <gtest/gtest.h>

#include <limits>

#include "common/error.h"
#include "studies/sampling_study.h"
#include "studies/study.h"

namespace hmcr::test {
namespace {

using nlohmann::json;

json meshing_cell() {
    CellResult c;
    c.scene = "plates";
    c.oracle = "power";
    c.budget = 20;
    c.seed = 1;
    c.epsilon = 1e-3;
    c.leaves = 21;
    c.probes = {{1e-3, 21, 0.1}};
    c.seconds = 0.1;
    c.views["side"] = {1.5, 1.2, 44.6, 46.5};
    c.object_error.relative_l2 = 0.04;
    c.object_error.samples = 768;
    c.rays = 20000;
    c.mesh_rays = 1000000;
    c.mesh_views["side"] = {0.3, 0.3, 58.7, 58.7};
    c.mesh_object_error.relative_l2 = 0.03;
    c.mesh_object_error.samples = 768;
    return cell_to_json(c);
}

json sampling_cell() {
    SamplingCell c;
    c.scene = "plates";
    c.sampler = "kl";
    c.spp = 16;
    c.seed = 1;
    c.views["side"] = {{1.5, 1.2, 44.6, 46.5}, 16.1, 4, 96, 0.02, 16500, 0.3};
    c.seconds = 0.3;
    return sampling_cell_to_json(c);
}

// `cell` with the value at `pointer` replaced.
json spoiled(json cell, const std::string& pointer, const json& value) {
    cell[json::json_pointer(pointer)] = value;
    return cell;
}

TEST(CellFiles, AGoodCellReadsBack) {
    EXPECT_EQ(cell_to_json(cell_from_json(meshing_cell())), meshing_cell());
    EXPECT_EQ(sampling_cell_to_json(sampling_cell_from_json(sampling_cell())), sampling_cell());
    // What the tables store for what was not measured: null, read as NaN or infinity.
    EXPECT_NO_THROW(cell_from_json(spoiled(meshing_cell(), "/object_error/relative_l2", nullptr)));
    EXPECT_NO_THROW(cell_from_json(spoiled(meshing_cell(), "/views/side/psnr_p", nullptr)));
    EXPECT_NO_THROW(
        sampling_cell_from_json(spoiled(sampling_cell(), "/views/side/threshold", nullptr)));
}

TEST(CellFiles, ValuesNoStudyWritesAreRefused) {
    const std::pair<const char*, json> meshing[] = {
        {"/budget", -20},
        {"/budget", 2.5},
        {"/seed", -1},
        {"/leaves", -3},
        {"/leaves", 1e30},
        {"/epsilon", -1e-3},
        {"/seconds", -1},
        {"/rays", -20000},
        {"/mesh_rays", "many"},
        {"/status", "great"},
        {"/probe_history/0/leaves", -7},
        {"/probe_history/0/epsilon", -1},
        {"/object_error/relative_l2", -0.5},
        {"/object_error/samples", -1},
        {"/object_error/unmatched", 0.5},
        {"/views/side/rmse_a", -1},
        {"/views/side/psnr_p", -3},
        {"/mesh_views/side/rmse_p", -0.1},
        {"/mesh_object_error/relative_l2", -0.03},
    };
    for (const auto& [pointer, value] : meshing) {
        EXPECT_THROW(cell_from_json(spoiled(meshing_cell(), pointer, value)), InputError)
            << pointer << " = " << value;
    }
    const std::pair<const char*, json> sampling[] = {
        {"/spp", -16},
        {"/spp", 0},
        {"/seed", -1},
        {"/status", ""},
        {"/seconds", -0.3},
        {"/views/side/spp", -16.1},
        {"/views/side/min_spp", -4},
        {"/views/side/max_spp", 5e9},
        {"/views/side/threshold", -0.02},
        {"/views/side/rays", -1},
        {"/views/side/errors/rmse_p", -1.2},
    };
    for (const auto& [pointer, value] : sampling) {
        EXPECT_THROW(sampling_cell_from_json(spoiled(sampling_cell(), pointer, value)), InputError)
            << pointer << " = " << value;
    }
}

TEST(CellFiles, AStudyIsBoundedInCellsAndSeeds) {
    EXPECT_NO_THROW(check_study_size(7, 1428, 1));
    EXPECT_THROW(check_study_size(7, 1429, 1), InputError);
    EXPECT_THROW(check_study_size(1, 1'000'000'000, 1), InputError);
    EXPECT_THROW(check_study_size(std::numeric_limits<std::uint64_t>::max(), 2, 1), InputError);
    const std::uint64_t last = std::numeric_limits<std::uint64_t>::max();
    EXPECT_NO_THROW(check_study_size(1, 1, last));
    EXPECT_NO_THROW(check_study_size(1, 3, last - 2));
    EXPECT_THROW(check_study_size(1, 3, last - 1), InputError);
}

}  // namespace
}  // namespace hmcr::test
