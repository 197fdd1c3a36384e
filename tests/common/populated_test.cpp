// SPDX-License-Identifier: Apache-2.0
#include "common/populated.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

namespace hmcr::test {
namespace {

// Growing keeps what the vector held and value-initialises the rest, as resize does; shrinking
// and growing within the capacity keep the block.
TEST(Populated, ResizeKeepsTheElementsAndZeroesTheNewOnes) {
    std::vector<std::uint64_t> v(1000);
    std::iota(v.begin(), v.end(), 1);
    resize_populated(v, 300'000);  // a new block of 2.4 MB
    ASSERT_EQ(v.size(), 300'000u);
    for (std::size_t k = 0; k < v.size(); ++k) {
        ASSERT_EQ(v[k], k < 1000 ? k + 1 : 0) << k;
    }
    const std::uint64_t* block = v.data();
    resize_populated(v, 10);
    resize_populated(v, 200'000);
    EXPECT_EQ(v.data(), block);
    EXPECT_EQ(v[9], 10u);
    EXPECT_EQ(v[10], 0u);
    std::vector<char> empty;
    resize_populated(empty, 0);
    EXPECT_TRUE(empty.empty());
}

// Reserving keeps the elements in a block of at least the room asked for, and a reserve within
// the capacity keeps the block.
TEST(Populated, ReserveKeepsTheElements) {
    std::vector<std::uint32_t> v(777);
    std::iota(v.begin(), v.end(), 3);
    reserve_populated(v, 100'000);
    ASSERT_EQ(v.size(), 777u);
    EXPECT_GE(v.capacity(), 100'000u);
    for (std::size_t k = 0; k < v.size(); ++k) ASSERT_EQ(v[k], k + 3) << k;
    const std::uint32_t* block = v.data();
    reserve_populated(v, 50'000);
    resize_populated(v, 100'000);
    EXPECT_EQ(v.data(), block);
    EXPECT_EQ(v[776], 779u);
    EXPECT_EQ(v[777], 0u);
}

// Populating is advice: any range, page-aligned or not, empty or within one page, leaves the
// memory's contents as they were.
TEST(Populated, PopulatingLeavesTheContents) {
    std::vector<unsigned char> bytes(3 * 4096 + 123);
    for (std::size_t k = 0; k < bytes.size(); ++k) bytes[k] = static_cast<unsigned char>(k * 7);
    populate_pages(bytes.data() + 5, bytes.size() - 9);
    populate_pages(bytes.data() + 1, 10);
    populate_pages(bytes.data(), 0);
    for (std::size_t k = 0; k < bytes.size(); ++k) {
        ASSERT_EQ(bytes[k], static_cast<unsigned char>(k * 7)) << k;
    }
}

}  // namespace
}  // namespace hmcr::test
