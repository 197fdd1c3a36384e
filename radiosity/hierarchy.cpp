// SPDX-License-Identifier: Apache-2.0
#include "radiosity/hierarchy.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>

#include "common/memory.h"

namespace hmcr {

std::size_t root_count(const PatchSet& patches) {
    std::size_t roots = patches.patches.size();
    if (patches.back_materials.empty()) return roots;
    for (std::size_t i = 0; i < patches.patches.size(); ++i) {
        if (patches.two_sided(i) && (patches.material(i, kBack).emission > 0).any()) ++roots;
    }
    return roots;
}

void check_root_count(std::size_t roots, std::uint64_t max_elements) {
    if (roots <= max_elements) return;
    throw ElementLimitReached(fmt::format(
        "the scene's patches alone are {} elements, more than --max-elements {}: raise it to at "
        "least {} (about {} of memory)",
        roots, max_elements, roots, human_bytes(double(roots) * sizeof(Element))));
}

namespace {

// `patches`, once their roots are known to fit: the check comes before the roots' memory.
PatchSet with_roots_within(PatchSet patches, std::uint64_t max_elements) {
    check_root_count(root_count(patches), max_elements);
    return patches;
}

}  // namespace

Hierarchy::Hierarchy(PatchSet patches, HierarchyLimits limits)
    : m_patches(with_roots_within(std::move(patches), limits.max_elements)),
      m_limits(limits),
      m_roots(m_patches.patches.size()) {
    if (m_limits.max_depth < 0 || m_limits.max_depth > 24) {
        throw std::invalid_argument("max depth must be between 0 and 24");
    }
    m_min_area = m_limits.min_area * m_patches.total_area;
    for (std::size_t i = 0; i < m_roots.size(); ++i) init_root(i, kFront, m_roots[i]);
    if (m_patches.back_materials.empty()) return;
    m_back_roots = std::vector<std::atomic<Element*>>(m_roots.size());
    // A back that emits is a source from the first iteration.
    for (std::size_t i = 0; i < m_roots.size(); ++i) {
        if (m_patches.two_sided(i) && (m_patches.material(i, kBack).emission > 0).any()) {
            make_back_root(i);
        }
    }
}

void Hierarchy::init_root(std::size_t patch, std::uint8_t side, Element& r) const {
    const Patch& p = m_patches.patches[patch];
    r.id = {std::uint32_t(patch), 0, side, 0};
    r.area = p.area;
    r.centre = p.point(r.domain.centre(p.is_quad()));
    r.radiosity = r.unshot = m_patches.material(patch, side).emission;
}

Element& Hierarchy::make_back_root(std::size_t patch) {
    if (!m_patches.two_sided(patch)) {
        throw std::logic_error("the back of one-sided patch " + std::to_string(patch));
    }
    const std::lock_guard lock(m_back_mutex);
    if (Element* r = m_back_roots[patch].load(std::memory_order_acquire)) return *r;
    Element& r = m_back_storage.emplace_back();
    init_root(patch, kBack, r);
    if (m_terms) give_terms(r);
    m_back_count.fetch_add(1, std::memory_order_relaxed);
    m_back_roots[patch].store(&r, std::memory_order_release);
    return r;
}

void Hierarchy::init_child(Element& parent, int k, Element& child) const {
    const Patch& p = patch(parent);
    child.id = parent.id.child(k);
    child.domain = parent.domain.child(p.is_quad(), k);
    const auto uv = child.domain.corners(p.is_quad());
    child.area = p.region_area(uv.data(), p.corner_count);
    child.centre = p.point(child.domain.centre(p.is_quad()));
    child.radiosity = parent.radiosity;
    child.unshot = parent.unshot;
    child.received = {};
    child.first_child.store(nullptr, std::memory_order_relaxed);
    if (terms(parent)) {
        // The parent's polynomial restricted to the child, its mean included.
        const PolynomialBasis& basis = polynomial(parent);
        const RgbCoefficients b = basis.transform(k).transpose() * radiosity_coefficients(parent);
        const RgbCoefficients db = basis.transform(k).transpose() * unshot_coefficients(parent);
        TermSlot* to = terms(child);
        child.radiosity = b.row(0).transpose().array();
        child.unshot = db.row(0).transpose().array();
        for (int j = 1; j < basis.size(); ++j) {
            to[j - 1] = {b.row(j).transpose().array(), db.row(j).transpose().array(), {}};
        }
    }
}

void Hierarchy::give_terms(Element& e) {
    if (e.terms != TermStore::kNone) return;
    e.terms = m_terms->allocate(1);
}

void Hierarchy::set_basis(Basis basis) {
    if (basis == m_basis) return;
    if (m_terms || basis_size(basis) == 1) {
        throw std::logic_error("a hierarchy's basis is set once, to a higher one");
    }
    m_basis = basis;
    // A deposit toward a term is at most bound_k Jbar / J times the ray's (shooting.cpp): on a
    // quad that is no parallelogram J is affine in (u, v), so Jbar / J is below its largest
    // corner value over its smallest.
    double stretch = 1;
    for (const Patch& p : m_patches.patches) {
        if (!p.is_quad() || p.is_parallelogram()) continue;
        double lo = p.jacobian({0, 0}), hi = lo;
        for (const Vec2& uv : {Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}) {
            lo = std::min(lo, p.jacobian(uv));
            hi = std::max(hi, p.jacobian(uv));
        }
        if (lo > 0) stretch = std::max(stretch, hi / lo);
    }
    m_term_bound = term_bound(basis) * stretch;
    m_terms = std::make_unique<TermStore>(basis_size(basis) - 1);
    for_each_element([this](Element& e) { give_terms(e); });
}

namespace {

RgbCoefficients coefficients(const Element& e, const TermSlot* t, int size, bool unshot) {
    RgbCoefficients c(size, 3);
    c.row(0) = (unshot ? e.unshot : e.radiosity).matrix().transpose();
    for (int k = 1; k < size; ++k) {
        c.row(k) = (unshot ? t[k - 1].unshot : t[k - 1].radiosity).matrix().transpose();
    }
    return c;
}

}  // namespace

RgbCoefficients Hierarchy::radiosity_coefficients(const Element& e) const {
    return coefficients(e, terms(e), basis_size(m_basis), false);
}

RgbCoefficients Hierarchy::unshot_coefficients(const Element& e) const {
    return coefficients(e, terms(e), basis_size(m_basis), true);
}

Element* Hierarchy::subdivide(Element& e) {
    if (Element* c = e.children()) return c;
    if (element_count() + 4 > m_limits.max_elements) {
        throw ElementLimitReached(fmt::format(
            "the element hierarchy would grow beyond --max-elements {} (about {} of memory); "
            "raise it, or refine less (a larger epsilon, --min-area or a smaller --max-depth)",
            m_limits.max_elements, human_bytes(double(m_limits.max_elements) * element_bytes())));
    }
    ElementArena& arena = m_arenas.local();
    Element* block = arena.allocate_block();
    const std::uint32_t first = m_terms ? m_terms->allocate(4) : TermStore::kNone;
    for (int k = 0; k < 4; ++k) {
        block[k].terms =
            m_terms ? first + std::uint32_t(k * m_terms->per_element()) : TermStore::kNone;
        init_child(e, k, block[k]);
    }
    Element* expected = nullptr;
    if (e.first_child.compare_exchange_strong(expected, block, std::memory_order_acq_rel)) {
        m_blocks.fetch_add(1, std::memory_order_relaxed);
        return block;
    }
    arena.give_back(block);  // another thread subdivided e first: its children are identical
    return expected;
}

void Hierarchy::subdivide_uniformly(double max_area) {
    auto split = [&](auto& self, Element& e) -> void {
        if (e.area <= max_area || e.id.depth >= m_limits.max_depth) return;
        Element* c = subdivide(e);
        for (int k = 0; k < 4; ++k) self(self, c[k]);
    };
    // Both sides of a two-sided patch: a reference has the whole scene's elements.
    tbb::parallel_for(std::size_t(0), m_roots.size(), [&](std::size_t i) {
        split(split, m_roots[i]);
        if (m_patches.two_sided(i)) split(split, root(i, kBack));
    });
}

void Hierarchy::subdivide_like(const Hierarchy& shape) {
    if (shape.patch_count() != patch_count()) {
        throw std::invalid_argument("subdivide_like: another scene's hierarchy");
    }
    auto split = [&](auto& self, Element& e, const Element& model) -> void {
        const Element* m = model.children();
        if (!m) return;
        Element* c = subdivide(e);
        for (int k = 0; k < 4; ++k) self(self, c[k], m[k]);
    };
    tbb::parallel_for(std::size_t(0), m_roots.size(), [&](std::size_t i) {
        split(split, m_roots[i], shape.m_roots[i]);
        if (const Element* back = shape.back_root(i)) split(split, root(i, kBack), *back);
    });
}

void Hierarchy::reset_values() {
    const auto reset = [this](Element& e) {
        e.radiosity = e.unshot = material(e).emission;
        e.received = {};
        if (TermSlot* t = terms(e)) std::fill_n(t, m_terms->per_element(), TermSlot{});
    };
    tbb::parallel_for(std::size_t(0), m_roots.size(), [&](std::size_t i) {
        visit_all(m_roots[i], reset);
        if (m_back_roots.empty()) return;
        if (Element* back = m_back_roots[i].load(std::memory_order_acquire))
            visit_all(*back, reset);
    });
}

Element& Hierarchy::child_containing(const Element& e, const Vec2& uv) const {
    const int k = e.domain.child_containing(patch(e).is_quad(), uv);
    return e.children()[k];
}

Element& Hierarchy::locate(Element& e, const Vec2& uv) const {
    Element* cur = &e;
    while (!cur->is_leaf()) cur = &child_containing(*cur, uv);
    return *cur;
}

std::array<Vec3, 4> Hierarchy::corners(const Element& e) const {
    const Patch& p = patch(e);
    const auto uv = e.domain.corners(p.is_quad());
    std::array<Vec3, 4> out;
    for (int k = 0; k < 4; ++k) out[k] = p.point(uv[k]);
    return out;
}

namespace {

void push_pull_element(Element& e, const Rgb& from_above, const PowerQuantum& quantum) {
    const Rgb acc = from_above + quantum.power(e.received) / e.area;
    e.received = {};
    Element* c = e.children();
    if (!c) {
        e.unshot = acc;
        e.radiosity += acc;
        return;
    }
    Rgb b = Rgb::Zero(), db = Rgb::Zero();
    double area = 0;
    for (int k = 0; k < 4; ++k) {
        push_pull_element(c[k], acc, quantum);
        b += c[k].area * c[k].radiosity;
        db += c[k].area * c[k].unshot;
        area += c[k].area;
    }
    e.radiosity = b / area;
    e.unshot = db / area;
}

// The same on a higher basis: `from_above` and what e received are polynomials on e's basis;
// each child takes their restriction to it.
void push_pull_terms(const Hierarchy& h, Element& e, const RgbCoefficients& from_above,
                     const PowerQuantum& quantum, const PowerQuantum& term_quantum) {
    const PolynomialBasis& basis = h.polynomial(e);
    TermSlot* t = h.terms(e);
    RgbCoefficients acc = from_above;
    acc.row(0) += (quantum.power(e.received) / e.area).matrix().transpose();
    e.received = {};
    for (int k = 1; k < basis.size(); ++k) {
        acc.row(k) += (term_quantum.power(t[k - 1].received) / e.area).matrix().transpose();
        t[k - 1].received = {};
    }
    Element* c = e.children();
    if (!c) {
        e.unshot = acc.row(0).transpose().array();
        e.radiosity += e.unshot;
        for (int k = 1; k < basis.size(); ++k) {
            t[k - 1].unshot = acc.row(k).transpose().array();
            t[k - 1].radiosity += t[k - 1].unshot;
        }
        return;
    }
    Rgb b = Rgb::Zero(), db = Rgb::Zero();
    double area = 0;
    for (int k = 0; k < 4; ++k) {
        push_pull_terms(h, c[k], basis.transform(k).transpose() * acc, quantum, term_quantum);
        b += c[k].area * c[k].radiosity;
        db += c[k].area * c[k].unshot;
        area += c[k].area;
    }
    e.radiosity = b / area;
    e.unshot = db / area;
}

}  // namespace

void Hierarchy::push_pull(const PowerQuantum& quantum) { push_pull(quantum, {}); }

void Hierarchy::push_pull(const PowerQuantum& quantum, std::span<const Rgb> from_above) {
    const auto above = [&](std::size_t side_value) -> Rgb {
        return from_above.empty() ? Rgb::Zero() : from_above[side_value];
    };
    const PowerQuantum term = term_quantum(quantum);
    const int size = basis_size(m_basis);
    const auto one = [&](Element& root, const Rgb& from) {
        if (!m_terms) {
            push_pull_element(root, from, quantum);
            return;
        }
        RgbCoefficients c = RgbCoefficients::Zero(size, 3);
        c.row(0) = from.matrix().transpose();
        push_pull_terms(*this, root, c, quantum, term);
    };
    tbb::parallel_for(std::size_t(0), m_roots.size(), [&](std::size_t i) {
        one(m_roots[i], above(2 * i));
        if (m_back_roots.empty()) return;
        if (Element* r = m_back_roots[i].load(std::memory_order_acquire)) one(*r, above(2 * i + 1));
    });
}

Rgb Hierarchy::unshot_power() const {
    Rgb sum = Rgb::Zero();
    for (const Element& r : m_roots) sum += r.area * r.unshot;
    for (std::size_t p = 0; p < m_back_roots.size(); ++p) {
        if (const Element* r = back_root(p)) sum += r->area * r->unshot;
    }
    return sum;
}

std::size_t Hierarchy::bytes() const {
    std::size_t b = (m_roots.size() + m_back_count.load()) * sizeof(Element) +
                    m_back_roots.size() * sizeof(std::atomic<Element*>);
    for (const ElementArena& a : m_arenas) b += a.bytes();
    if (m_terms) b += m_terms->bytes();
    return b;
}

}  // namespace hmcr
