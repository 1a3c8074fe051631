// Rows of bytes that are 0 or 1 (the charts' block bitmaps, the bakes' painted flags) read eight
// bytes at a time as one little-endian word: byte i of the word is the row's byte 8k + i, so a
// set byte is bit 8i of the word, found by a bit scan and counted by a multiply. The word-at-a-
// time byte scan of SWAR ("SIMD within a register") code, e.g. glibc's strlen.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace voxelfair {

// Every byte of a word 1.
constexpr uint64_t kAllBytesOne = 0x0101010101010101u;

// The index of the lowest set bit of a non-zero word.
inline int lowestSetBit(uint64_t word) {
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctzll(word);
#else
    int i = 0;
    while ((word >> i & 1) == 0)
        ++i;
    return i;
#endif
}

// The index of the highest set bit of a non-zero word.
inline int highestSetBit(uint64_t word) {
#if defined(__GNUC__) || defined(__clang__)
    return 63 - __builtin_clzll(word);
#else
    int i = 63;
    while ((word >> i & 1) == 0)
        --i;
    return i;
#endif
}

// Word k of a row of `width` bytes: its bytes 8k to 8k + 7, zeros past the row's end.
inline uint64_t byteWord(const uint8_t *row, size_t width, size_t k) {
    uint64_t v = 0;
    std::memcpy(&v, row + 8 * k, 8 * k + 8 <= width ? 8 : width - 8 * k);
    return v;
}

// The first and the last set byte (0 to 7) of a non-zero word of 0/1 bytes.
inline int lowestSetByte(uint64_t word) { return lowestSetBit(word) / 8; }
inline int highestSetByte(uint64_t word) { return highestSetBit(word) / 8; }

// How many bytes of a word of 0/1 bytes are set: their sum, gathered in the top byte.
inline size_t setByteCount(uint64_t word) { return size_t((word * kAllBytesOne) >> 56); }

}  // namespace voxelfair
