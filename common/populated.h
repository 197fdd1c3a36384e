// SPDX-License-Identifier: Apache-2.0
// Growing a buffer whose every element is about to be written, with its new pages faulted in by
// one system call instead of one page fault a page as the elements are written: on the virtual
// machine hmcr is measured on, that halves what the kernel spends on them (docs/performance.md,
// "Where the time goes").
#pragma once

#include <cstddef>
#include <iterator>
#include <vector>

namespace hmcr {

// Asks the kernel to map the whole pages of [p, p + bytes) now, writable (MADV_POPULATE_WRITE);
// advice only: a kernel without it leaves them to be faulted in as before.
void populate_pages(void* p, std::size_t bytes);

// v.reserve(n), the new block (if it needs one) populated before v's elements move into it.
template <class T>
void reserve_populated(std::vector<T>& v, std::size_t n) {
    if (n <= v.capacity()) return;
    std::vector<T> grown;
    grown.reserve(n);
    // NOLINTNEXTLINE(bugprone-sizeof-expression): n elements' bytes, whatever T is (a pointer too)
    populate_pages(grown.data(), n * sizeof(T));
    grown.insert(grown.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
    v.swap(grown);
}

// v.resize(n), its new block (if it needs one) populated first.
template <class T>
void resize_populated(std::vector<T>& v, std::size_t n) {
    reserve_populated(v, n);
    v.resize(n);
}

}  // namespace hmcr
