// SPDX-License-Identifier: Apache-2.0
// Python's side of hmcr's long work: progress told to a Python callable, where Ctrl-C is seen,
// and the work run with the GIL released and the caller's floating-point mode kept.
#pragma once

#include <pybind11/pybind11.h>
#include <xmmintrin.h>

#include <csignal>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "common/interrupt.h"
#include "common/progress.h"

namespace hmcr::python {

namespace py = pybind11;

// Progress told to a Python callable, callback(stage, fraction), with Python's signals checked
// at each call: an exception there (KeyboardInterrupt from Ctrl-C, or the callback's own) stops
// the work at its next safe point as Interrupted does on the command line, and is raised again
// once the work has unwound.
class PythonProgress final : public Progress {
public:
    explicit PythonProgress(py::object callback) : m_callback(std::move(callback)) {}
    void stage(std::string_view label) override {
        m_stage = label;
        call(0);
    }
    void advance(double fraction) override { call(fraction); }
    void note(std::string_view) override {}

    // With the GIL held: raises the Python exception that stopped the work, if one did.
    void raise_if_stopped() {
        if (!m_error) return;
        m_error->restore();
        m_error.reset();
        throw py::error_already_set();
    }

private:
    void call(double fraction) {
        const py::gil_scoped_acquire gil;
        try {
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            if (!m_callback.is_none()) m_callback(m_stage, fraction);
        } catch (py::error_already_set& e) {
            m_error.emplace(std::move(e));
            throw Interrupted(SIGINT);
        }
    }

    py::object m_callback;
    std::string m_stage;
    std::optional<py::error_already_set> m_error;
};

// The caller's floating-point mode, given back when a call ends: hmcr's tracing flushes
// subnormal numbers to zero in the threads that trace (rays/embree_scene.h), the caller's among
// them, and Python's own arithmetic (numpy's) must not inherit that.
class CallersFloatMode {
public:
    CallersFloatMode() : m_csr(_mm_getcsr()) {}
    ~CallersFloatMode() { _mm_setcsr(m_csr); }
    CallersFloatMode(const CallersFloatMode&) = delete;
    CallersFloatMode& operator=(const CallersFloatMode&) = delete;

private:
    unsigned m_csr;
};

// Runs work(progress) with the GIL released and the caller's floating-point mode kept, telling
// its progress to `callback` (None: only Python's signals are checked); an exception Python
// raised there is raised again once the work has unwound.
template <class Work>
auto run_released(py::object callback, Work&& work) {
    PythonProgress told(std::move(callback));
    try {
        const CallersFloatMode mode;
        const py::gil_scoped_release released;
        return work(static_cast<Progress&>(told));
    } catch (const Interrupted&) {
        told.raise_if_stopped();
        throw;
    }
}

}  // namespace hmcr::python
