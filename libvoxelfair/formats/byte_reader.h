// Bounds-checked little-endian reads from a byte array (private to the format readers).
// Every read checks its range first, so a corrupt offset becomes a FormatError, never an
// out-of-bounds access.
#pragma once

#include "formats/format_error.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace voxelfair {

class ByteReader {
public:
    ByteReader(const uint8_t *data, size_t size) : data_(data), size_(size) {}

    size_t size() const { return size_; }

    // True when bytes [offset, offset + count) lie inside the data (written to avoid overflow).
    bool fits(uint64_t offset, uint64_t count) const { return offset <= size_ && count <= size_ - offset; }

    // Throws "<what> at byte offset <offset> needs <count> bytes but the data ends at byte <size>".
    void require(uint64_t offset, uint64_t count, const char *what) const {
        if (!fits(offset, count))
            throw FormatError(std::string("truncated: ") + what + " at byte offset " + std::to_string(offset) +
                              " needs " + std::to_string(count) + " bytes but the data ends at byte " +
                              std::to_string(size_));
    }

    // Pointer to `count` checked bytes at `offset`, for loops that then read them directly.
    const uint8_t *bytes(uint64_t offset, uint64_t count, const char *what) const {
        require(offset, count, what);
        return data_ + offset;
    }

    uint8_t u8(uint64_t offset, const char *what) const { return *bytes(offset, 1, what); }
    uint32_t u32(uint64_t offset, const char *what) const { return load32(bytes(offset, 4, what)); }
    int32_t i32(uint64_t offset, const char *what) const { return int32_t(u32(offset, what)); }
    float f32(uint64_t offset, const char *what) const {
        const uint32_t bits = u32(offset, what);
        float value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
    }

    // NUL-terminated text of at most `length` bytes (names in fixed-size fields).
    std::string text(uint64_t offset, size_t length, const char *what) const {
        const char *p = reinterpret_cast<const char *>(bytes(offset, length, what));
        return std::string(p, strnlen(p, length));
    }

    // Little-endian regardless of the host, and without alignment assumptions.
    static uint32_t load32(const uint8_t *p) {
        return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
    }

private:
    const uint8_t *data_;
    size_t size_;
};

}  // namespace voxelfair
