// SPDX-License-Identifier: Apache-2.0
#include "viz/vtk_console.h"

#include <vtkLogger.h>
#include <vtkObject.h>

namespace hmcr {

void silence_vtk_console() {
    vtkObject::GlobalWarningDisplayOff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

}  // namespace hmcr
