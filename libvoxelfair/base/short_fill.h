// Bytes set to one value, written inline: the spans that rasterisers fill are mostly a few
// bytes long, where a call into libc's memset costs more than the stores (on the 2048^2
// tank atlas, 0.6 million spans per bake and about 1 million per chart bitmap pass). Short
// runs take two overlapping stores of 1, 2, 4 or 8 bytes, the technique of libc memsets'
// own small-size paths; longer ones still go to memset. And the test whether such a run is
// whole (every byte 1), eight bytes at a time, and the rows of a box that are not.
#pragma once

#include "base/byte_words.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace voxelfair {

inline void fillBytes(uint8_t *p, uint8_t value, size_t n) {
    if (n > 16) {
        std::memset(p, value, n);
        return;
    }
    const uint64_t v8 = uint64_t(value) * kAllBytesOne;
    if (n >= 8) {
        std::memcpy(p, &v8, 8);
        std::memcpy(p + n - 8, &v8, 8);
    } else if (n >= 4) {
        const uint32_t v4 = uint32_t(v8);
        std::memcpy(p, &v4, 4);
        std::memcpy(p + n - 4, &v4, 4);
    } else if (n >= 2) {
        const uint16_t v2 = uint16_t(v8);
        std::memcpy(p, &v2, 2);
        std::memcpy(p + n - 2, &v2, 2);
    } else if (n == 1) {
        *p = value;
    }
}

// Whether all n bytes at p are 1 (bytes holding 0 or 1: painted or set flags). Short runs
// take two overlapping loads, as fillBytes.
inline bool allOnes(const uint8_t *p, size_t n) {
    if (n >= 8) {
        for (size_t i = 0; i + 8 < n; i += 8) {
            uint64_t v;
            std::memcpy(&v, p + i, 8);
            if (v != kAllBytesOne)
                return false;
        }
        uint64_t v;
        std::memcpy(&v, p + n - 8, 8);
        return v == kAllBytesOne;
    }
    if (n >= 4) {
        uint32_t a, b;
        std::memcpy(&a, p, 4);
        std::memcpy(&b, p + n - 4, 4);
        return a == 0x01010101u && b == 0x01010101u;
    }
    if (n >= 2) {
        uint16_t a, b;
        std::memcpy(&a, p, 2);
        std::memcpy(&b, p + n - 2, 2);
        return a == 0x0101u && b == 0x0101u;
    }
    return n == 0 || p[0] == 1;
}

// The first and last of rows y0..y1 whose `length` flags from rowAt(y) are not all 1: first >
// last when every row is whole. Rows known to be whole add nothing to a raster of flags, so
// rasterisers skip to the rows between (the chart masks' blocks, the crisp bake's overlaps).
template <class RowAt>
inline void unsetRowRange(RowAt &&rowAt, size_t length, int y0, int y1, int &first, int &last) {
    first = y0;
    while (first <= y1 && allOnes(rowAt(first), length))
        ++first;
    last = y1;
    while (last > first && allOnes(rowAt(last), length))
        --last;
}

}  // namespace voxelfair
