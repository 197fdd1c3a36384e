// SPDX-License-Identifier: Apache-2.0
// Every setting of a solve, declared once. The list below generates SolverOptions; the command
// line's flags (app/), a scene file's "solver" keys and the run summary's "options" are all
// read off it, so a new setting is one line here plus its use in the engine.
//
// Columns: type, name (the field, the scene-file and summary key, and the flag --name with '-'
// for '_'), default, the condition on a value v, that condition in words, where it may be set,
// and the help text.
//   scene_file:   the command line and a scene file's "solver" object
//   command_line: the command line only (a property of the run, not of the scene)
//   internal:     set by hmcr itself (a reference's uniform mesh); shown in the summary
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "radiosity/basis.h"
#include "radiosity/oracle_registry.h"
#include "rays/sobol.h"

namespace hmcr {

enum class SettingScope { scene_file, command_line, internal };

// The refinement oracle of a solve, resolved from its name where the name is read.
using OracleRef = const Oracle*;
const Oracle* default_oracle();  // kl

// The weight w_ij of a link: the receiver's reflectance times the source's unshot radiosity
// (Delta B) or its total radiosity (B, RenderPark's), docs/design.md §4.4.
enum class LinkWeight { unshot, total };

// What the shooting subtracts from every surface's unshot radiosity and adds back exactly:
// nothing, or a constant per channel (docs/design.md §3.11).
enum class ControlVariate { none, constant };

// Clusters of patches above the patch roots, and how a cluster receives: none; as an isotropic
// cloud of surfaces, one irradiance over all its sides; or oriented, each ray's power to the
// sides that face it, by their projected area (docs/design.md §2.7).
enum class Clustering { none, isotropic, oriented };

// What weighs a refining solve's link values besides the oracle: nothing, or the receiver's
// importance for the scene's views (docs/design.md §3.12).
enum class Importance { none, views };

// Whether a line of a fixed mesh's pass also carries the unshot power of the leaf it lands on
// back to the leaf it left, each way weighted by the two leaves' shares (docs/design.md §3.13).
enum class Bidirectional { no, yes };

// An enumerated setting's names, in the order of its values.
template <class E>
struct EnumNames;
template <>
struct EnumNames<LinkWeight> {
    static constexpr std::array<std::string_view, 2> names{"unshot", "total"};
};
template <>
struct EnumNames<ControlVariate> {
    static constexpr std::array<std::string_view, 2> names{"none", "constant"};
};
template <>
struct EnumNames<Clustering> {
    static constexpr std::array<std::string_view, 3> names{"none", "isotropic", "oriented"};
};
template <>
struct EnumNames<RaySequence> {
    static constexpr std::array<std::string_view, 2> names{"random", "sobol"};
};
template <>
struct EnumNames<Importance> {
    static constexpr std::array<std::string_view, 2> names{"none", "views"};
};
template <>
struct EnumNames<Bidirectional> {
    static constexpr std::array<std::string_view, 2> names{"no", "yes"};
};
template <>
struct EnumNames<Basis> {
    static constexpr std::array<std::string_view, 5> names = kBasisNames;
};
template <class E>
concept NamedEnum = requires {
    EnumNames<E>::names;
};

// "total" for LinkWeight::total: how flags, scene files and summaries spell a value.
template <NamedEnum E>
std::string_view name(E value) {
    return EnumNames<E>::names[std::size_t(value)];
}

// Settings whose values are names (flags, scene files and summaries spell them): parse gives
// none for a name that is not one.
template <class T>
struct SettingNames;
template <>
struct SettingNames<OracleRef> {
    static std::optional<OracleRef> parse(std::string_view name);
    static std::string_view name(OracleRef oracle) { return oracle->name(); }
};
template <NamedEnum E>
struct SettingNames<E> {
    static std::optional<E> parse(std::string_view text) {
        const auto& names = EnumNames<E>::names;
        for (std::size_t k = 0; k < names.size(); ++k) {
            if (names[k] == text) return E(k);
        }
        return std::nullopt;
    }
    static std::string_view name(E value) { return hmcr::name(value); }
};
template <class T>
concept NamedSetting = requires(T v) {
    SettingNames<T>::name(v);
};

// clang-format off
#define HMCR_SOLVER_SETTINGS(X)                                                                   \
    X(OracleRef,     oracle,    default_oracle(), v != nullptr,      "one of " + oracle_registry().names(),  \
      scene_file, "refinement oracle (`hmcr oracles` lists them)")                                \
    X(double,        epsilon,   kOracleDefault, std::isnan(v) || v > 0, "positive",             \
      scene_file, "refinement threshold; a link is accepted when value / Phi_max < epsilon "     \
                  "(default: the oracle's)")                                                     \
    X(int,           lines,     10,         v >= 1 && v <= 4096,     "in 1..4096",                \
      scene_file, "kernel lines per link, N_s, for the line-based oracles")                      \
    X(std::uint64_t, rays,      2'684'000,  v >= 1 && v <= kMaxRays, "in 1..1e15",                \
      scene_file, "shooting rays over the whole solve (shot within 2%)")                         \
    X(std::uint64_t, seed,      1,          true,                    "a count",                   \
      scene_file, "keys every random stream")                                                    \
    X(int,           threads,   0,          v >= 0 && v <= 4096,     "0 (all cores) to 4096",     \
      command_line, "worker threads, 0 = all cores; results do not depend on it")                \
    X(double,        min_area,  1e-6,       v >= 0 && v < 1,         "in [0, 1)",                 \
      scene_file, "elements at or below this area, relative to the total, are not split")        \
    X(int,           max_depth, 16,         v >= 0 && v <= 24,       "in 0..24",                  \
      scene_file, "quadtree depth limit")                                                        \
    X(LinkWeight,    link_weight, LinkWeight::unshot, true,           "unshot or total",            \
      scene_file, "a link's weight w_ij: the receiver's reflectance times the source's unshot "  \
                  "(Delta B) or total (B) radiosity")                                           \
    X(ControlVariate, control_variate, ControlVariate::none, true,  "none or constant",          \
      scene_file, "on a fixed mesh, shoot the unshot radiosity minus a constant per channel and "\
                  "add the constant's share exactly (none: shoot it all)")                       \
    X(Clustering,    clustering, Clustering::none, true,   "none, isotropic or oriented",        \
      scene_file, "clusters of patches above the patch roots, each receiving as an isotropic "   \
                  "cloud of surfaces or, oriented, by its sides' projected areas toward the ray "\
                  "(none: the hierarchy starts at the patches)")                                 \
    X(RaySequence,   sequence,  RaySequence::sobol, true,            "random or sobol",           \
      scene_file, "where the shooting rays' sources and uniforms come from: keyed pseudo-random "\
                  "streams, each ray picking its source leaf (random); or the rays dealt to the "\
                  "source leaves by their power, each leaf's from its own Owen-scrambled Sobol " \
                  "sequence (sobol)")                                                            \
    X(Bidirectional, bidirectional, Bidirectional::no, true,         "no or yes",                 \
      scene_file, "on a fixed mesh (the frozen pass, a reference's mesh), each line that lands " \
                  "also carries the unshot power of the leaf it lands on back to the leaf it "   \
                  "left, both ways weighted by the two leaves' unshot radiosity (no: one way)")  \
    X(Basis,         basis,     Basis::constant, true,  "constant, linear, bilinear, quadratic or cubic", \
      scene_file, "the polynomials each element's radiosity is taken from, orthonormal on its "  \
                  "square or triangle: 1, 3, 4, 6 or 10 functions; the oracles decide on the "   \
                  "mean (constant: one value per element)")                                     \
    X(double,        refine_share, 0.1,     v > 0 && v <= 1,         "in (0, 1]",                 \
      scene_file, "share of the rays that refine the mesh; the rest solve its leaves again, "    \
                  "frozen, from scratch (1: one refined solve)")                                 \
    X(Importance,    importance, Importance::none, true,             "none or views",             \
      scene_file, "views: weigh a refining solve's link values by the receiver's importance "    \
                  "for the scene's views, so that elements go where they look (none: do not)")  \
    X(double,        stop,      0.01,       v > 0 && v < 1,          "in (0, 1)",                 \
      scene_file, "stop when the unshot power is below stop x the emitted power")                \
    X(double,        cache_mb,  32,         v >= 0 && v <= 1 << 20,  "in [0, 1048576]",           \
      command_line, "link cache for the line-based oracles, MiB (0: none); results do not "      \
                    "depend on it")                                                              \
    X(std::uint64_t, max_elements, default_max_elements(), v >= 1,   "at least 1",                \
      command_line, "refuse to grow the element hierarchy beyond this (default: a quarter of "   \
                    "this machine's memory)")                                                    \
    X(double, uniform_max_area, 0,          v >= 0,                  "not negative",              \
      internal,   "> 0: a fixed uniform mesh of elements no larger (m^2), no oracle")
// clang-format on

// About what a thousand machines shoot in a day (10^7 rays/s each): beyond it, a typo.
inline constexpr std::uint64_t kMaxRays = 1'000'000'000'000'000;

// Elements in a quarter of this machine's memory.
std::uint64_t default_max_elements();

// epsilon's default: the oracle's own (Oracle::default_epsilon), which a solve resolves when it
// derives its passes (passes_of, radiosity/solve_passes.h).
inline constexpr double kOracleDefault = std::numeric_limits<double>::quiet_NaN();

struct SolverOptions {
#define HMCR_FIELD(type, name, default_value, ...) type name = default_value;
    HMCR_SOLVER_SETTINGS(HMCR_FIELD)
#undef HMCR_FIELD
};

// Whether a solve's mesh is fixed from its start: the uniform mesh of uniform_max_area, or the
// patches themselves where nothing may split (max_depth 0 and no clusters to open). Such a solve
// has nothing to refine, so all its rays solve that mesh as a frozen pass does, lines used both
// ways and the control variate included (docs/design.md §3.10).
inline bool fixed_from_start(const SolverOptions& o) {
    return o.uniform_max_area > 0 || (o.max_depth == 0 && o.clustering == Clustering::none);
}

// The elements a solve may make: its max_elements, or with the default limit on a higher basis
// the elements a quarter of the memory holds with their coefficients (docs/design.md §2.6), so
// that the default bounds the memory on every basis.
std::uint64_t element_limit(const SolverOptions& options);

}  // namespace hmcr
