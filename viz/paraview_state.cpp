// SPDX-License-Identifier: Apache-2.0
// The .pvsm writer (paraview_state.h). The layout of the file is ParaView's own: proxies with
// ids and properties, then proxy collections that name them; ids here are fixed.
#include "viz/paraview_state.h"

#include <fmt/format.h>

#include "common/atomic_file.h"

namespace hmcr {
namespace {

constexpr int kView = 4, kLayout = 5;
// Source k is reader kFirstReader + 2k, shown by representation kFirstReader + 2k + 1.
constexpr int kFirstReader = 10;
int reader_id(std::size_t k) { return kFirstReader + 2 * int(k); }
int representation_id(std::size_t k) { return reader_id(k) + 1; }

// One property with its elements, as ParaView writes it.
template <typename... Values>
std::string property(int proxy, const char* name, const Values&... values) {
    std::string elements;
    int index = 0;
    ((elements += fmt::format(R"(<Element index="{}" value="{}"/>)", index++, values)), ...);
    return fmt::format(
        R"(      <Property name="{}" id="{}.{}" number_of_elements="{}">{}</Property>)"
        "\n",
        name, proxy, name, index, elements);
}

std::string vector3(int proxy, const char* name, const Eigen::Vector3d& v) {
    return property(proxy, name, v.x(), v.y(), v.z());
}

std::string reader(const StateSource& source, int id) {
    const std::string file =
        xml_escape(std::filesystem::absolute(source.vtp).lexically_normal().string());
    return fmt::format(R"(    <Proxy group="sources" type="XMLPolyDataReader" id="{}" servers="1">)"
                       "\n{}    </Proxy>\n",
                       id, property(id, "FileName", file));
}

// RadiosityColor as it is (MapScalars 0), interpolated, and unlit: the ambient term alone,
// at full strength, shows a colour exactly. With two-sided patches, back faces are culled
// (401, "Cull Backface"): a patch's two sides are coincident polygons facing away from each
// other, and each viewer then sees the side that faces it.
std::string representation(int r, int input, bool visible, bool cull_backfaces) {
    return fmt::format(
        R"(    <Proxy group="representations" type="GeometryRepresentation" id="{}" servers="21">)"
        "\n"
        R"(      <Property name="Input" id="{}.Input" number_of_elements="1"><Proxy value="{}" output_port="0"/></Property>)"
        "\n{}{}{}{}{}{}{}{}{}    </Proxy>\n",
        r, r, input, property(r, "Representation", "Surface"),
        property(r, "ColorArrayName", "", "", "", "0", "RadiosityColor"),
        property(r, "MapScalars", 0), property(r, "Interpolation", 1), property(r, "Ambient", 1),
        property(r, "Diffuse", 0), property(r, "Specular", 0),
        property(r, "Visibility", visible ? 1 : 0),
        cull_backfaces ? property(r, "BackfaceRepresentation", 401) : std::string());
}

std::string render_view(const View& view, std::size_t sources) {
    const int v = kView;
    std::string shown;
    for (std::size_t k = 0; k < sources; ++k) {
        shown += fmt::format(R"(<Proxy value="{}"/>)", representation_id(k));
    }
    return fmt::format(
        R"(    <Proxy group="views" type="RenderView" id="{}" servers="21">)"
        "\n"
        R"(      <Property name="Representations" id="{}.Representations" number_of_elements="{}">{}</Property>)"
        "\n{}{}{}{}{}{}{}{}{}{}    </Proxy>\n",
        v, v, sources, shown, vector3(v, "CameraPosition", view.position),
        vector3(v, "CameraFocalPoint", view.look_at), vector3(v, "CameraViewUp", view.up),
        property(v, "CameraViewAngle", view.fov_degrees),
        vector3(v, "CenterOfRotation", view.look_at), property(v, "UseLight", 0),
        property(v, "OrientationAxesVisibility", 0), property(v, "UseColorPaletteForBackground", 0),
        property(v, "Background", 0, 0, 0), property(v, "ViewSize", view.width, view.height));
}

// The pipeline browser's names: each source's own, its representation numbered.
std::string collections(const std::vector<StateSource>& sources) {
    std::string names, shown;
    for (std::size_t k = 0; k < sources.size(); ++k) {
        names +=
            fmt::format(R"(<Item id="{}" name="{}"/>)", reader_id(k), xml_escape(sources[k].name));
        shown += fmt::format(R"(<Item id="{}" name="GeometryRepresentation{}"/>)",
                             representation_id(k), k + 1);
    }
    return fmt::format(
        R"(    <ProxyCollection name="sources">{}</ProxyCollection>)"
        "\n"
        R"(    <ProxyCollection name="representations">{}</ProxyCollection>)"
        "\n"
        R"(    <ProxyCollection name="views"><Item id="{}" name="RenderView1"/></ProxyCollection>)"
        "\n"
        R"(    <ProxyCollection name="layouts"><Item id="{}" name="Layout #1"/></ProxyCollection>)"
        "\n",
        names, shown, kView, kLayout);
}

// The layout of the one view, in preview mode at the view's image size (ParaView's View >
// Preview): the GUI draws the view at exactly that size, or scaled down to fit its window with
// the same aspect, so that it frames what `hmcr render` draws. ViewSize alone gives way to the
// window.
std::string layout(const View& view) {
    return fmt::format(
        R"(    <Proxy group="misc" type="ViewLayout" id="{}" servers="20">)"
        "\n{}"
        R"(      <Layout number_of_elements="1"><Item direction="0" fraction="0.5" view="{}"/></Layout>)"
        "\n    </Proxy>\n",
        kLayout, property(kLayout, "PreviewMode", view.width, view.height), kView);
}

}  // namespace

std::string xml_escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string paraview_state(const std::vector<StateSource>& sources, const View& view,
                           bool cull_backfaces) {
    std::string proxies;
    for (std::size_t k = 0; k < sources.size(); ++k) {
        proxies +=
            reader(sources[k], reader_id(k)) +
            representation(representation_id(k), reader_id(k), sources[k].visible, cull_backfaces);
    }
    return fmt::format(
        "<?xml version=\"1.0\"?>\n<ParaView>\n  <ServerManagerState version=\"5.11.0\">\n"
        "{}{}{}{}  </ServerManagerState>\n</ParaView>\n",
        proxies, render_view(view, sources.size()), layout(view), collections(sources));
}

std::string paraview_state(const std::filesystem::path& vtp, const View& view,
                           bool cull_backfaces) {
    return paraview_state({{vtp, vtp.filename().string(), true}}, view, cull_backfaces);
}

void write_paraview_state(const std::filesystem::path& pvsm, const std::filesystem::path& vtp,
                          const View& view, bool cull_backfaces) {
    write_text_atomically(pvsm, paraview_state(vtp, view, cull_backfaces));
}

void write_paraview_state(const std::filesystem::path& pvsm,
                          const std::vector<StateSource>& sources, const View& view,
                          bool cull_backfaces) {
    write_text_atomically(pvsm, paraview_state(sources, view, cull_backfaces));
}

}  // namespace hmcr
