// SPDX-License-Identifier: Apache-2.0
#include "radiosity/budget_search.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "radiosity/solve_passes.h"

namespace hmcr {
namespace {

// The probes so far and the bracket [lo, hi] in log epsilon: more leaves than the target at
// lo, fewer at hi (the leaf count falls as epsilon grows).
class Search {
public:
    Search(const PatchMesh& mesh, const SolverOptions& options, const BudgetOptions& budget,
           const SolveInputs& inputs, Progress& progress, const Ranks& ranks, KnownProbes* known)
        : m_mesh(mesh),
          m_options(options),
          m_budget(budget),
          m_inputs(inputs),
          m_passes(passes_of(options)),
          m_progress(progress),
          m_ranks(ranks),
          m_known(known) {}

    BudgetResult run();

private:
    // Solves at log epsilon x, or finds its leaf count known; returns the leaf count. Keeps the
    // solve if it is within the tolerance (the search then ends).
    std::size_t probe(double x);
    void record(double x, const BudgetProbe& p);
    bool within(std::size_t leaves) const {
        return std::abs(double(leaves) - double(m_budget.leaves)) <=
               m_budget.tolerance * double(m_budget.leaves);
    }
    double next_point() const;
    [[noreturn]] void fail(const std::string& why) const;

    const PatchMesh& m_mesh;
    const SolverOptions& m_options;
    BudgetOptions m_budget;
    SolveInputs m_inputs;
    // Every probe is a refining pass of the refining rays at its own epsilon; the accepted one
    // is then frozen with the rest.
    Passes m_passes;
    // The probes' scene, buffers and view importance (they solve the same patches), made by the
    // first and handed to each next probe, then to the frozen pass.
    ShootingSetup m_shooting;
    double m_accepted_epsilon = 0;
    Progress& m_progress;
    const Ranks& m_ranks;
    KnownProbes* m_known;
    BudgetResult m_result;
    std::optional<double> m_lo, m_hi;  // log epsilon bounds
    std::size_t m_lo_leaves = 0, m_hi_leaves = 0;
    std::optional<BudgetProbe> m_closest;  // to the target, for a failure's message
};

std::size_t Search::probe(double x) {
    const Pass pass{std::exp(x), m_passes.refining.rays};
    const std::size_t k = m_result.probes.size() + 1;
    if (m_known) {
        const auto it = m_known->find(pass.epsilon);
        if (it != m_known->end() && !within(it->second)) {
            record(x, {pass.epsilon, it->second, 0, true});
            m_progress.note(fmt::format("budget probe {}: epsilon {:.4g} -> {} leaves (known)", k,
                                        pass.epsilon, it->second));
            return it->second;
        }
    }
    m_progress.stage(fmt::format("budget probe {}", k));
    Solution sol = refine_pass(build_patch_set(m_mesh), m_options, pass, m_inputs, m_shooting,
                               m_progress, m_ranks);
    const BudgetProbe p{pass.epsilon, sol.stats.leaves, sol.stats.total_seconds};
    if (m_known) (*m_known)[pass.epsilon] = p.leaves;
    record(x, p);
    m_progress.note(fmt::format("budget probe {}: epsilon {:.4g} -> {} leaves ({:.1f} s)", k,
                                p.epsilon, p.leaves, p.seconds));
    if (within(p.leaves)) {
        m_result.solution = std::move(sol);
        m_accepted_epsilon = pass.epsilon;
    }
    return p.leaves;
}

void Search::record(double x, const BudgetProbe& p) {
    m_result.probes.push_back(p);
    const auto distance = [&](const BudgetProbe& q) {
        return std::abs(double(q.leaves) - double(m_budget.leaves));
    };
    if (!m_closest || distance(p) < distance(*m_closest)) m_closest = p;
    if (p.leaves > m_budget.leaves) {
        m_lo = x;
        m_lo_leaves = p.leaves;
    } else {
        m_hi = x;
        m_hi_leaves = p.leaves;
    }
}

// Inside a bracket: the log-log interpolation of the two ends (leaf counts follow a power of
// epsilon closely), kept in the middle 80% so that the bracket always shrinks; outside one:
// a step of a factor 10 towards the target.
double Search::next_point() const {
    if (!m_lo) return *m_hi - std::log(10.0);
    if (!m_hi) return *m_lo + std::log(10.0);
    const double a = std::log(double(m_lo_leaves)),
                 b = std::log(double(std::max<std::size_t>(1, m_hi_leaves)));
    const double t = (a - std::log(double(m_budget.leaves))) / (a - b);
    return *m_lo + std::clamp(t, 0.1, 0.9) * (*m_hi - *m_lo);
}

void Search::fail(const std::string& why) const {
    throw BudgetNotReached(fmt::format("budget of {} leaves (+-{}%) not reached: {}",
                                       m_budget.leaves, 100 * m_budget.tolerance, why));
}

BudgetResult Search::run() {
    // Without clusters a mesh has at least a leaf per patch (docs/design.md §2.7).
    const std::size_t patches = m_mesh.n_faces();
    if (m_options.clustering == Clustering::none && m_budget.leaves < patches) {
        fail(
            fmt::format("the scene has {} patches, the fewest leaves a solve can have without "
                        "clustering (try --clustering oriented)",
                        patches));
    }
    const double start = m_passes.refining.epsilon;
    double x = std::log(start);
    for (int k = 0; k < m_budget.max_probes; ++k) {
        if (within(probe(x))) {
            const Pass frozen{m_accepted_epsilon, m_passes.frozen.rays};
            if (frozen.rays > 0) m_progress.stage("the mesh frozen");
            m_result.solution = freeze_pass(std::move(m_result.solution), frozen,
                                            std::move(m_shooting), m_progress, m_ranks);
            return std::move(m_result);
        }
        // The leaf count is a step function of epsilon: one decision flipping near the top of a
        // tree changes every ray's descent below it (and, through the noise, the rest of the
        // solve), so it can jump across the whole tolerance at one epsilon.
        if (m_lo && m_hi && *m_hi - *m_lo < 1e-6) {
            fail(fmt::format(
                "with seed {} the leaf count jumps from {} to {} between epsilon "
                "{:.8g} and {:.8g}; try another seed or a wider budget-tolerance",
                m_options.seed, m_lo_leaves, m_hi_leaves, std::exp(*m_lo), std::exp(*m_hi)));
        }
        // Ten decades below the start without reaching the target: limits or rays bind.
        if (!m_hi && *m_lo > std::log(start) + std::log(1e10)) break;
        if (!m_lo && *m_hi < std::log(start) - std::log(1e10)) {
            fail(
                fmt::format("even at epsilon {:.3g} the solve stops at {} leaves (limits: "
                            "min-area {} of the total area, max-depth {}; more rays or looser "
                            "limits may help)",
                            std::exp(*m_hi), m_hi_leaves, m_options.min_area, m_options.max_depth));
        }
        x = next_point();
    }
    fail(fmt::format("closest after {} probes: {} leaves at epsilon {:.4g}", m_result.probes.size(),
                     m_closest->leaves, m_closest->epsilon));
}

}  // namespace

BudgetResult solve_for_budget(const PatchMesh& mesh, const SolverOptions& options,
                              const BudgetOptions& budget, const SolveInputs& inputs,
                              Progress& progress, const Ranks& ranks, KnownProbes* known) {
    if (budget.leaves == 0) throw InputError("budget must be a positive leaf count");
    check_root_count(mesh.n_faces(), element_limit(options));
    return Search(mesh, options, budget, inputs, progress, ranks, known).run();
}

void validate(const BudgetOptions& budget) {
    if (!(budget.tolerance > 0 && budget.tolerance < 1)) {
        throw InputError(
            fmt::format("budget-tolerance must be in (0, 1), got {}", budget.tolerance));
    }
}

void to_json(nlohmann::json& j, const BudgetProbe& p) {
    j = {{"epsilon", p.epsilon}, {"leaves", p.leaves}, {"seconds", p.seconds}};
}

}  // namespace hmcr
