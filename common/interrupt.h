// SPDX-License-Identifier: Apache-2.0
// Ending a run cleanly on SIGINT (Ctrl-C), SIGTERM (a cluster's time limit) or SIGHUP (its
// terminal closed; ignored under nohup, which asks for that). The signal only raises a flag;
// long work checks it at safe points (between ray batches, probes, study cells, stages) and
// throws Interrupted, whose unwinding removes temporary files, while what is complete stays (a
// study's finished cells). A second signal ends the process at once.
#pragma once

#include <stdexcept>

namespace hmcr {

class Interrupted : public std::runtime_error {
public:
    explicit Interrupted(int signal);
    int signal() const { return m_signal; }

private:
    int m_signal;
};

// Installs the handlers for SIGINT, SIGTERM and SIGHUP, SIGHUP only where it is not ignored (the
// command line does, once).
void install_interrupt_handlers();
// Throws Interrupted if a signal came since the handlers were installed.
void throw_if_interrupted();

}  // namespace hmcr
