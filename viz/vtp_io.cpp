// SPDX-License-Identifier: Apache-2.0
#include "viz/vtp_io.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkStringArray.h>
#include <vtkVariant.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <cctype>

#include "viz/vtk_console.h"
#include "viz/vtp_envelope.h"

namespace hmcr {
namespace {

// Collects VTK error messages instead of letting them go to the console.
class ErrorObserver : public vtkCommand {
public:
    static ErrorObserver* New() { return new ErrorObserver; }
    void Execute(vtkObject*, unsigned long, void* data) override {
        std::string text = data ? static_cast<const char*>(data) : "unknown VTK error";
        while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
            text.pop_back();
        }
        m_message += (m_message.empty() ? "" : "; ") + text;
    }
    const std::string& message() const { return m_message; }

private:
    std::string m_message;
};

}  // namespace

void write_polydata(vtkPolyData* pd, const std::filesystem::path& file,
                    const std::filesystem::path& target) {
    silence_vtk_console();
    vtkNew<vtkXMLPolyDataWriter> writer;
    vtkNew<ErrorObserver> errors, pipeline;
    writer->AddObserver(vtkCommand::ErrorEvent, errors);
    // The executive repeats the failure with a dump of the request: keep it off the console.
    writer->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipeline);
    writer->SetFileName(file.c_str());
    writer->SetInputData(pd);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    // LZ4, not zlib: several times faster to write and to read for a larger file, and every
    // ParaView and VTK reader decompresses it (docs/decisions.md). VTK's level 9 is LZ4's
    // default acceleration, its smallest fast mode.
    writer->SetCompressorTypeToLZ4();
    writer->SetCompressionLevel(9);
    const int ok = writer->Write();
    if (ok != 1 || writer->GetErrorCode() != 0 || !errors->message().empty() ||
        !pipeline->message().empty()) {
        // VTK's own text names its source file and line; say it in hmcr's words.
        const unsigned long code = writer->GetErrorCode();
        throw InputError("cannot write " + target.string(),
                         code != 0 ? std::string(vtkErrorCode::GetStringFromErrorCode(code))
                                   : "the VTK writer failed");
    }
}

vtkSmartPointer<vtkDataArray> rgb_float_array(const char* name, const std::vector<Rgb>& values) {
    auto a = vtkSmartPointer<vtkFloatArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(3);
    a->SetComponentName(0, "R");
    a->SetComponentName(1, "G");
    a->SetComponentName(2, "B");
    a->SetNumberOfTuples(vtkIdType(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) {
        for (int k = 0; k < 3; ++k) a->SetTypedComponent(vtkIdType(i), k, float(values[i][k]));
    }
    return a;
}

void add_string_field(vtkFieldData* fd, const char* name, const std::string& value) {
    vtkNew<vtkStringArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
}

std::string VtpChecker::string_field(vtkFieldData* fd, const char* name, const char* what) const {
    auto* a = vtkStringArray::SafeDownCast(fd->GetAbstractArray(name));
    if (!a || a->GetNumberOfValues() != 1) fail(fmt::format("no {} field: {}", name, what));
    return a->GetValue(0);
}

// VTK reads UInt64 back as its own unsigned long type, so the check is on the data type, not
// the array class.
std::uint64_t VtpChecker::count_field(vtkFieldData* fd, const char* name, const char* what) const {
    vtkAbstractArray* a = fd->GetAbstractArray(name);
    if (!a) fail(fmt::format("{} (no {} field)", what, name));
    const int type = a->GetDataType();
    const bool unsigned64 =
        (type == VTK_UNSIGNED_LONG || type == VTK_UNSIGNED_LONG_LONG) && a->GetDataTypeSize() == 8;
    if (!unsigned64 || a->GetNumberOfComponents() != 1 || a->GetNumberOfTuples() != 1) {
        fail(fmt::format("field {} is not one unsigned 64-bit count", name));
    }
    return a->GetVariantValue(0).ToTypeUInt64();
}

// Reads the XML with VTK's own messages kept off the console: our one line says it.
vtkSmartPointer<vtkPolyData> read_polydata(const std::filesystem::path& path,
                                           const VtpChecker& check) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) check.fail("no such file");
    if (!std::filesystem::is_regular_file(path, ec)) check.fail("is not a regular file");
    silence_vtk_console();  // the envelope's decompression reports through VTK too
    check_vtp_envelope(path);
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    bool failed = false;
    auto on_error = vtkSmartPointer<vtkCallbackCommand>::New();
    on_error->SetClientData(&failed);
    on_error->SetCallback(
        [](vtkObject*, unsigned long, void* flag, void*) { *static_cast<bool*>(flag) = true; });
    reader->AddObserver(vtkCommand::ErrorEvent, on_error);
    reader->AddObserver(vtkCommand::WarningEvent, on_error);
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkSmartPointer<vtkPolyData> data = reader->GetOutput();
    if (failed || reader->GetErrorCode() != 0 || !data)
        check.fail("cannot read it as VTK PolyData");
    return data;
}

}  // namespace hmcr
