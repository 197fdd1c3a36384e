// SPDX-License-Identifier: Apache-2.0
// Hostile solution files: a .vtp from outside is checked array by array and cell by cell, and
// bound to the scene it was solved for.
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

// Every way VTK's writer stores arrays: compressed three ways, raw, base64, inline and ascii.
using WriterMode = std::function<void(vtkXMLPolyDataWriter*)>;
const std::vector<std::pair<std::string, WriterMode>>& writer_modes() {
    static const std::vector<std::pair<std::string, WriterMode>> modes = {
        {"zlib", [](vtkXMLPolyDataWriter* w) { w->SetCompressorTypeToZLib(); }},
        {"lz4", [](vtkXMLPolyDataWriter* w) { w->SetCompressorTypeToLZ4(); }},
        {"lzma", [](vtkXMLPolyDataWriter* w) { w->SetCompressorTypeToLZMA(); }},
        {"zlib-raw",
         [](vtkXMLPolyDataWriter* w) {
             w->SetCompressorTypeToZLib();
             w->EncodeAppendedDataOff();
         }},
        {"raw",
         [](vtkXMLPolyDataWriter* w) {
             w->SetCompressorTypeToNone();
             w->EncodeAppendedDataOff();
         }},
        {"base64", [](vtkXMLPolyDataWriter* w) { w->SetCompressorTypeToNone(); }},
        {"binary", [](vtkXMLPolyDataWriter* w) { w->SetDataModeToBinary(); }},
        {"ascii", [](vtkXMLPolyDataWriter* w) { w->SetDataModeToAscii(); }},
    };
    return modes;
}

class HostileSolution : public Hostile {
protected:
    void SetUp() override {
        plates();
        accepted("solve plates.json --rays 2000 -q -o good.vtp");
    }
    // FROM (good.vtp) changed by `spoil`, written as NAME.
    void spoilt(const std::string& name, const std::function<void(vtkPolyData*)>& spoil,
                const std::string& from = "good.vtp") const {
        vtkNew<vtkXMLPolyDataReader> reader;
        reader->SetFileName((dir() / from).c_str());
        reader->Update();
        vtkPolyData* data = reader->GetOutput();
        spoil(data);
        vtkNew<vtkXMLPolyDataWriter> writer;
        writer->SetFileName((dir() / name).c_str());
        writer->SetInputData(data);
        ASSERT_EQ(writer->Write(), 1);
    }
    // Both readers of solutions refuse it.
    void expect_refused(const std::string& vtp, const std::string& needle) const {
        refused("render " + vtp + " --scene plates.json -o x.png", needle);
        refused("info " + vtp + " --scene plates.json", needle);
    }
    // good.vtp's bytes changed by `edit`, written as NAME: refused as "NAME: damaged VTK file:
    // WHAT".
    void expect_damaged(const std::string& name, const std::function<void(std::string&)>& edit,
                        const std::string& what) {
        std::string bytes = read_file(dir() / "good.vtp");
        edit(bytes);
        m_temp.write(name, bytes);
        expect_refused(name, name + ": damaged VTK file: " + what);
    }
    // good.vtp as VTK reads it, written again by VTK in each of writer_modes() as NAME-MODE.vtp,
    // and changed by `spoil` first as NAME-MODE-spoilt.vtp: the first accepted, the second
    // refused as "damaged VTK file: WHY".
    void expect_every_layout(const std::string& name,
                             const std::function<void(vtkPolyData*)>& spoil,
                             const std::string& why) const {
        for (const auto& [mode, configure] : writer_modes()) {
            for (const bool spoilt : {false, true}) {
                vtkNew<vtkXMLPolyDataReader> reader;
                reader->SetFileName((dir() / "good.vtp").c_str());
                reader->Update();
                vtkPolyData* data = reader->GetOutput();
                if (spoilt) spoil(data);
                const std::string file = name + "-" + mode + (spoilt ? "-spoilt.vtp" : ".vtp");
                vtkNew<vtkXMLPolyDataWriter> writer;
                writer->SetFileName((dir() / file).c_str());
                writer->SetInputData(data);
                configure(writer);
                ASSERT_EQ(writer->Write(), 1) << file;
                if (spoilt) {
                    expect_refused(file, file + ": damaged VTK file: " + why);
                } else {
                    accepted("info " + file + " --scene plates.json --lines 1000");
                }
            }
        }
    }
};

