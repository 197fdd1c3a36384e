// SPDX-License-Identifier: Apache-2.0
// The Python module hmcr._core (docs/python.md): what the command line does, with its bits, from
// Python: scenes from files and arrays, solves with every solver setting as a keyword, solutions
// as numpy arrays and files, references, studies, information measures and the path tracer. hmcr
// works with the GIL released; progress calls back into Python, where Ctrl-C stops the work.
#include <pybind11/pybind11.h>

#include "common/error.h"
#include "python/bindings.h"

PYBIND11_MODULE(_core, m) {
    m.doc() = "hmcr's engine: scenes, solves and solutions (docs/python.md)";
    m.attr("__version__") = HMCR_VERSION;
    pybind11::register_exception<hmcr::InputError>(m, "InputError", PyExc_ValueError);
    hmcr::python::bind_scenes(m);
    hmcr::python::bind_solutions(m);
    hmcr::python::bind_studies(m);
    hmcr::python::bind_measures(m);
}
