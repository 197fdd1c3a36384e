// SPDX-License-Identifier: Apache-2.0
#include "app/solver_flags.h"

#include <cmath>

#include "app/count.h"
#include "radiosity/solver_settings.h"

namespace hmcr {
namespace {

template <class T>
CLI::Option* add_flag(CLI::App& command, const Setting<T>& s, T& field) {
    if constexpr (NamedSetting<T>) {  // resolved here, where the name is read
        return command
            .add_option_function<std::string>(
                s.flag(), [s, &field](const std::string& text) { field = parse_named(s, text); },
                std::string(s.help))
            ->default_str(std::string(SettingNames<T>::name(field)));
    } else {
        CLI::Option* option = command.add_option(s.flag(), field, std::string(s.help));
        if constexpr (std::is_same_v<T, std::uint64_t>) option->transform(count_notation());
        // (a real's text is checked to be finite for every command: app/count.h)
        if constexpr (std::is_floating_point_v<T>) {
            if (std::isnan(field)) return option;  // "the oracle's": the help says so
        }
        return option->capture_default_str();
    }
}

}  // namespace

SolverFlags add_solver_flags(CLI::App& command, SolverOptions& options,
                             const std::set<std::string>& except,
                             const std::set<std::string>& not_from_scene) {
    SolverFlags flags{&command, {}, {}};
    for_each_setting(
        [&](const auto& setting, auto& field) {
            const std::string name(setting.name);
            if (setting.scope == SettingScope::internal || except.count(name)) return;
            add_flag(command, setting, field);
            flags.names.insert(name);
            if (!not_from_scene.count(name)) flags.from_scene.insert(name);
        },
        options);
    return flags;
}

void apply_scene_settings(const SolverFlags& flags, const Scene& scene, SolverOptions& options) {
    SolverOptions from_scene = options;
    apply_scene_settings(scene.solver_defaults, scene.source.string(), from_scene);
    for_each_setting(
        [&](const auto& setting, auto& field, const auto& scene_value) {
            const std::string name(setting.name);
            if (flags.from_scene.count(name) && flags.command->count(setting.flag()) == 0) {
                field = scene_value;
            }
        },
        options, from_scene);
    validate(options);
}

}  // namespace hmcr