TEST_F(HostileSolution, CellsThatAreNotPolygonsAreRefused) {
    // As many lines as there were polygons, so that VTK itself reads the file.
    spoilt("lines.vtp", [](vtkPolyData* d) {
        vtkNew<vtkCellArray> lines;
        for (vtkIdType c = 0; c < d->GetNumberOfPolys(); ++c) {
            const vtkIdType ids[2] = {0, 1};
            lines->InsertNextCell(2, ids);
        }
        d->SetPolys(vtkNew<vtkCellArray>());
        d->SetLines(lines);
    });
    expect_refused("lines.vtp", "has cells that are not polygons");
    spoilt("empty.vtp", [](vtkPolyData* d) {
        d->SetPolys(vtkNew<vtkCellArray>());
        d->GetCellData()->Initialize();
    });
    expect_refused("empty.vtp", "holds no polygons");
}

TEST_F(HostileSolution, ArraysOfTheWrongShapeAreRefused) {
    spoilt("one.vtp", [](vtkPolyData* d) {
        vtkNew<vtkFloatArray> b;
        b->SetName("Radiosity");
        b->SetNumberOfTuples(d->GetNumberOfPoints());
        b->Fill(1);
        d->GetPointData()->AddArray(b);
    });
    expect_refused("one.vtp", "array Radiosity has");
    spoilt("noarea.vtp", [](vtkPolyData* d) { d->GetCellData()->RemoveArray("ElementArea"); });
    expect_refused("noarea.vtp", "no ElementArea array");
}

TEST_F(HostileSolution, ValuesOutOfRangeAreRefused) {
    const auto set_patch = [](int value) {
        return [value](vtkPolyData* d) {
            vtkIntArray::SafeDownCast(d->GetCellData()->GetArray("PatchId"))->SetValue(0, value);
        };
    };
    spoilt("minus.vtp", set_patch(-1));
    expect_refused("minus.vtp", "PatchId -1");
    spoilt("beyond.vtp", set_patch(7));
    expect_refused("beyond.vtp", "PatchId 7, but the scene has 2 patches");
    spoilt("nan.vtp", [](vtkPolyData* d) {
        vtkFloatArray::SafeDownCast(d->GetPointData()->GetArray("Radiosity"))->SetValue(0, NAN);
    });
    expect_refused("nan.vtp", "Radiosity nan is not a finite number\n");
    // Not "is not a finite number of at least -inf": a radiosity may be negative (§3.11).
    for (const float value : {-INFINITY, INFINITY, NAN}) {
        spoilt("inf.vtp", [value](vtkPolyData* d) {
            vtkFloatArray::SafeDownCast(d->GetCellData()->GetArray("ElementRadiosity"))
                ->SetValue(1, value);
        });
        const std::string shown = std::isnan(value) ? "nan" : value < 0 ? "-inf" : "inf";
        expect_refused("inf.vtp", "ElementRadiosity " + shown + " is not a finite number\n");
    }
    spoilt("area.vtp", [](vtkPolyData* d) {
        vtkDoubleArray::SafeDownCast(d->GetCellData()->GetArray("ElementArea"))->SetValue(0, -2);
    });
    expect_refused("area.vtp", "ElementArea -2 is negative\n");
}

