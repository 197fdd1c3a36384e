// SPDX-License-Identifier: Apache-2.0
// read_mgf: an interpreter of MGF statements (mgf_reader.h). Named contexts (colours,
// materials, vertices) are scratch spaces selected by c, m and v; geometry takes the current
// material and transformation when it is read. An xf with arrays, or an include with one, runs
// its statements once per instance, as the specification describes arrays.
#include "meshes/mgf_reader.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>

#include "meshes/mgf_color.h"
#include "meshes/mgf_color_fit.h"
#include "meshes/mgf_contexts.h"
#include "meshes/mgf_file.h"
#include "meshes/mgf_polygon_count.h"
#include "meshes/mgf_shapes.h"
#include "meshes/mgf_transform.h"
#include "meshes/validation.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

// Counts and first place of what a warning reports: the statements hmcr ignores, by entity, and
// the colours it fits to RGB.
struct Tally {
    std::map<std::string, std::pair<std::size_t, std::string>> by_entity;
    void add(const std::string& entity, const std::string& where) {
        auto& [count, first] = by_entity[entity];
        if (count++ == 0) first = where;
    }
};

// Throws InputError at `where` unless the statement has min to max arguments.
void need_arguments(const std::vector<std::string>& w, std::size_t min, std::size_t max,
                    const std::string& where) {
    const std::size_t n = w.size() - 1;
    if (n < min || n > max) {
        throw InputError(
            where, max == SIZE_MAX
                       ? fmt::format("'{}' needs at least {} arguments, found {}", w[0], min, n)
                       : fmt::format("'{}' needs {} to {} arguments, found {}", w[0], min, max, n));
    }
}

double parse_number(const std::string& token, const std::string& where) {
    double v = 0;
    const std::string_view t = token.front() == '+' ? std::string_view(token).substr(1) : token;
    const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc{} || ptr != t.data() + t.size() || !std::isfinite(v)) {
        throw InputError(where, fmt::format("bad number {}", quote(token)));
    }
    return v;
}

class MgfReader {
public:
    explicit MgfReader(const MgfOptions& options)
        : m_options(options),
          m_count(options.curve_segments,
                  [this](const MgfFile& from, const MgfStatement& i,
                         const std::string& where) -> const MgfFile& {
                      return load(include_path(from, i.words, where), where);
                  }) {}

    PolygonSoup read(const fs::path& top) {
        run_file(load(top, top.string()));
        finish_warnings();
        return std::move(m_soup);
    }

private:
    // ---- files, statements, transformations ----

    const MgfFile& load(const fs::path& path, const std::string& where) {
        const fs::path key = path.lexically_normal();
        if (auto it = m_files.find(key); it != m_files.end()) return *it->second;
        std::unique_ptr<MgfFile> file;
        try {
            file =
                std::make_unique<MgfFile>(read_mgf_file(key, std::uint32_t(m_soup.files.size())));
        } catch (const InputError& e) {
            if (m_soup.files.empty()) throw;
            throw InputError(where, fmt::format("include: {}", e.what()));
        }
        m_soup.files.push_back(key);
        return *m_files.emplace(key, std::move(file)).first->second;
    }

    void run_file(const MgfFile& file) {
        check_mgf_include(m_stack, file.path, m_where);
        m_stack.push_back(file.path);
        run_block(file, 0, file.statements.size());
        m_stack.pop_back();
    }

