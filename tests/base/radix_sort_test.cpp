// base/radix_sort.h: the radix sort orders like std::stable_sort by the key, on families of keys
// (full range, a narrow range whose top bytes are all equal, many duplicates, special doubles),
// and orderedKey orders doubles like their values.
#include "base/radix_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace voxelfair {
namespace {

struct Item {
    double value;
    uint32_t index;  // its place before sorting
};

std::vector<double> family(int kind, size_t n, std::mt19937 &rng) {
    std::vector<double> v(n);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> few(-3, 3);
    for (double &x : v) {
        switch (kind) {
        case 0:  // thin faces' inradii: (0, 1.42), top bytes shared
            x = 1.42 * unit(rng);
            break;
        case 1:  // both signs, many magnitudes
            x = (unit(rng) - 0.5) * std::pow(10.0, 12 * unit(rng) - 6);
            break;
        case 2:  // a few values, many ties
            x = few(rng) * 0.25;
            break;
        default: {  // special values among ordinary ones
            const double specials[] = {0.0,
                                       -0.0,
                                       std::numeric_limits<double>::infinity(),
                                       -std::numeric_limits<double>::infinity(),
                                       std::numeric_limits<double>::denorm_min(),
                                       -std::numeric_limits<double>::denorm_min(),
                                       std::numeric_limits<double>::max(),
                                       std::numeric_limits<double>::lowest(),
                                       1.0,
                                       -1.0};
            x = unit(rng) < 0.5 ? specials[rng() % 10] : unit(rng) - 0.5;
        }
        }
    }
    return v;
}

TEST(RadixSort, DoublesSortLikeAStableSortByValue) {
    std::mt19937 rng(20261127);
    std::vector<Item> scratch;  // reused across calls, as callers do
    for (int kind = 0; kind < 4; ++kind)
        for (size_t n : {size_t(0), size_t(1), size_t(2), size_t(17), size_t(1000), size_t(50000)}) {
            const std::vector<double> values = family(kind, n, rng);
            std::vector<Item> items(n);
            for (size_t i = 0; i < n; ++i)
                items[i] = {values[i], uint32_t(i)};
            std::vector<Item> expected = items;
            std::stable_sort(expected.begin(), expected.end(),
                             [](const Item &a, const Item &b) { return a.value < b.value; });
            radixSortStable(items, scratch, [](const Item &t) { return orderedKey(t.value); });
            ASSERT_EQ(items.size(), n);
            for (size_t i = 0; i < n; ++i)
                ASSERT_EQ(items[i].index, expected[i].index) << "family " << kind << ", " << n << " items, at " << i;
        }
}

TEST(RadixSort, OrderedKeyOrdersLikeTheValue) {
    std::mt19937 rng(7);
    const std::vector<double> values = family(3, 4000, rng);
    for (size_t i = 0; i + 1 < values.size(); ++i) {
        const double a = values[i], b = values[i + 1];
        EXPECT_EQ(a < b, orderedKey(a) < orderedKey(b)) << a << " " << b;
        EXPECT_EQ(a == b, orderedKey(a) == orderedKey(b)) << a << " " << b;
    }
    EXPECT_EQ(orderedKey(0.0), orderedKey(-0.0));
}

TEST(RadixSort, IntegerKeysOfEveryWidth) {
    std::mt19937 rng(11);
    std::vector<uint32_t> scratch32;
    std::vector<uint64_t> scratch64;
    for (size_t n : {size_t(3), size_t(300), size_t(30000)}) {
        std::vector<uint32_t> small(n);
        std::vector<uint64_t> wide(n);
        for (size_t i = 0; i < n; ++i) {
            small[i] = uint32_t(rng()) >> (i % 3 == 0 ? 0 : 20);  // some keys use every byte
            wide[i] = (uint64_t(rng()) << 32 | rng()) >> (rng() % 64);
        }
        std::vector<uint32_t> small2 = small;
        std::vector<uint64_t> wide2 = wide;
        std::sort(small2.begin(), small2.end());
        std::sort(wide2.begin(), wide2.end());
        radixSortStable(small, scratch32, [](uint32_t k) { return k; });
        radixSortStable(wide, scratch64, [](uint64_t k) { return k; });
        EXPECT_EQ(small, small2);
        EXPECT_EQ(wide, wide2);
    }
    // Keys that order on the byte a skipped pass would hold: all equal but the lowest byte.
    std::vector<uint32_t> keys = {0x12345603, 0x12345601, 0x12345602}, scratch;
    radixSortStable(keys, scratch, [](uint32_t k) { return k; });
    EXPECT_EQ(keys, (std::vector<uint32_t>{0x12345601, 0x12345602, 0x12345603}));
}

}  // namespace
}  // namespace voxelfair