// A signed estimator (the control variate, docs/design.md §3.11) may leave a dim leaf below 0:
// a value, not damage. Both readers take it; the image shows it black.
TEST_F(HostileSolution, NegativeRadiosityIsAValue) {
    spoilt("negative.vtp", [](vtkPolyData* d) {
        vtkFloatArray::SafeDownCast(d->GetPointData()->GetArray("Radiosity"))->SetValue(0, -0.25f);
        vtkFloatArray::SafeDownCast(d->GetCellData()->GetArray("ElementRadiosity"))
            ->SetValue(1, -0.5f);
    });
    accepted("render negative.vtp --scene plates.json -o negative.png");
    accepted("info negative.vtp --scene plates.json");
}

TEST_F(HostileSolution, ASolutionOfAnotherSceneIsRefused) {
    refused("render good.vtp --scene cornell -o x.png", "is a solution of scene 'plates'");
    refused("info good.vtp --scene cornell", "not of 'cornell'");
}

// The Side array must be the scene's: backs only on two-sided patches, one on every patch whose
// back emits (the plates' emitter, two-sided here), and the cells in their order, fronts patch
// by patch, then backs. Each of these changed a study's or info's results, or ended a study in
// an internal error.
TEST_F(HostileSolution, SidesThatAreNotTheScenesAreRefused) {
    m_temp.write("one.json", with(kPlatesJson, "{", R"({"sides": 1, )"));
    refused("render good.vtp --scene one.json -o x.png",
            "is the back of patch 0, which is one-sided in scene 'one'");
    refused("info good.vtp --scene one.json", "which is one-sided in scene 'one'");
    refused("error good.vtp --scene one.json --reference nowhere", "one-sided in scene 'one'");
    accepted("solve one.json --rays 2000 -q -o one-sided.vtp");
    refused("render one-sided.vtp --scene plates.json -o x.png",
            "one-sided.vtp: patch 0 has no back cell, but its back emits in scene 'plates'");
    const auto set_sides = [](const std::function<unsigned char(vtkIdType, unsigned char)>& f) {
        return [f](vtkPolyData* d) {
            auto* side = vtkUnsignedCharArray::SafeDownCast(d->GetCellData()->GetArray("Side"));
            for (vtkIdType c = 0; c < side->GetNumberOfTuples(); ++c)
                side->SetValue(c, f(c, side->GetValue(c)));
        };
    };
    spoilt("fronts.vtp", set_sides([](vtkIdType, unsigned char) { return 0; }));
    spoilt("backs.vtp", set_sides([](vtkIdType, unsigned char) { return 1; }));
    spoilt("shuffled.vtp", set_sides([](vtkIdType c, unsigned char s) { return c == 0 ? 1 : s; }));
    for (const char* vtp : {"fronts.vtp", "backs.vtp", "shuffled.vtp"}) {
        const std::string needle = std::string(vtp) + ": ";
        expect_refused(vtp, needle);
        refused(std::string("info ") + vtp, needle);  // without the scene, the order alone
    }
    expect_refused("fronts.vtp", "is patch 0's front after patch 1's");
    expect_refused("backs.vtp", "is patch 0's back after patch 1's");
    expect_refused("shuffled.vtp", "cell 1 is a front after a back");
    spoilt("patch0.vtp", [](vtkPolyData* d) {
        auto* patch = vtkIntArray::SafeDownCast(d->GetCellData()->GetArray("PatchId"));
        for (vtkIdType c = 0; c < patch->GetNumberOfTuples(); ++c) patch->SetValue(c, 0);
    });
    expect_refused("patch0.vtp", "patch0.vtp: patch 1 has no front cell (of 2 patches)");
}

