// SPDX-License-Identifier: Apache-2.0
#include "viz/paraview_collection.h"

#include <fmt/format.h>

#include "common/atomic_file.h"
#include "viz/paraview_state.h"

namespace hmcr {

std::string paraview_collection(const std::vector<CollectionEntry>& entries) {
    std::string out =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
    for (std::size_t k = 0; k < entries.size(); ++k) {
        out += fmt::format(R"(    <DataSet timestep="{}" part="0" file="{}" name="{}"/>)"
                           "\n",
                           k, xml_escape(entries[k].file.generic_string()),
                           xml_escape(entries[k].name));
    }
    return out + "  </Collection>\n</VTKFile>\n";
}

void write_paraview_collection(const std::filesystem::path& pvd,
                               const std::vector<CollectionEntry>& entries) {
    write_text_atomically(pvd, paraview_collection(entries));
}

}  // namespace hmcr
