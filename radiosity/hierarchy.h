// SPDX-License-Identifier: Apache-2.0
// The element hierarchy: one quadtree per patch, created lazily and safely from many threads.
#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <atomic>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "common/error.h"
#include "radiosity/element.h"
#include "radiosity/element_arena.h"
#include "radiosity/element_terms.h"
#include "rays/patch.h"

namespace hmcr {

struct HierarchyLimits {
    double min_area = 1e-6;  // relative to A_T; an element at or below it is never subdivided
    int max_depth = 16;      // a leaf at this depth is never subdivided (at most 24)
    std::uint64_t max_elements = std::uint64_t(-1);  // a subdivision beyond it is an error
};

// The hierarchy would grow beyond HierarchyLimits::max_elements: the user's limit, so an
// InputError (the message says how to raise or avoid it).
class ElementLimitReached : public InputError {
public:
    using InputError::InputError;
};

// The elements a hierarchy of `patches` holds before any subdivision: a root for every patch's
// front, and for every two-sided patch whose back emits.
std::size_t root_count(const PatchSet& patches);
// Throws ElementLimitReached when `roots` root elements alone pass `max_elements` (the user's
// --max-elements): no refinement could help, so the message says what to raise.
void check_root_count(std::size_t roots, std::uint64_t max_elements);

class Hierarchy {
public:
    // Throws ElementLimitReached when the roots alone pass limits.max_elements.
    Hierarchy(PatchSet patches, HierarchyLimits limits);

    const PatchSet& patch_set() const { return m_patches; }
    const Patch& patch(const Element& e) const { return m_patches.patches[e.id.patch]; }
    std::size_t patch_count() const { return m_patches.patches.size(); }
    // The unit normal out of the element's side, and that side's material.
    Vec3 normal(const Element& e) const { return side_normal(patch(e), e.id.side); }
    const PatchMaterial& material(const Element& e) const {
        return m_patches.material(e.id.patch, e.id.side);
    }
    // The root of a patch's front side.
    Element& root(std::size_t patch) { return m_roots[patch]; }
    const Element& root(std::size_t patch) const { return m_roots[patch]; }
    // The root of a side, made when first asked for (thread-safe): a two-sided patch's back
    // has elements only once light reaches it, or from the start if it emits.
    Element& root(std::size_t patch, std::uint8_t side) {
        if (side == kFront) return m_roots[patch];
        if (Element* r = m_back_roots[patch].load(std::memory_order_acquire)) return *r;
        return make_back_root(patch);
    }
    // The back side's root if it exists yet.
    const Element* back_root(std::size_t patch) const {
        return m_back_roots.empty() ? nullptr : m_back_roots[patch].load(std::memory_order_acquire);
    }
    // A side's root if it exists yet: looked for, never made.
    const Element* made_root(std::size_t patch, std::uint8_t side) const {
        return side == kFront ? &m_roots[patch] : back_root(patch);
    }

    bool can_subdivide(const Element& e) const {
        return e.area > m_min_area && e.id.depth < m_limits.max_depth;
    }
    // Splits every element larger than max_area (m^2) until none is, within max_depth, on both
    // sides of a two-sided patch: the fixed uniform mesh of a converged reference
    // (docs/design.md §6). Parallel over patches.
    void subdivide_uniformly(double max_area);
    // Splits every element that `shape` (a hierarchy of the same patches) has split: the same
    // leaves, for re-solving a mesh frozen (a study's mesh error). Parallel over patches.
    void subdivide_like(const Hierarchy& shape);
    // Every element back to what a new hierarchy split like this one holds: B and Delta B its
    // side's emission, nothing received. A frozen pass solves its refining pass's mesh again
    // in place, rather than in a copy (docs/design.md §3.10). Parallel over patches.
    void reset_values();
    // The four children of e, created if they do not exist yet (thread-safe). New children
    // inherit B and Delta B (constant basis) and start with nothing received. Throws
    // ElementLimitReached when they would make more than max_elements elements.
    Element* subdivide(Element& e);
    // The existing child of e that contains the parameter point uv.
    Element& child_containing(const Element& e, const Vec2& uv) const;
    // The leaf below e containing uv (existing elements only). A fixed mesh's rays ask a
    // LeafIndex, which finds the same leaf without reading the elements on the way.
    Element& locate(Element& e, const Vec2& uv) const;

    std::array<Vec3, 4> corners(const Element& e) const;

