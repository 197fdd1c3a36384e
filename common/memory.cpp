// SPDX-License-Identifier: Apache-2.0
#include "common/memory.h"

#include <fmt/format.h>
#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <fstream>

#include "common/error.h"

namespace hmcr {

std::uint64_t physical_memory_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : 0;
}

// VmHWM, the high-water mark of this process's own address space. getrusage's ru_maxrss is not
// it: Linux counts there also the address space an exec replaced, which for a process started
// by posix_spawn (Python's subprocess, the bench) is its parent's. A Python sweep holding 500 MB
// made a 63 MB solve report 539 MB.
std::uint64_t peak_memory_bytes() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);) {
        if (line.starts_with("VmHWM:")) return std::stoull(line.substr(6)) * 1024;  // in kB
    }
    rusage usage{};  // no /proc: the kernel's figure, which may include the parent's
    getrusage(RUSAGE_SELF, &usage);
    return std::uint64_t(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

void return_freed_memory() {
#ifdef __GLIBC__
    malloc_trim(0);
#endif
}

std::string human_bytes(double bytes) {
    if (bytes >= 1e9) return fmt::format("{:.1f} GB", bytes / 1e9);
    if (bytes >= 1e6) return fmt::format("{:.0f} MB", bytes / 1e6);
    return fmt::format("{:.0f} kB", bytes / 1e3);
}

void require_memory(double bytes, const std::string& what, const std::string& remedy) {
    const double available = 0.75 * double(physical_memory_bytes());
    if (available > 0 && bytes > available) {
        throw InputError(fmt::format(
            "{} would need about {} of memory; this machine has {}{}{}", what, human_bytes(bytes),
            human_bytes(double(physical_memory_bytes())), remedy.empty() ? "" : ": ", remedy));
    }
}

}  // namespace hmcr
