// The .pvsm writer (paraview_state.h). The layout of the file is ParaView's own: proxies with
// ids and properties, then proxy collections that name them; ids here are fixed.
#include "viz/paraview_state.h"

#include <fmt/format.h>

#include "common/atomic_file.h"

namespace hmcr {
namespace {

constexpr int kReader = 2, kRepresentation = 3, kView = 4, kLayout = 5;

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

std::string reader(const std::filesystem::path& vtp) {
    const std::string file = xml_escape(std::filesystem::absolute(vtp).lexically_normal().string());
    return fmt::format(R"(    <Proxy group="sources" type="XMLPolyDataReader" id="{}" servers="1">)"
                       "\n{}    </Proxy>\n",
                       kReader, property(kReader, "FileName", file));
}

// RadiosityColor as it is (MapScalars 0), interpolated, and unlit: the ambient term alone,
// at full strength, shows a colour exactly. With two-sided patches, back faces are culled
// (401, "Cull Backface"): a patch's two sides are coincident polygons facing away from each
// other, and each viewer then sees the side that faces it.
std::string representation(bool cull_backfaces) {
    const int r = kRepresentation;
    return fmt::format(
        R"(    <Proxy group="representations" type="GeometryRepresentation" id="{}" servers="21">)"
        "\n"
        R"(      <Property name="Input" id="{}.Input" number_of_elements="1"><Proxy value="{}" output_port="0"/></Property>)"
        "\n{}{}{}{}{}{}{}{}{}    </Proxy>\n",
        r, r, kReader, property(r, "Representation", "Surface"),
        property(r, "ColorArrayName", "", "", "", "0", "RadiosityColor"),
        property(r, "MapScalars", 0), property(r, "Interpolation", 1), property(r, "Ambient", 1),
        property(r, "Diffuse", 0), property(r, "Specular", 0), property(r, "Visibility", 1),
        cull_backfaces ? property(r, "BackfaceRepresentation", 401) : std::string());
}

std::string render_view(const View& view) {
    const int v = kView;
    return fmt::format(
        R"(    <Proxy group="views" type="RenderView" id="{}" servers="21">)"
        "\n"
        R"(      <Property name="Representations" id="{}.Representations" number_of_elements="1"><Proxy value="{}"/></Property>)"
        "\n{}{}{}{}{}{}{}{}{}{}    </Proxy>\n",
        v, v, kRepresentation, vector3(v, "CameraPosition", view.position),
        vector3(v, "CameraFocalPoint", view.look_at), vector3(v, "CameraViewUp", view.up),
        property(v, "CameraViewAngle", view.fov_degrees),
        vector3(v, "CenterOfRotation", view.look_at), property(v, "UseLight", 0),
        property(v, "OrientationAxesVisibility", 0), property(v, "UseColorPaletteForBackground", 0),
        property(v, "Background", 0, 0, 0), property(v, "ViewSize", view.width, view.height));
}

std::string collections(const std::filesystem::path& vtp) {
    return fmt::format(
        R"(    <ProxyCollection name="sources"><Item id="{}" name="{}"/></ProxyCollection>)"
        "\n"
        R"(    <ProxyCollection name="representations"><Item id="{}" name="GeometryRepresentation1"/></ProxyCollection>)"
        "\n"
        R"(    <ProxyCollection name="views"><Item id="{}" name="RenderView1"/></ProxyCollection>)"
        "\n"
        R"(    <ProxyCollection name="layouts"><Item id="{}" name="Layout #1"/></ProxyCollection>)"
        "\n",
        kReader, xml_escape(vtp.filename().string()), kRepresentation, kView, kLayout);
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

std::string paraview_state(const std::filesystem::path& vtp, const View& view,
                           bool cull_backfaces) {
    return fmt::format(
        "<?xml version=\"1.0\"?>\n<ParaView>\n  <ServerManagerState version=\"5.11.0\">\n"
        "{}{}{}{}{}  </ServerManagerState>\n</ParaView>\n",
        reader(vtp), representation(cull_backfaces), render_view(view), layout(view),
        collections(vtp));
}

void write_paraview_state(const std::filesystem::path& pvsm, const std::filesystem::path& vtp,
                          const View& view, bool cull_backfaces) {
    write_text_atomically(pvsm, paraview_state(vtp, view, cull_backfaces));
}

}  // namespace hmcr
