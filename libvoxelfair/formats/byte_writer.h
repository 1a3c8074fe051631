// Little-endian appends to a byte vector (private to the format writers).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace voxelfair {

class ByteWriter {
public:
    std::vector<uint8_t> &bytes() { return bytes_; }
    size_t size() const { return bytes_.size(); }

    void u8(uint8_t v) { bytes_.push_back(v); }
    void u32(uint32_t v) {
        const uint8_t b[4] = {uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)};
        bytes_.insert(bytes_.end(), b, b + 4);
    }
    void i32(int32_t v) { u32(uint32_t(v)); }
    void f32(float v) {
        uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        u32(bits);
    }
    // `text` truncated to `length - 1` bytes, NUL padded: the field always holds a terminator.
    void text(const std::string &text, size_t length) {
        const size_t n = std::min(text.size(), length - 1);
        bytes_.insert(bytes_.end(), text.begin(), text.begin() + std::ptrdiff_t(n));
        bytes_.insert(bytes_.end(), length - n, uint8_t(0));
    }

    // Overwrites 4 bytes at `offset` (for sizes and offsets known only later).
    void patchI32(size_t offset, int32_t v) {
        const uint32_t u = uint32_t(v);
        for (int i = 0; i < 4; ++i)
            bytes_[offset + size_t(i)] = uint8_t(u >> (8 * i));
    }

private:
    std::vector<uint8_t> bytes_;
};

}  // namespace voxelfair