// ClusterId and Clustering: a known clustering, ids only with clustering, whole numbers from -1
// to below the clusters a tree over the patches' sides has, one per side of a patch.
TEST_F(HostileSolution, ClusterIdsThatNoSolveWritesAreRefused) {
    accepted("solve plates.json --rays 2000 --clustering isotropic -q -o clustered.vtp");
    accepted("render clustered.vtp --scene plates.json -o clustered.png");
    const auto set_ids = [](const std::function<int(vtkIdType, int)>& f) {
        return [f](vtkPolyData* d) {
            auto* ids = vtkIntArray::SafeDownCast(d->GetCellData()->GetArray("ClusterId"));
            for (vtkIdType c = 0; c < ids->GetNumberOfTuples(); ++c)
                ids->SetValue(c, f(c, ids->GetValue(c)));
        };
    };
    spoilt("minus.vtp", set_ids([](vtkIdType c, int id) { return c == 0 ? -5 : id; }),
           "clustered.vtp");
    expect_refused("minus.vtp",
                   "minus.vtp: cell 0 has ClusterId -5, not -1 or one of the 3 "
                   "clusters of 2 patches");
    spoilt("largest.vtp", set_ids([](vtkIdType c, int id) { return c == 0 ? 2147483647 : id; }),
           "clustered.vtp");
    expect_refused("largest.vtp", "cell 0 has ClusterId 2147483647");
    // Cells 0 and 1 are one side of one patch (the first patch's front is refined).
    spoilt("split.vtp", set_ids([](vtkIdType c, int id) { return c == 1 ? id + 1 : id; }),
           "clustered.vtp");
    expect_refused("split.vtp", "one side of a patch is in one cluster");
    spoilt(
        "float.vtp",
        [](vtkPolyData* d) {
            vtkNew<vtkFloatArray> ids;
            ids->SetName("ClusterId");
            ids->SetNumberOfTuples(d->GetNumberOfCells());
            ids->Fill(0.5f);
            d->GetCellData()->RemoveArray("ClusterId");
            d->GetCellData()->AddArray(ids);
        },
        "clustered.vtp");
    expect_refused("float.vtp", "float.vtp: ");
    spoilt(
        "anisotropic.vtp",
        [](vtkPolyData* d) {
            vtkNew<vtkStringArray> clustering;
            clustering->SetName("Clustering");
            clustering->InsertNextValue("anisotropic");
            d->GetFieldData()->RemoveArray("Clustering");
            d->GetFieldData()->AddArray(clustering);
        },
        "clustered.vtp");
    expect_refused("anisotropic.vtp",
                   "has Clustering 'anisotropic', not none, isotropic or oriented");
    spoilt("unclustered.vtp", [](vtkPolyData* d) {
        vtkNew<vtkIntArray> ids;
        ids->SetName("ClusterId");
        ids->SetNumberOfTuples(d->GetNumberOfCells());
        ids->Fill(-1);
        d->GetCellData()->AddArray(ids);
    });
    expect_refused("unclustered.vtp", "has a ClusterId array, but Clustering 'none'");
}

