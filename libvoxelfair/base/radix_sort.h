// Stable LSD radix sort by an unsigned integer key, for the large sorts of the atlas whose
// comparison sorts spent their time on mispredicted branches (random keys: about one branch
// in two mispredicts). Linear time: 8 bits a pass, every digit's histogram taken in one read
// of the items, passes where every item has the same digit skipped (keys of values in a narrow
// range share their top bytes). The order equals std::stable_sort's by the key.
//
// orderedKey maps a double to a key that orders like the value (Herf, "Radix Tricks", 2001):
// the sign bit flipped for positive numbers, every bit for negative ones; -0.0 takes +0.0's key,
// so the two stay equal as they compare. NaN has no place in that order: callers keep it out.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

namespace voxelfair {

inline uint64_t orderedKey(double v) {
    v += 0.0;  // -0.0 -> +0.0
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits >> 63 ? ~bits : bits | (uint64_t(1) << 63);
}

constexpr size_t kInsertionSortItems = 32;

// Sorts `items` by key(item) (an unsigned integer), equal keys keeping their order; `scratch`
// is working room (any contents, reused across calls).
template <class T, class KeyOf>
void radixSortStable(std::vector<T> &items, std::vector<T> &scratch, KeyOf key) {
    using Key = std::decay_t<decltype(key(std::declval<const T &>()))>;
    static_assert(std::is_unsigned_v<Key>, "radixSortStable sorts by an unsigned key");
    constexpr int kDigits = int(sizeof(Key));
    const size_t n = items.size();
    if (n <= kInsertionSortItems) {  // a few: an insertion sort (stable) beats the histograms
        for (size_t i = 1; i < n; ++i) {
            T item = items[i];
            const Key k = key(item);
            size_t j = i;
            for (; j > 0 && k < key(items[j - 1]); --j)
                items[j] = items[j - 1];
            items[j] = item;
        }
        return;
    }
    size_t count[kDigits][256] = {};
    for (const T &item : items) {
        const Key k = key(item);
        for (int d = 0; d < kDigits; ++d)
            ++count[d][(k >> (8 * d)) & 0xFF];
    }
    scratch.resize(n);
    for (int d = 0; d < kDigits; ++d) {
        size_t *digit = count[d];
        if (std::find(digit, digit + 256, n) != digit + 256)
            continue;  // every item has this digit
        size_t at = 0;
        for (size_t v = 0; v < 256; ++v)
            at += std::exchange(digit[v], at);
        for (const T &item : items)
            scratch[digit[(key(item) >> (8 * d)) & 0xFF]++] = item;
        items.swap(scratch);
    }
}

}  // namespace voxelfair
