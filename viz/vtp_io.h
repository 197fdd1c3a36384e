// SPDX-License-Identifier: Apache-2.0
// What every hmcr .vtp reader and writer shares (the solutions of viz/vtk_export.h and
// viz/vtk_import.h, the reference points of viz/point_radiosity_file.h): VTK's XML PolyData
// written atomically with hmcr's compression, read with VTK's messages kept off the console,
// and a checker for the arrays a file holds, which comes from outside and may hold anything.
#pragma once

#include <fmt/format.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/types.h"

namespace hmcr {

// Writes `pd` to `file` (appended raw, LZ4), throwing InputError naming `target` (the file the
// caller means, of which `file` may be the temporary) when VTK fails.
void write_polydata(vtkPolyData* pd, const std::filesystem::path& file,
                    const std::filesystem::path& target);

// A float array of RGB triples named `name`, with components R, G, B.
vtkSmartPointer<vtkDataArray> rgb_float_array(const char* name, const std::vector<Rgb>& values);

// One-tuple field data: a string, or one value of an array type.
void add_string_field(vtkFieldData* fd, const char* name, const std::string& value);

template <class Array, class T>
void add_value_field(vtkFieldData* fd, const char* name, T value) {
    vtkNew<Array> a;
    a->SetName(name);
    a->SetNumberOfTuples(1);
    a->SetValue(0, value);
    fd->AddArray(a);
}

// Every array, count and value is checked before use: VTK hands out whatever the file says (a
// 1-component "Radiosity", a PatchId of -7, lines for cells). Every failure is an InputError
// naming the file.
class VtpChecker {
public:
    explicit VtpChecker(const std::filesystem::path& path) : m_path(path.string()) {}

    [[noreturn]] void fail(const std::string& why) const { throw InputError(m_path, why); }

    // The array called name in `data`, of type A, with `components` components and `tuples`
    // tuples; `what` says what a file without it is not ("not an hmcr solution").
    template <class A>
    A* array(vtkFieldData* data, const char* name, int components, vtkIdType tuples,
             const char* what = "not an hmcr solution") const {
        vtkAbstractArray* raw = data->GetAbstractArray(name);
        if (!raw) fail(fmt::format("{} (no {} array)", what, name));
        A* a = A::SafeDownCast(raw);
        if (!a) {
            const vtkNew<A> wanted;  // an instance only for its type's name
            fail(fmt::format("array {} has type {}, not {}", name, raw->GetDataTypeAsString(),
                             wanted->GetDataTypeAsString()));
        }
        if (a->GetNumberOfComponents() != components || a->GetNumberOfTuples() != tuples) {
            fail(fmt::format("array {} has {} tuples of {} components; expected {} of {}", name,
                             a->GetNumberOfTuples(), a->GetNumberOfComponents(), tuples,
                             components));
        }
        return a;
    }

    // The value when it is finite and at least `lowest` (-HUGE_VAL: any finite value); else a
    // failure "Radiosity nan is not a finite number", "PatchId -1 is negative" or "X 2 is below
    // 3".
    template <class T>
    T finite_at_least(T value, T lowest, const char* what) const {
        if (!std::isfinite(double(value)))
            fail(fmt::format("{} {} is not a finite number", what, value));
        if (value < lowest) {
            fail(lowest == T(0) ? fmt::format("{} {} is negative", what, value)
                                : fmt::format("{} {} is below {}", what, value, lowest));
        }
        return value;
    }

    // A string field of one value, or a failure saying `what` the file is not.
    std::string string_field(vtkFieldData* fd, const char* name, const char* what) const;
    // A 64-bit unsigned field of one value.
    std::uint64_t count_field(vtkFieldData* fd, const char* name,
                              const char* what = "not an hmcr solution") const;

private:
    std::string m_path;
};

// Checks that `path` is a regular file whose declared sizes fit its bytes (viz/vtp_envelope.h),
// then reads it as PolyData; fails through `check` when VTK cannot.
vtkSmartPointer<vtkPolyData> read_polydata(const std::filesystem::path& path,
                                           const VtpChecker& check);

}  // namespace hmcr