// Basis and its arrays: a known basis; LeafCoordinates, Coefficients and LeafIndex exactly with
// a basis beyond the constant, of its component counts; leaf coordinates in the unit domain,
// finite coefficients, and the cells of each leaf together, numbered from 0.
TEST_F(HostileSolution, HigherOrderArraysThatNoSolveWritesAreRefused) {
    accepted("solve plates.json --rays 2000 --basis cubic -q -o cubic.vtp");
    accepted("render cubic.vtp --scene plates.json -o cubic.png");
    accepted("info cubic.vtp --scene plates.json --lines 1000");
    spoilt(
        "uncoefficient.vtp", [](vtkPolyData* d) { d->GetCellData()->RemoveArray("Coefficients"); },
        "cubic.vtp");
    expect_refused("uncoefficient.vtp",
                   "uncoefficient.vtp: not a whole solution on the cubic basis (no Coefficients "
                   "array)");
    spoilt(
        "narrow.vtp",
        [](vtkPolyData* d) {
            vtkNew<vtkDoubleArray> c;
            c->SetName("Coefficients");
            c->SetNumberOfComponents(3);
            c->SetNumberOfTuples(d->GetNumberOfCells());
            c->Fill(1);
            d->GetCellData()->RemoveArray("Coefficients");
            d->GetCellData()->AddArray(c);
        },
        "cubic.vtp");
    expect_refused("narrow.vtp", "narrow.vtp: array Coefficients has");
    expect_refused("narrow.vtp", "components; expected");
    spoilt(
        "quartic.vtp",
        [](vtkPolyData* d) {
            vtkNew<vtkStringArray> basis;
            basis->SetName("Basis");
            basis->InsertNextValue("quartic");
            d->GetFieldData()->RemoveArray("Basis");
            d->GetFieldData()->AddArray(basis);
        },
        "cubic.vtp");
    expect_refused("quartic.vtp",
                   "quartic.vtp: has Basis 'quartic', not constant, linear, bilinear, quadratic "
                   "or cubic");
    spoilt(
        "unbased.vtp", [](vtkPolyData* d) { d->GetFieldData()->RemoveArray("Basis"); },
        "cubic.vtp");
    expect_refused("unbased.vtp",
                   "unbased.vtp: has a Coefficients array, but no Basis beyond the constant");
    spoilt(
        "outside.vtp",
        [](vtkPolyData* d) {
            vtkDoubleArray::SafeDownCast(d->GetPointData()->GetArray("LeafCoordinates"))
                ->SetValue(1, 1.5);
        },
        "cubic.vtp");
    expect_refused("outside.vtp", "outside.vtp: point 0 has LeafCoordinates 1.5, not in [0, 1]");
    spoilt(
        "infinite.vtp",
        [](vtkPolyData* d) {
            vtkDoubleArray::SafeDownCast(d->GetCellData()->GetArray("Coefficients"))
                ->SetValue(4, INFINITY);
        },
        "cubic.vtp");
    expect_refused("infinite.vtp", "infinite.vtp: Coefficients inf is not a finite number");
    spoilt(
        "skipped.vtp",
        [](vtkPolyData* d) {
            vtkIntArray::SafeDownCast(d->GetCellData()->GetArray("LeafIndex"))->SetValue(1, 5);
        },
        "cubic.vtp");
    expect_refused("skipped.vtp",
                   "skipped.vtp: cell 1 has LeafIndex 5 after 0: the cells of a leaf run "
                   "together");
    spoilt("stray.vtp", [](vtkPolyData* d) {
        vtkNew<vtkDoubleArray> ab;
        ab->SetName("LeafCoordinates");
        ab->SetNumberOfComponents(2);
        ab->SetNumberOfTuples(d->GetNumberOfPoints());
        ab->Fill(0);
        d->GetPointData()->AddArray(ab);
    });
    expect_refused("stray.vtp",
                   "stray.vtp: has a LeafCoordinates array, but no Basis beyond the constant");
}

TEST_F(HostileSolution, GarbageIsRefused) {
    m_temp.write("junk.vtp", "<VTKFile>nonsense");
    expect_refused("junk.vtp", "junk.vtp: ");
    expect_refused("none.vtp", "none.vtp: no such file");
    std::filesystem::create_directory(dir() / "folder.vtp");
    expect_refused("folder.vtp", "folder.vtp: is not a regular file");
}