    void run_block(const MgfFile& file, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const MgfStatement& s = file.statements[i];
            m_at = {file.index, std::uint32_t(s.line)};
            m_where = at(file.path, s.line);
            count_step();
            if (s.words[0] == "xf") {
                const MgfXf xf = parse_mgf_xf(arguments(s.words, 1), m_where);
                const std::size_t close = file.xf_close[i];
                if (xf.instances() > 1) expect_polygons(m_count.block(file, i + 1, close), xf);
                run_transformed(xf, close == i + 1, [&] { run_block(file, i + 1, close); });
                i = close;
            } else {
                execute(s.words, file);
            }
        }
    }

    // Statements run and array instances both count: an array of 10^9 empty instances would
    // otherwise run for minutes without a statement to count.
    void count_step(std::uint64_t steps = 1) {
        if ((m_statements += steps) > m_options.max_statements) {
            throw InputError(m_where, fmt::format("more than {} statements to run (arrays and "
                                                  "includes expanded)",
                                                  m_options.max_statements));
        }
    }

    // Refuses an array whose instances, each making `per_instance` polygons, would make more
    // than the limit, before it makes any.
    void expect_polygons(std::uint64_t per_instance, const MgfXf& xf) const {
        const auto n = std::uint64_t(xf.instances());
        const std::uint64_t room = m_options.max_polygons - m_soup.polygon_count();
        if (per_instance == 0 || per_instance <= room / n) return;
        // The count saturates at 2^64 - 1 (mgf_polygon_count.h).
        std::string makes = "more than 2^64";
        if (per_instance <= UINT64_MAX / n) makes = fmt::format("{}", per_instance * n);
        if (per_instance < UINT64_MAX)
            makes += fmt::format(" ({} instances of {})", n, per_instance);
        throw InputError(m_where, fmt::format("more than {} polygons: the array makes {}",
                                              m_options.max_polygons, makes));
    }

    static std::vector<std::string_view> arguments(const std::vector<std::string>& w,
                                                   std::size_t from) {
        return {w.begin() + std::ptrdiff_t(from), w.end()};
    }

    // Runs `body` once per instance of the transformation, each inside the enclosing one and one
    // level deeper (the levels are limited: each is a few frames of the stack). The instances
    // of an empty body are only counted, all at once: each would cost a power of the
    // transformation and do nothing.
    template <typename Body>
    void run_transformed(const MgfXf& xf, bool empty_body, Body&& body) {
        if (empty_body) return count_step(std::uint64_t(xf.instances()));
        if (m_depth == m_options.max_nesting) {
            throw InputError(m_where,
                             fmt::format("transformations and includes nested more than {} deep",
                                         m_options.max_nesting));
        }
        ++m_depth;
        const MgfTransform enclosing = m_transform;
        for (long long k = 0; k < xf.instances(); ++k) {
            count_step();
            m_transform = enclosing * xf.instance(k);
            body();
        }
        m_transform = enclosing;
        --m_depth;
    }

    // The path of the file an include statement `w` of `from` names.
    static fs::path include_path(const MgfFile& from, const std::vector<std::string>& w,
                                 const std::string& where) {
        need_arguments(w, 1, SIZE_MAX, where);
        if (fs::path(w[1]).is_absolute()) {
            throw InputError(where, "include paths are relative to the including file");
        }
        return from.path.parent_path() / w[1];
    }

    void include(const std::vector<std::string>& w, const MgfFile& from) {
        const fs::path path = include_path(from, w, m_where);
        const MgfXf xf = parse_mgf_xf(arguments(w, 2), m_where);
        const MgfFile& file = load(path, m_where);
        if (xf.instances() > 1) expect_polygons(m_count.whole(file), xf);
        const std::string where = m_where;
        run_transformed(xf, file.statements.empty(), [&] {
            m_where = where;
            run_file(file);
        });
    }

    // ---- entities ----

    void execute(const std::vector<std::string>& w, const MgfFile& file) {
        const std::string& e = w[0];
        if (e == "i") return include(w, file);
        if (e == "o") return object(w);
        if (e == "c" || e == "cxy" || e == "cspec" || e == "cct" || e == "cmix") return color(w);
        if (e == "m" || e == "rd" || e == "ed" || e == "sides") return material(w);
        if (e == "rs") return specular(w);
        if (e == "v" || e == "p" || e == "n") return vertex(w);
        if (e == "ts" || e == "td" || e == "ir" || e == "ies") return m_ignored.add(e, m_where);
        if (e == "fh")
            throw InputError(m_where,
                             "fh (a face with holes) is not read: give the hole as a seam in an f");
        // Unknown entities are skipped with a warning, as the specification's own filter does
        // (later versions of MGF add entities).
        if (!geometry(w)) m_ignored.add(fmt::format("unknown entity {}", quote(e)), m_where);
    }

    void need(const std::vector<std::string>& w, std::size_t min, std::size_t max) const {
        need_arguments(w, min, max, m_where);
    }

    double number(const std::vector<std::string>& w, std::size_t i) const {
        return parse_number(w[i], m_where);
    }

    void object(const std::vector<std::string>& w) {
        need(w, 0, 1);
        if (w.size() == 2) {
            ++m_objects;
        } else if (m_objects-- == 0) {
            throw InputError(m_where, "o ends no object");
        }
    }

    void color(const std::vector<std::string>& w) {
        const std::string& e = w[0];
        if (e == "c") return m_colors.select(w, m_where, Chromaticity{});
        std::optional<Chromaticity> c;
        if (e == "cxy") {
            need(w, 2, 2);
            const double x = number(w, 1), y = number(w, 2);
            // The specification asks for x, y > 0; files in use have 0 (a colour of y = 0 has
            // no luminance to scale and is read as grey where it is used).
            if (!(x >= 0 && y >= 0 && x + y <= 1)) {
                throw InputError(m_where, "cxy: needs x, y >= 0 and x + y <= 1");
            }
            c = Chromaticity{x, y};
        } else if (e == "cspec") {
            need(w, 4, SIZE_MAX);
            std::vector<double> values;
            for (std::size_t i = 3; i < w.size(); ++i) values.push_back(number(w, i));
            c = spectrum_chromaticity(number(w, 1), number(w, 2), values);
        } else if (e == "cct") {
            need(w, 1, 1);
            const double kelvin = number(w, 1);
            if (!(kelvin > 0)) {
                throw InputError(
                    m_where,
                    fmt::format("cct: a temperature must be above 0 K, got {}", quote(w[1])));
            }
            c = blackbody_chromaticity(kelvin);
        } else {
            c = mix(w);
        }
        if (!c) throw InputError(m_where, fmt::format("{} gives no visible colour", e));
        m_colors.current() = *c;
    }

    std::optional<Chromaticity> mix(const std::vector<std::string>& w) {
        if (w.size() < 3 || w.size() % 2 == 0) {
            throw InputError(m_where, "cmix needs pairs of a weight and a colour name");
        }
        std::vector<std::pair<double, Chromaticity>> parts;
        for (std::size_t i = 1; i + 1 < w.size(); i += 2) {
            parts.emplace_back(number(w, i), m_colors.get(w[i + 1], m_where));
        }
        return mix_chromaticity(parts);
    }

    // RGB of the current colour at a luminance, each channel in [0, upper]: a colour outside
    // (outside the RGB gamut, or too bright to be a reflectance) is moved toward the grey of the
    // same luminance until it fits, keeping its luminance.
    Eigen::Vector3d rgb(double luminance, double upper) {
        const FittedColour f = fit_colour(m_colors.current(), luminance, upper);
        if (f.moved) m_fitted.add("colours", m_where);
        return f.rgb;
    }

    void material(const std::vector<std::string>& w) {
        const std::string& e = w[0];
        if (e == "m") {
            m_materials.select(w, m_where, MgfMaterial{});
            if (w.size() >= 3) {  // a new definition: a new soup material when used
                MgfMaterial& m = m_materials.current();
                m.name = w[1];
                m.kd_at = m.ed_at = m.ks_at = m_at;
                m.soup = -1;
            }
            return;
        }
        need(w, 1, 1);
        const double v = number(w, 1);
        MgfMaterial& m = m_materials.current();
        m.soup = -1;
        if (e == "sides") {
            if (v != 1 && v != 2) {
                throw InputError(m_where, fmt::format("sides {} is not 1 or 2", w[1]));
            }
            m.sides = int(v);
        } else if (!(v >= 0)) {
            throw InputError(m_where, fmt::format("{} {} is negative", e, w[1]));
        } else if (e == "rd") {
            if (v > 1) throw InputError(m_where, fmt::format("rd {} is above 1", w[1]));
            m.kd = rgb(v, std::max(v, kMaxColouredReflectance));
            m.rd = v;
            m.kd_at = m_at;
        } else {
            m.emitted = rgb(v, INFINITY);
            m.ed_at = m_at;
        }
    }

    // rs rho_s alpha: specular reflectance in the current colour and the RMS facet slope of its
    // Gaussian lobe, 0 for a mirror (docs/design.md §1.7).
    void specular(const std::vector<std::string>& w) {
        need(w, 2, 2);
        const double v = number(w, 1), roughness = number(w, 2);
        if (!(v >= 0 && v <= 1))
            throw InputError(m_where, fmt::format("rs {} is not in [0, 1]", w[1]));
        if (!(roughness >= 0 && roughness <= kMaxRoughness)) {
            throw InputError(m_where,
                             fmt::format("rs roughness {} is not in [0, {:g}] (0: a mirror)", w[2],
                                         kMaxRoughness));
        }
        MgfMaterial& m = m_materials.current();
        m.soup = -1;
        m.ks = rgb(v, std::max(v, kMaxColouredReflectance));
        m.rs = v;
        m.roughness = roughness;
        m.ks_at = m_at;
    }

    void vertex(const std::vector<std::string>& w) {
        if (w[0] == "v") return m_vertices.select(w, m_where, MgfVertex{});
        need(w, 3, 3);
        const Eigen::Vector3d value(number(w, 1), number(w, 2), number(w, 3));
        if (w[0] == "p") {
            m_vertices.current().p = value;
        } else {
            m_vertices.current().n =
                value.norm() > 0 ? value.normalized() : Eigen::Vector3d::Zero();
        }
    }

    // ---- geometry ----

    bool geometry(const std::vector<std::string>& w);
    void cone(const std::vector<std::string>& w, int segments);
    void ring_or_torus(const std::vector<std::string>& w, int segments);
    void prism(const std::vector<std::string>& w);
    void add(std::vector<MgfPolygon> polygons, bool reverse);
    std::int32_t soup_material();
    void fit_reflectances(const MgfMaterial& m, Material& out);
    void finish_warnings();

    MgfOptions m_options;
    MgfPolygonCount m_count;
    PolygonSoup m_soup;
    std::map<fs::path, std::unique_ptr<MgfFile>> m_files;
    std::vector<fs::path> m_stack;  // files being run, for cycles
    int m_depth = 0;                // transformations and includes around the statement run
    Contexts<Chromaticity> m_colors;
    Contexts<MgfMaterial> m_materials;
    Contexts<MgfVertex> m_vertices;
    MgfTransform m_transform = MgfTransform::Identity();
    std::uint64_t m_statements = 0;
    std::size_t m_objects = 0;
    SourcePlace m_at;
    std::string m_where;
    Tally m_ignored;  // statements and entities skipped
    Tally m_fitted;   // colours moved toward grey to fit RGB
};

