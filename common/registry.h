// SPDX-License-Identifier: Apache-2.0
// A registry of plug-ins by name: the refinement oracles (radiosity/oracle_registry.h) and the
// pixel criteria (trace/criteria/registry.h) are each one. A name is resolved once, where it is
// read (a flag, a scene file; find_named of common/error.h), and from there on the code holds the
// plug-in itself.
#pragma once

#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hmcr {

// An ordered list of plug-ins (each with name()), built from one list of makers.
template <class Plugin>
class Registry {
public:
    using Maker = std::unique_ptr<Plugin> (*)();

    // `kind` names the plug-ins in messages ("oracle").
    Registry(std::string_view kind, std::initializer_list<Maker> makers) : m_kind(kind) {
        for (const Maker make : makers) m_owned.push_back(make());
        for (const auto& p : m_owned) m_all.push_back(p.get());
    }

    // Every plug-in, in the order the list gives them (the order `hmcr oracles` prints).
    const std::vector<const Plugin*>& all() const { return m_all; }

    // The plug-in called name, or none.
    const Plugin* find(std::string_view name) const {
        for (const Plugin* p : m_all) {
            if (p->name() == name) return p;
        }
        return nullptr;
    }

    // "power, ks, ...": every name, for messages.
    std::string names() const {
        std::string out;
        for (const Plugin* p : m_all) {
            if (!out.empty()) out += ", ";
            out += p->name();
        }
        return out;
    }

    // What the plug-ins are, for messages: "oracle".
    const std::string& kind() const { return m_kind; }

private:
    std::string m_kind;
    std::vector<std::unique_ptr<Plugin>> m_owned;
    std::vector<const Plugin*> m_all;
};

}  // namespace hmcr