// Sizes VTK would trust: a block count of 2^31 in the first appended array's header made the
// reader take gigabytes and a minute (found by the fuzzer); a huge NumberOfPoints likewise.
TEST_F(HostileSolution, DeclaredSizesBeyondTheFileAreRefusedBeforeReading) {
    const std::string bytes = read_file(dir() / "good.vtp");
    const auto first_array = [](const std::string& b) {
        return b.find('_', b.find("<AppendedData")) + 1;
    };
    const auto replace = [](std::size_t at, std::size_t n, std::string with) {
        return [=](std::string& b) { b.replace(at, n, with); };
    };
    expect_damaged("blocks.vtp", replace(first_array(bytes), 4, std::string("\x00\x00\x00\x80", 4)),
                   "the array at offset 0 declares");
    const std::size_t at = bytes.find("NumberOfPoints=\"") + 16;
    const std::size_t count = bytes.find('"', at) - at;
    expect_damaged("points.vtp", replace(at, count, "900000000000"),
                   "NumberOfPoints is '900000000000'");
    // A count of 400 digits: std::stod would throw out_of_range (an internal error).
    expect_damaged("digits.vtp", replace(at, count, std::string(400, '9')),
                   "NumberOfPoints is '999");
    // A count attribute of 3,000 characters and no number: the message shows its name cut
    // short, one short line (fuzzer).
    const std::size_t name = bytes.find("NumberOfPoints=\"");
    expect_damaged("name.vtp",
                   replace(name, 16 + count, "NumberOfP" + std::string(3000, '9') + "=\"x"),
                   "NumberOfP" + std::string(31, '9') + "... is 'x', not a plain number");
    // No blocks but a last block of some bytes: another null dereference in VTK (fuzzer).
    expect_damaged("header.vtp",
                   replace(first_array(bytes), 12,
                           std::string("\x00\x00\x00\x00\x00\x80\x00\x00\x08\x00\x00\x00", 12)),
                   "the array at offset 0 has a block header");
    // An unknown type name crashed VTK's reader (a null array dereferenced; the fuzzer again).
    const std::size_t type = bytes.find("type=\"Float64\"");
    expect_damaged("type.vtp", replace(type, 14, "type=\"Float65\""),
                   "an array of unknown type 'Float65'");
    // An array without a type: another null dereference in VTK (fuzzer).
    expect_damaged("untyped.vtp", replace(type, 14, "Numi=\"Float64\""), "an array without a type");
    // Bytes before the '_' marker: VTK takes the first for the marker and reads every header
    // off by their count (a 3 GB allocation, fuzzer).
    expect_damaged("marker.vtp", replace(first_array(bytes) - 1, 0, "\xe0\xe8 "),
                   "appended data without its '_' marker");
    // An element VTK reads as an array though it is none: another null dereference (fuzzer).
    expect_damaged("element.vtp", replace(bytes.find("<DataArray"), 10, "<Dattr    "),
                   "an element 'Dattr' that no .vtp of hmcr holds");
    // Points of 6 components: VTK refuses them but leaks what it read (LeakSanitizer, fuzzer).
    expect_damaged("six.vtp",
                   replace(bytes.find("NumberOfComponents=\"3\"", bytes.find("<Points>")), 22,
                           "NumberOfComponents=\"6\""),
                   "its points do not have 3 components");
    // VTK reads offset="19i" as 19, inside another array: a 2.7 GB header and 26 s (fuzzer).
    // Every spelling XML allows is checked: single quotes, spaces around '='.
    const std::size_t offset = bytes.find("offset=\"", bytes.find("offset=\"") + 1);
    const std::size_t value = offset + 8, end = bytes.find('"', value);
    const std::string number = bytes.substr(value, end - value);
    for (const std::string& spelling :
         {"offset=\"" + number + "i\"", "offset='" + number + "i'", "offset = '" + number + "i'"}) {
        expect_damaged("offset.vtp", replace(offset, end + 1 - offset, spelling),
                       "offset is '" + number + "i', not a plain number");
    }
    expect_damaged("quoted.vtp", replace(at - 16, count + 17, "NumberOfPoints='900000000000'"),
                   "NumberOfPoints is '900000000000'");
    // Components and tuples each within the file, but not their product.
    const std::size_t components = bytes.find("NumberOfComponents=\"3\"", bytes.find("<CellData"));
    expect_damaged("components.vtp", replace(components, 22, "NumberOfComponents=\"9000000\""),
                   "an array of '9000000' components and ");
    // Headers are read as hmcr writes them: a big-endian file would be checked wrongly.
    expect_damaged("endian.vtp", replace(bytes.find("LittleEndian"), 12, "BigEndian"),
                   "byte_order is 'BigEndian', not LittleEndian");
}

