// SPDX-License-Identifier: Apache-2.0
// The ParaView state written beside a solution, read back as XML (VTK's parser): it names the
// .vtp, colours by RadiosityColor without mapping or lighting, and has the scene's first view
// as its camera. And the study's collection of meshes.
#include "viz/paraview_state.h"

#include <gtest/gtest.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <string>

#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"
#include "viz/paraview_collection.h"

namespace hmcr::test {
namespace {

vtkSmartPointer<vtkXMLDataElement> parse(const std::string& xml) {
    vtkSmartPointer<vtkXMLDataElement> root;
    root.TakeReference(vtkXMLUtilities::ReadElementFromString(xml.c_str()));
    return root;
}

// The proxy of the given type in the state.
vtkXMLDataElement* proxy(vtkXMLDataElement* root, const std::string& type) {
    vtkXMLDataElement* state = root->FindNestedElementWithName("ServerManagerState");
    for (int i = 0; state && i < state->GetNumberOfNestedElements(); ++i) {
        vtkXMLDataElement* e = state->GetNestedElement(i);
        if (std::string(e->GetName()) == "Proxy" && type == e->GetAttribute("type")) return e;
    }
    return nullptr;
}

// The values of a property of a proxy, in element order.
std::vector<std::string> values(vtkXMLDataElement* p, const std::string& name) {
    std::vector<std::string> out;
    for (int i = 0; p && i < p->GetNumberOfNestedElements(); ++i) {
        vtkXMLDataElement* prop = p->GetNestedElement(i);
        const char* attribute = prop->GetAttribute("name");  // a layout's <Layout> has none
        if (attribute == nullptr || name != attribute) continue;
        for (int k = 0; k < prop->GetNumberOfNestedElements(); ++k) {
            const char* v = prop->GetNestedElement(k)->GetAttribute("value");
            out.push_back(v ? v : "");
        }
    }
    return out;
}

std::vector<double> numbers(vtkXMLDataElement* p, const std::string& name) {
    std::vector<double> out;
    for (const std::string& v : values(p, name)) out.push_back(std::stod(v));
    return out;
}

TEST(ParaviewState, SolveWritesAStateThatShowsTheRadiosity) {
    TempDir dir;
    const CliRun r = run_hmcr("solve plates --rays 20000 -q -o out/plates.vtp", dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto root = parse(read_file(dir.path() / "out/plates.pvsm"));
    ASSERT_TRUE(root);
    EXPECT_STREQ(root->GetName(), "ParaView");

    vtkXMLDataElement* reader = proxy(root, "XMLPolyDataReader");
    const auto file = values(reader, "FileName");
    ASSERT_EQ(file.size(), 1u);
    EXPECT_TRUE(std::filesystem::path(file[0]).is_absolute()) << file[0];
    EXPECT_TRUE(std::filesystem::equivalent(file[0], dir.path() / "out/plates.vtp"));

    vtkXMLDataElement* shown = proxy(root, "GeometryRepresentation");
    const auto colour = values(shown, "ColorArrayName");
    ASSERT_EQ(colour.size(), 5u);
    EXPECT_EQ(colour[3], "0");  // point data
    EXPECT_EQ(colour[4], "RadiosityColor");
    EXPECT_EQ(values(shown, "MapScalars"), std::vector<std::string>{"0"});
    EXPECT_EQ(values(shown, "Interpolation"), std::vector<std::string>{"1"});  // Gouraud
    EXPECT_EQ(numbers(shown, "Ambient"), std::vector<double>{1});
    EXPECT_EQ(numbers(shown, "Diffuse"), std::vector<double>{0});

    // The plates scene's first view: "side", from (2.8, 0.5, 0.5) at (0.5, 0.5, 0.5), y up.
    vtkXMLDataElement* view = proxy(root, "RenderView");
    EXPECT_EQ(numbers(view, "CameraPosition"), (std::vector<double>{2.8, 0.5, 0.5}));
    EXPECT_EQ(numbers(view, "CameraFocalPoint"), (std::vector<double>{0.5, 0.5, 0.5}));
    EXPECT_EQ(numbers(view, "CameraViewUp"), (std::vector<double>{0, 1, 0}));
    EXPECT_EQ(values(view, "UseLight"), std::vector<std::string>{"0"});
}

// ParaView's window gives the view its own size, whatever ViewSize says; the layout's preview
// mode holds it at the scene view's image size, so that it frames what `hmcr render` draws.
TEST(ParaviewState, TheLayoutHoldsTheViewAtItsImageSize) {
    View view;
    view.width = 384;
    view.height = 288;
    const auto root = parse(paraview_state("/x.vtp", view));
    ASSERT_TRUE(root);
    EXPECT_EQ(numbers(proxy(root, "ViewLayout"), "PreviewMode"), (std::vector<double>{384, 288}));
    EXPECT_EQ(numbers(proxy(root, "RenderView"), "ViewSize"), (std::vector<double>{384, 288}));
}

// A study's meshes: one source each, named, coloured alike, the first alone shown.
TEST(ParaviewState, SeveralSourcesAreNamedAndTheFirstAloneShown) {
    View view;
    const auto root = parse(paraview_state(
        {{"/s/meshes/a.vtp", "a.vtp", true}, {"/s/meshes/b.vtp", "b.vtp", false}}, view, true));
    ASSERT_TRUE(root);
    vtkXMLDataElement* state = root->FindNestedElementWithName("ServerManagerState");
    std::vector<std::string> files, visible, colours, culled;
    for (int i = 0; i < state->GetNumberOfNestedElements(); ++i) {
        vtkXMLDataElement* e = state->GetNestedElement(i);
        const std::string type = e->GetAttribute("type") ? e->GetAttribute("type") : "";
        if (type == "XMLPolyDataReader") files.push_back(values(e, "FileName").at(0));
        if (type == "GeometryRepresentation") {
            visible.push_back(values(e, "Visibility").at(0));
            colours.push_back(values(e, "ColorArrayName").at(4));
            culled.push_back(values(e, "BackfaceRepresentation").at(0));
        }
    }
    EXPECT_EQ(files, (std::vector<std::string>{"/s/meshes/a.vtp", "/s/meshes/b.vtp"}));
    EXPECT_EQ(visible, (std::vector<std::string>{"1", "0"}));
    EXPECT_EQ(colours, (std::vector<std::string>{"RadiosityColor", "RadiosityColor"}));
    EXPECT_EQ(culled, (std::vector<std::string>{"401", "401"}));
    vtkXMLDataElement* shown =
        proxy(root, "RenderView")
            ->FindNestedElementWithNameAndAttribute("Property", "name", "Representations");
    ASSERT_TRUE(shown);
    EXPECT_EQ(shown->GetNumberOfNestedElements(), 2);
    const std::string xml =
        paraview_state({{"/x/a.vtp", "a.vtp", true}, {"/x/b.vtp", "b.vtp", false}}, view, false);
    EXPECT_NE(
        xml.find(
            R"(<ProxyCollection name="sources"><Item id="10" name="a.vtp"/><Item id="12" name="b.vtp"/></ProxyCollection>)"),
        std::string::npos)
        << xml;
}

TEST(ParaviewState, FileNamesAreEscaped) {
    View view;
    const std::string xml = paraview_state("/a & b/\"x\" <y>.vtp", view);
    const auto root = parse(xml);
    ASSERT_TRUE(root);
    EXPECT_EQ(values(proxy(root, "XMLPolyDataReader"), "FileName"),
              std::vector<std::string>{"/a & b/\"x\" <y>.vtp"});
}

TEST(ParaviewCollection, OneTimeStepPerFile) {
    const auto root =
        parse(paraview_collection({{"meshes/a.vtp", "a"}, {"meshes/b & c.vtp", "b"}}));
    ASSERT_TRUE(root);
    EXPECT_STREQ(root->GetAttribute("type"), "Collection");
    vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
    ASSERT_EQ(collection->GetNumberOfNestedElements(), 2);
    EXPECT_STREQ(collection->GetNestedElement(1)->GetAttribute("file"), "meshes/b & c.vtp");
    EXPECT_STREQ(collection->GetNestedElement(1)->GetAttribute("timestep"), "1");
}

}  // namespace
}  // namespace hmcr::test