// The polygons of one geometric entity, in the material and transformation in effect; false
// for an entity that is not one.
bool MgfReader::geometry(const std::vector<std::string>& w) {
    const std::string& e = w[0];
    const auto vertex = [&](std::size_t i) -> const MgfVertex& {
        return m_vertices.get(w[i], m_where);
    };
    const int segments = m_options.curve_segments;
    if (e == "f") {
        need(w, 3, SIZE_MAX);
        MgfPolygon face;
        for (std::size_t i = 1; i < w.size(); ++i) face.push_back(vertex(i).p);
        add({face}, false);
    } else if (e == "sph") {
        need(w, 2, 2);
        const double r = number(w, 2);
        if (r == 0) throw InputError(m_where, "sph: the radius is 0");
        add(tessellate_sphere(vertex(1).p, std::abs(r), segments), r < 0);
    } else if (e == "cyl" || e == "cone") {
        cone(w, segments);
    } else if (e == "ring" || e == "torus") {
        ring_or_torus(w, segments);
    } else if (e == "prism") {
        prism(w);
    } else {
        return false;
    }
    return true;
}

void MgfReader::cone(const std::vector<std::string>& w, int segments) {
    const bool cylinder = w[0] == "cyl";
    need(w, cylinder ? 3 : 4, cylinder ? 3 : 4);
    const Eigen::Vector3d a = m_vertices.get(w[1], m_where).p;
    const Eigen::Vector3d b = m_vertices.get(w[3], m_where).p;
    const double ra = number(w, 2), rb = cylinder ? ra : number(w, 4);
    if (a == b) throw InputError(m_where, fmt::format("{}: both ends are the same point", w[0]));
    if (ra * rb < 0 || (ra == 0 && rb == 0)) {
        throw InputError(m_where, fmt::format("{}: radii of opposite signs, or both 0", w[0]));
    }
    add(tessellate_cone(a, std::abs(ra), b, std::abs(rb), segments), ra < 0 || rb < 0);
}

