// SPDX-License-Identifier: Apache-2.0
#include "common/interrupt.h"

#include <csignal>
#include <cstring>
#include <string>

namespace hmcr {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int signal) {
    if (g_signal != 0) {  // the second one: stop now
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    g_signal = signal;
}

const char* signal_name(int signal) {
    switch (signal) {
        case SIGTERM:
            return "SIGTERM";
        case SIGHUP:
            return "SIGHUP";
        default:
            return "SIGINT";
    }
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") + signal_name(signal)), m_signal(signal) {}

void install_interrupt_handlers() {
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    // A hang-up (the terminal or the ssh session closed) ends a run as SIGTERM does, unless the
    // run was started to outlive it (nohup, which leaves SIGHUP ignored).
    struct sigaction hangup {};
    if (sigaction(SIGHUP, nullptr, &hangup) == 0 && hangup.sa_handler != SIG_IGN) {
        sigaction(SIGHUP, &action, nullptr);
    }
}

void throw_if_interrupted() {
    if (g_signal != 0) throw Interrupted(g_signal);
}

}  // namespace hmcr