// VTK makes a cell array's connectivity as long as its last offset says, whatever the
// connectivity holds: one byte of an offset changed asked for 10^17 bytes (AddressSanitizer,
// fuzzer). Every way VTK stores an array is checked, and each is read when it is sound.
TEST_F(HostileSolution, OffsetsBeyondTheConnectivityAreRefusedBeforeReading) {
    expect_every_layout(
        "offsets",
        [](vtkPolyData* data) {
            vtkCellArray* polys = data->GetPolys();
            vtkNew<vtkTypeInt64Array> offsets;
            offsets->DeepCopy(polys->GetOffsetsArray());
            offsets->SetValue(offsets->GetNumberOfValues() - 1, 4'000'000'000'000);
            vtkNew<vtkTypeInt64Array> connectivity;
            connectivity->DeepCopy(polys->GetConnectivityArray());
            polys->SetData(offsets, connectivity);
        },
        "its Polys offsets reach 4000000000000, but its connectivity holds");
}

// A String array whose values hold more strings than it has places: VTK 9.1 writes the strings
// past the array's end (found by the fuzzer).
TEST_F(HostileSolution, StringArraysOfMoreStringsThanPlacesAreRefusedBeforeReading) {
    expect_every_layout(
        "strings",
        [](vtkPolyData* data) {
            vtkNew<vtkStringArray> note;
            note->SetName("Note");
            // The writer stores a string's bytes and then its end: one more inside makes two.
            note->InsertNextValue(std::string("one\0two", 7));
            data->GetFieldData()->AddArray(note);
        },
        "String array 'Note' holds 2 strings; it has places for 1");
}

// A count of 200,000 digits: the envelope check itself once crashed on it (a regular
// expression's recursion overflowed the stack); an XML parser reads it like any other value.
TEST_F(HostileSolution, AnAttributeOf200000CharactersIsReadNotACrash) {
    std::string bytes = read_file(dir() / "good.vtp");
    const std::size_t at = bytes.find("NumberOfPoints=\"") + 16;
    bytes.replace(at, bytes.find('"', at) - at, std::string(200'000, '9'));
    m_temp.write("digits.vtp", bytes);
    expect_refused("digits.vtp", "digits.vtp: damaged VTK file: NumberOfPoints is '999");
    bytes = read_file(dir() / "good.vtp");
    // As long, but harmless: an attribute VTK does not read.
    bytes.insert(bytes.find("<DataArray") + 10, " Note=\"" + std::string(200'000, 'n') + "\"");
    m_temp.write("note.vtp", bytes);
    accepted("info note.vtp --scene plates.json --lines 1000");
}

// Two arrays of one name in CellData: VTK 9.1 dereferences null (found by the fuzzer).
TEST_F(HostileSolution, TwoArraysOfOneNameAreRefused) {
    std::string bytes = read_file(dir() / "good.vtp");
    const std::size_t start = bytes.rfind('\n', bytes.find("Name=\"ElementArea\"")) + 1;
    const std::size_t end = bytes.find('\n', start) + 1;
    bytes.insert(end, bytes.substr(start, end - start));
    m_temp.write("twice.vtp", bytes);
    expect_refused("twice.vtp",
                   "twice.vtp: damaged VTK file: two arrays named 'ElementArea' in its CellData");
}

// The XML part is read by an XML parser: what is not XML, or holds a document type (where
// entities could be declared and expanded), is refused before VTK reads it.
TEST_F(HostileSolution, XmlThatIsNotWellFormedOrDeclaresATypeIsRefused) {
    const std::string bytes = read_file(dir() / "good.vtp");
    const auto edit = [](std::size_t at, std::size_t n, std::string with) {
        return [=](std::string& b) { b.replace(at, n, with); };
    };
    const std::size_t type = bytes.find("type=\"Float64\"");
    expect_damaged("joined.vtp", edit(type, 15, "type=\"Float64\""),
                   "XML error at line 5: not well-formed");
    expect_damaged("doctype.vtp", edit(bytes.find("<VTKFile"), 0, "<!DOCTYPE VTKFile>"),
                   "a document type declaration");
}

}  // namespace
}  // namespace hmcr::test
