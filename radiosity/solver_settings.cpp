// SPDX-License-Identifier: Apache-2.0
#include "radiosity/solver_settings.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "common/error.h"
#include "common/memory.h"
#include "common/types.h"
#include "radiosity/element.h"
#include "radiosity/element_terms.h"

namespace hmcr {
namespace {

using nlohmann::json;

// A value as messages show it.
template <class T>
std::string shown(const T& value) {
    if constexpr (std::is_same_v<T, std::string>) {
        return quote(value);
    } else if constexpr (NamedSetting<T>) {
        if constexpr (std::is_pointer_v<T>) {
            if (value == nullptr) return "none";
        }
        return quote(SettingNames<T>::name(value));
    } else {
        return fmt::format("{}", value);
    }
}

// A bad value for a message, quoted (that is, cut short) once: a string as its text, anything
// else as JSON.
std::string got(const json& j) {
    return ", got " + quote(j.is_string() ? j.get<std::string>() : j.dump());
}

// The JSON value as T, or a one-line reason it is not one (a named setting's: set_value).
template <class T>
T json_value([[maybe_unused]] const Setting<T>& s, const json& j) {
    if constexpr (std::is_same_v<T, std::string>) {
        if (!j.is_string()) throw InputError("must be a string");
        return j.get<std::string>();
    } else if constexpr (std::is_floating_point_v<T>) {
        if (!j.is_number() || !std::isfinite(j.get<double>())) {
            throw InputError("must be a finite number" + got(j));
        }
        return j.get<T>();
    } else {
        // Whole numbers only: 2.5, 1e30 (a float to JSON) and -5 for a count are refused, not
        // rounded or wrapped.
        const bool whole =
            j.is_number_integer() && (j.is_number_unsigned() || j.get<std::int64_t>() >= 0 ||
                                      std::numeric_limits<T>::is_signed);
        if (!whole) throw InputError("must be a whole number in range" + got(j));
        if constexpr (std::is_signed_v<T>) {
            // An unsigned number beyond int64's range is out of every signed setting's.
            const std::uint64_t largest = std::numeric_limits<std::int64_t>::max();
            const auto v = j.is_number_unsigned()
                               ? std::int64_t(std::min(j.get<std::uint64_t>(), largest))
                               : j.get<std::int64_t>();
            if (v < std::numeric_limits<T>::min() || v > std::numeric_limits<T>::max()) {
                throw InputError("must be a whole number in range" + got(j));
            }
        }
        return j.get<T>();
    }
}

// "min-area must be in [0, 1), got 2".
[[noreturn]] void refuse(std::string_view setting, std::string_view range, std::string_view got) {
    std::string name(setting);
    std::replace(name.begin(), name.end(), '_', '-');
    throw InputError(fmt::format("{} must be {}, got {}", name, range, got));
}

template <class T>
void check(const Setting<T>& s, const T& value) {
    if constexpr (std::is_floating_point_v<T>) {
        if (is_subnormal(value)) {
            std::string name(s.name);
            std::replace(name.begin(), name.end(), '_', '-');
            throw InputError(fmt::format("{}: {} {}", name, value, kSubnormalReason));
        }
    }
    if (!s.valid(value)) refuse(s.name, s.range, shown(value));
}

// Sets `field` from the JSON value of setting `s`. A value of the wrong type is refused naming
// `type_place`, one out of range (or a name that is none) naming `value_place`; an empty place
// leaves the message as it is, the command line's own words ("stop must be in (0, 1), got 2").
template <class T>
void set_value(const Setting<T>& s, const json& j, const std::string& type_place,
               const std::string& value_place, T& field) {
    const auto fail = [](const std::string& place, const InputError& e) {
        if (place.empty()) throw e;
        throw InputError(place, e.what());
    };
    T value{};
    if constexpr (NamedSetting<T>) {
        if (!j.is_string()) fail(type_place, InputError("must be a string"));
        try {
            value = parse_named(s, j.get<std::string>());
        } catch (const InputError& e) {
            fail(value_place, e);
        }
    } else {
        try {
            value = json_value<T>(s, j);
        } catch (const InputError& e) {
            fail(type_place, e);
        }
    }
    try {
        check(s, value);
    } catch (const InputError& e) {
        fail(value_place, e);
    }
    field = value;
}

// Throws InputError at `place` ("" for none) for the first key of `values` not in `known`.
void refuse_unknown(const json& values, const std::set<std::string>& known,
                    const std::string& place) {
    for (const auto& [key, value] : values.items()) {
        if (known.count(key) > 0) continue;
        const std::string why =
            fmt::format("unknown setting {} (settings: {})", quote(key), fmt::join(known, ", "));
        if (place.empty()) throw InputError(why);
        throw InputError(place, why);
    }
}

}  // namespace

template <class T>
std::string Setting<T>::flag() const {
    std::string f = "--" + std::string(name);
    std::replace(f.begin(), f.end(), '_', '-');
    return f;
}
template struct Setting<OracleRef>;
template struct Setting<LinkWeight>;
template struct Setting<ControlVariate>;
template struct Setting<Clustering>;
template struct Setting<RaySequence>;
template struct Setting<Importance>;
template struct Setting<Bidirectional>;
template struct Setting<Basis>;
template struct Setting<double>;
template struct Setting<int>;
template struct Setting<std::uint64_t>;

template <NamedSetting T>
T parse_named(const Setting<T>& s, std::string_view text) {
    if (const std::optional<T> value = SettingNames<T>::parse(text)) return *value;
    refuse(s.name, s.range, quote(text));
}
template OracleRef parse_named(const Setting<OracleRef>&, std::string_view);
template LinkWeight parse_named(const Setting<LinkWeight>&, std::string_view);
template ControlVariate parse_named(const Setting<ControlVariate>&, std::string_view);
template Clustering parse_named(const Setting<Clustering>&, std::string_view);
template RaySequence parse_named(const Setting<RaySequence>&, std::string_view);
template Importance parse_named(const Setting<Importance>&, std::string_view);
template Bidirectional parse_named(const Setting<Bidirectional>&, std::string_view);
template Basis parse_named(const Setting<Basis>&, std::string_view);

const Oracle* default_oracle() { return oracle_registry().find("kl"); }

std::optional<OracleRef> SettingNames<OracleRef>::parse(std::string_view name) {
    if (const Oracle* o = oracle_registry().find(name)) return o;
    return std::nullopt;
}

std::uint64_t default_max_elements() {
    const std::uint64_t memory = physical_memory_bytes();
    return memory > 0 ? std::max<std::uint64_t>(1'000'000, memory / 4 / sizeof(Element))
                      : 10'000'000;
}

std::uint64_t element_limit(const SolverOptions& options) {
    if (options.basis == Basis::constant || options.max_elements != default_max_elements()) {
        return options.max_elements;
    }
    const double bytes =
        double(sizeof(Element) + std::size_t(basis_size(options.basis) - 1) * sizeof(TermSlot));
    return std::max<std::uint64_t>(
        1, std::uint64_t(double(options.max_elements) * double(sizeof(Element)) / bytes));
}

void validate(const SolverOptions& options) {
    for_each_setting([](const auto& setting, const auto& value) { check(setting, value); },
                     options);
}

void apply_scene_settings(const json& solver, const std::string& where, SolverOptions& options) {
    if (!solver.is_object()) throw InputError(where + ": solver", "must be a JSON object");
    std::set<std::string> known;
    for_each_setting(
        [&](const auto& setting, auto& field) {
            if (setting.scope != SettingScope::scene_file) return;
            known.emplace(setting.name);
            const std::string key(setting.name);
            if (!solver.contains(key)) return;
            const std::string place = fmt::format("{}: solver.{}", where, setting.name);
            set_value(setting, solver.at(key), place, place, field);
        },
        options);
    refuse_unknown(solver, known, where + ": solver");
}

void apply_settings(const json& values, SolverOptions& options) {
    std::set<std::string> known;
    for_each_setting(
        [&](const auto& setting, auto&) {
            if (setting.scope != SettingScope::internal) known.emplace(setting.name);
        },
        options);
    refuse_unknown(values, known, "");
    for_each_setting(
        [&](const auto& setting, auto& field) {
            const std::string key(setting.name);
            if (setting.scope == SettingScope::internal || !values.contains(key)) return;
            set_value(setting, values.at(key), key, "", field);
        },
        options);
}

json settings_json(const SolverOptions& options) {
    json j = json::object();
    for_each_setting(
        [&](const auto& setting, const auto& value) {
            using T = std::remove_cvref_t<decltype(value)>;
            if constexpr (NamedSetting<T>) {
                j[std::string(setting.name)] = std::string(SettingNames<T>::name(value));
            } else {
                j[std::string(setting.name)] = value;
            }
        },
        options);
    return j;
}

}  // namespace hmcr
