// SPDX-License-Identifier: Apache-2.0
#include "tests/support/same_leaves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace hmcr::test {

void expect_same_leaves(const Hierarchy& a, const Hierarchy& b) {
    std::vector<std::pair<ElementId, Rgb>> la, lb;
    a.for_each_leaf([&](const Element& e) { la.emplace_back(e.id, e.radiosity); });
    b.for_each_leaf([&](const Element& e) { lb.emplace_back(e.id, e.radiosity); });
    EXPECT_EQ(la.size(), lb.size());
    for (std::size_t k = 0; k < std::min(la.size(), lb.size()); ++k) {
        if (!(la[k].first == lb[k].first) || !(la[k].second == lb[k].second).all()) {
            ADD_FAILURE() << "leaf " << k << " differs: " << la[k].first.to_string() << " vs "
                          << lb[k].first.to_string();
            return;
        }
    }
    // A higher basis's coefficients beyond the mean, leaf by leaf.
    EXPECT_EQ(a.basis(), b.basis());
    if (a.basis() == Basis::constant || a.basis() != b.basis()) return;
    std::vector<RgbCoefficients> ca, cb;
    a.for_each_leaf([&](const Element& e) { ca.push_back(a.radiosity_coefficients(e)); });
    b.for_each_leaf([&](const Element& e) { cb.push_back(b.radiosity_coefficients(e)); });
    for (std::size_t k = 0; k < std::min(ca.size(), cb.size()); ++k) {
        if (ca[k] != cb[k]) {
            ADD_FAILURE() << "leaf " << k << "'s coefficients differ";
            return;
        }
    }
}

Solution solve_on_one_and_two_threads(const PatchMesh& mesh, SolverOptions options,
                                      const SolveInputs& inputs) {
    options.threads = 1;
    Solution one = solve(mesh, options, inputs);
    options.threads = 2;
    const Solution two = solve(mesh, options, inputs);
    expect_same_leaves(*one.hierarchy, *two.hierarchy);
    EXPECT_EQ(one.cluster_of_side(), two.cluster_of_side());
    return one;
}

}  // namespace hmcr::test