    // The polynomials B and Delta B are taken from on each element (docs/design.md §3.14).
    // Gives every element K - 1 slots for its coefficients beyond the mean, all zero but those
    // that children inherit; elements made later get theirs when made, each child its parent's
    // polynomial restricted to it. Call before the hierarchy is shared between threads. The
    // constant basis (the default) keeps no slots.
    void set_basis(Basis basis);
    Basis basis() const { return m_basis; }
    const PolynomialBasis& polynomial(const Element& e) const {
        return polynomial_basis(m_basis, patch(e).is_quad());
    }
    // e's slots of coefficients 1 .. K-1, or none on the constant basis.
    TermSlot* terms(const Element& e) const {
        return e.terms == TermStore::kNone ? nullptr : m_terms->at(e.terms);
    }
    // e's B or Delta B on its basis: row 0 the element's mean, rows 1 .. K-1 its slots.
    RgbCoefficients radiosity_coefficients(const Element& e) const;
    RgbCoefficients unshot_coefficients(const Element& e) const;
    // The quantum a ray's deposit toward a coefficient beyond the mean is counted in: the
    // iteration's times term_bound(basis), so that no sum of them can overflow.
    PowerQuantum term_quantum(const PowerQuantum& quantum) const {
        return {quantum.watts * m_term_bound};
    }

    // Pushes received radiosity (the power received, in `quantum`s, over the area) to the
    // leaves (Delta B = received, B += received), then pulls B and Delta B up as area-weighted
    // averages. Parallel over patches. On a higher basis the coefficients beyond the mean are
    // pushed too, each child taking its parent's polynomial restricted to it; an element with
    // children keeps only its mean up to date, since only a leaf shoots or is drawn.
    void push_pull(const PowerQuantum& quantum);
    // The same, each side's root starting with the radiosity from_above[2 * patch + side]
    // instead of 0: what its clusters received (docs/design.md §2.7).
    void push_pull(const PowerQuantum& quantum, std::span<const Rgb> from_above);
    // Total unshot power sum_l A_l Delta B_l (per channel).
    Rgb unshot_power() const;

    std::size_t element_count() const {
        return m_patches.patches.size() + m_back_count.load() + 4 * m_blocks.load();
    }
    std::size_t leaf_count() const { return element_count() - m_blocks.load(); }
    std::size_t bytes() const;
    // What an element takes: the Element and, on a higher basis, its coefficients' slots.
    std::size_t element_bytes() const {
        return sizeof(Element) +
               (m_terms ? std::size_t(m_terms->per_element()) * sizeof(TermSlot) : 0);
    }

    // Leaves in canonical order (the fronts patch by patch, then the backs that exist; child
    // index depth-first): the order of the output.
    template <class F>
    void for_each_leaf(F&& f) const {
        for (const Element& r : m_roots) visit_leaves(r, f);
        for (std::size_t p = 0; p < m_back_roots.size(); ++p) {
            if (const Element* r = back_root(p)) visit_leaves(*r, f);
        }
    }
    // The leaves of one side, in canonical order (a back only where it exists).
    template <class F>
    void for_each_leaf_of(std::uint8_t side, F&& f) const {
        if (side == kFront) {
            for (const Element& r : m_roots) visit_leaves(r, f);
            return;
        }
        for (std::size_t p = 0; p < m_back_roots.size(); ++p) {
            if (const Element* r = back_root(p)) visit_leaves(*r, f);
        }
    }
    bool has_backs() const { return m_back_count.load() > 0; }
    template <class F>
    static void visit_leaves(const Element& e, F&& f) {
        if (const Element* c = e.children()) {
            for (int k = 0; k < 4; ++k) visit_leaves(c[k], f);
        } else {
            f(e);
        }
    }

    // Every element, parents before children, in the roots' canonical order (the order ranks
    // share).
    template <class F>
    void for_each_element(F&& f) const {
        for (const Element& r : m_roots) visit_all(r, f);
        for (std::size_t p = 0; p < m_back_roots.size(); ++p) {
            if (const Element* r = back_root(p)) visit_all(*r, f);
        }
    }
    template <class F>
    void for_each_element(F&& f) {
        for (Element& r : m_roots) visit_all(r, f);
        for (std::size_t p = 0; p < m_back_roots.size(); ++p) {
            if (Element* r = m_back_roots[p].load(std::memory_order_acquire)) visit_all(*r, f);
        }
    }

private:
    template <class E, class F>
    static void visit_all(E& e, F&& f) {
        f(e);
        if (E* c = e.children()) {
            for (int k = 0; k < 4; ++k) visit_all(c[k], f);
        }
    }

    void init_child(Element& parent, int k, Element& child) const;
    void give_terms(Element& e);
    void init_root(std::size_t patch, std::uint8_t side, Element& root) const;
    Element& make_back_root(std::size_t patch);

    PatchSet m_patches;
    HierarchyLimits m_limits;
    double m_min_area = 0;  // absolute
    std::vector<Element> m_roots;
    // The back sides' roots, made when first needed (none when no patch has a back): the
    // atomic pointers are read without a lock; m_back_storage, which owns them, takes one.
    std::vector<std::atomic<Element*>> m_back_roots;
    std::deque<Element> m_back_storage;
    std::mutex m_back_mutex;
    std::atomic<std::size_t> m_back_count{0};
    mutable tbb::enumerable_thread_specific<ElementArena> m_arenas;
    std::atomic<std::size_t> m_blocks{0};
    Basis m_basis = Basis::constant;
    double m_term_bound = 1;
    std::unique_ptr<TermStore> m_terms;  // none on the constant basis
};

}  // namespace hmcr