void MgfReader::ring_or_torus(const std::vector<std::string>& w, int segments) {
    need(w, 3, 3);
    const MgfVertex& c = m_vertices.get(w[1], m_where);
    if (c.n.isZero())
        throw InputError(m_where, fmt::format("{}: vertex {} has no normal", w[0], quote(w[1])));
    const double rmin = number(w, 2), rmax = number(w, 3);
    if (w[0] == "ring") {
        if (!(rmin >= 0 && rmax > rmin)) throw InputError(m_where, "ring: needs 0 <= rmin < rmax");
        return add(tessellate_ring(c.p, c.n, rmin, rmax, segments), false);
    }
    if (rmin * rmax < 0 || !(std::abs(rmax) > std::abs(rmin))) {
        throw InputError(m_where, "torus: needs |rmin| < |rmax| and radii of one sign");
    }
    add(tessellate_torus(c.p, c.n, std::abs(rmin), std::abs(rmax), segments), rmax < 0);
}

void MgfReader::prism(const std::vector<std::string>& w) {
    need(w, 4, SIZE_MAX);
    MgfPolygon base;
    for (std::size_t i = 1; i + 1 < w.size(); ++i) base.push_back(m_vertices.get(w[i], m_where).p);
    const double length = number(w, w.size() - 1);
    if (length == 0) throw InputError(m_where, "prism: the length is 0");
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < base.size(); ++i)
        newell += base[i].cross(base[(i + 1) % base.size()]);
    if (!(newell.norm() > 0)) throw InputError(m_where, "prism: the base has no area");
    add(extrude_prism(base, length), false);
}

