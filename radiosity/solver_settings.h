// SPDX-License-Identifier: Apache-2.0
// The settings table of solver_options.h as data: what the command line, scene files and run
// summaries walk, so that none of them names a setting itself.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

#include "radiosity/solver_options.h"

namespace hmcr {

template <class T>
struct Setting {
    std::string_view name;  // the field; the key in scene files and summaries
    SettingScope scope;
    std::string_view help;
    std::string range;  // the condition on a value, in words
    T default_value;
    bool (*valid)(const T& value);

    std::string flag() const;  // "--min-area" for min_area
};

// Calls f(setting, options.field...) for every setting in table order, passing the setting's
// field of each options object given (none, one, or several to compare or merge).
template <class F, class... Options>
void for_each_setting(F&& f, Options&... options) {
#define HMCR_VISIT(type, name, default_value, condition, range, scope, help)         \
    f(Setting<type>{#name, SettingScope::scope, help, range, default_value,          \
                    []([[maybe_unused]] const type& v) { return bool(condition); }}, \
      options.name...);
    HMCR_SOLVER_SETTINGS(HMCR_VISIT)
#undef HMCR_VISIT
}

// The value a name stands for; throws InputError "NAME must be RANGE, got 'TEXT'" for a name
// that is none (a flag's or a scene file's text).
template <NamedSetting T>
T parse_named(const Setting<T>& setting, std::string_view text);

// Throws InputError "NAME must be RANGE, got VALUE" for the first setting out of range.
void validate(const SolverOptions& options);

// Applies a scene file's "solver" object: every key must be a scene-file setting, every value
// of its type and in range, whatever the command line later overrides. Errors name the place:
// "WHERE: solver.KEY: why".
void apply_scene_settings(const nlohmann::json& solver, const std::string& where,
                          SolverOptions& options);

// Applies settings by name, every user's setting (command-line ones too): a program's keywords (the
// Python module's). A bad value gets the command line's message, "NAME must be RANGE, got VALUE"; a
// value of the wrong type "KEY: why"; an unknown name lists the settings.
void apply_settings(const nlohmann::json& values, SolverOptions& options);

// Every setting by name: the run summary's "options".
nlohmann::json settings_json(const SolverOptions& options);

}  // namespace hmcr
