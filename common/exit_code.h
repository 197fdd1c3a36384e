// SPDX-License-Identifier: Apache-2.0
// Exit codes (docs/usage.md#bad-input): 0 done, 2 bad input (anything the user can fix), 1 a fault
// of hmcr, 128 + N after signal N. One mapping for the command line and for MPI ranks, which relay
// a failure to the others (ranks.h).
#pragma once

#include <exception>
#include <string>

namespace hmcr {

struct Failure {
    int exit_code = 1;
    std::string message;  // as the command line prints it after "hmcr: error: "
};

Failure failure_of(const std::exception_ptr& e);

}  // namespace hmcr
