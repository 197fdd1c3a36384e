// SPDX-License-Identifier: Apache-2.0
#include "common/populated.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

namespace hmcr {

void populate_pages(void* p, std::size_t bytes) {
#ifdef MADV_POPULATE_WRITE
    static const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t begin = (at + page - 1) & ~(page - 1), end = (at + bytes) & ~(page - 1);
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
    (void)p;
    (void)bytes;
#endif
}

}  // namespace hmcr