// Transforms the polygons, reverses them for an inward surface or a mirroring transformation,
// and adds them to the soup with the current material.
void MgfReader::add(std::vector<MgfPolygon> polygons, bool reverse) {
    if (m_soup.polygon_count() + polygons.size() > m_options.max_polygons) {
        throw InputError(m_where, fmt::format("more than {} polygons", m_options.max_polygons));
    }
    reverse = reverse != mirrors(m_transform);
    const std::int32_t material = soup_material();
    std::vector<std::uint32_t> ids;
    for (MgfPolygon& polygon : polygons) {
        if (reverse) std::reverse(polygon.begin(), polygon.end());
        ids.clear();
        for (const Eigen::Vector3d& p : polygon) {
            const Eigen::Vector3d q = m_transform * p;
            if (!q.allFinite()) {
                throw InputError(m_where, "a coordinate is not finite after the transformation");
            }
            ids.push_back(std::uint32_t(m_soup.positions.size()));
            m_soup.positions.push_back(q);
        }
        m_soup.add_polygon(ids, material, m_at);
    }
}

std::int32_t MgfReader::soup_material() {
    MgfMaterial& m = m_materials.current();
    if (m.soup >= 0) return m.soup;
    SoupMaterial out;
    out.material.name = m.name;
    out.material.kd = m.kd;
    out.material.ke = m.emitted / std::numbers::pi;  // E = pi Ke
    out.material.ks = m.ks;
    fit_reflectances(m, out.material);
    out.material.roughness = m.roughness;
    out.kd = m.kd_at;
    out.ke = m.ed_at;
    out.ks = m.ks_at;
    out.sides = m.sides;
    out.specular_reducible = true;
    m.soup = std::int32_t(m_soup.materials.size());
    m_soup.materials.push_back(std::move(out));
    return m.soup;
}

// MGF states rd and rs as luminances, and lets them sum to 1: two colours that fit alone can
// still sum above 1 in a channel (a saturated red rd under a white rs), and move together
// (meshes/mgf_color_fit.h).
void MgfReader::fit_reflectances(const MgfMaterial& m, Material& out) {
    const auto fitted = fit_sum(m.kd, m.rd, m.ks, m.rs);
    if (!fitted) return;
    out.kd = fitted->first;
    out.ks = fitted->second;
    m_fitted.add("colours", m_soup.where(m.ks_at));
}

void MgfReader::finish_warnings() {
    // Read, and changed: a warning of its own, not among the statements ignored.
    for (const auto& [what, seen] : m_fitted.by_entity) {
        m_soup.warnings.push_back(fmt::format(
            "{}: {} {} moved toward the grey of {} luminance to fit RGB (first at {})",
            m_soup.files.front().string(), seen.first, seen.first == 1 ? "colour" : "colours",
            seen.first == 1 ? "its" : "their", seen.second));
    }
    if (!m_ignored.by_entity.empty()) {
        std::string list;
        for (const auto& [entity, seen] : m_ignored.by_entity) {
            list += fmt::format("{}{} {} time{} (first at {})", list.empty() ? "" : ", ", entity,
                                seen.first, seen.first == 1 ? "" : "s", seen.second);
        }
        m_soup.warnings.push_back(
            fmt::format("{}: ignored (hmcr reads reflection rd and rs and emission ed): {}",
                        m_soup.files.front().string(), list));
    }
}

}  // namespace

PolygonSoup read_mgf(const fs::path& mgf, const MgfOptions& options) {
    return MgfReader(options).read(mgf);
}

}  // namespace hmcr
