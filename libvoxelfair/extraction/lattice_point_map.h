// Open-addressing hash map from a lattice point to the vertices made for it (internal to the
// extraction). Every boundary quad looks up its four corners here, so it is kept minimal: packed
// 64-bit keys, linear probing, no erase.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace voxelfair {

class LatticePointMap {
public:
    struct Entry {
        uint64_t key;
        uint32_t firstVertex;  // the point's sheets own firstVertex .. firstVertex + sheetCount - 1
        uint8_t config;        // solid cells around the point (lattice_vertex_sheets.h)
        bool joined;           // its pinched half-edge is joined (LatticeVertexConfig::joined)
    };

    // Lattice coordinates are below 2^16 (kMaxVolumeSide + 1 points per side).
    static uint64_t key(int x, int y, int z) { return uint64_t(x) | uint64_t(y) << 16 | uint64_t(z) << 32; }

    explicit LatticePointMap(size_t expectedPoints) { allocate(capacityFor(expectedPoints)); }

    // The entry for `key` and true when it was just inserted (the caller then fills it). The
    // pointer is valid until the next insertion.
    std::pair<Entry *, bool> insert(uint64_t key) {
        if (2 * (size_ + 1) > slots_.size())
            grow();
        size_t i = slotIndex(key);
        while (slots_[i].key != key) {
            if (slots_[i].key == kEmpty) {
                slots_[i].key = key;
                ++size_;
                return {&slots_[i], true};
            }
            i = (i + 1) & mask_;
        }
        return {&slots_[i], false};
    }

    // The entry for `key`, or nullptr when it was never inserted.
    const Entry *find(uint64_t key) const {
        for (size_t i = slotIndex(key);; i = (i + 1) & mask_) {
            if (slots_[i].key == key)
                return &slots_[i];
            if (slots_[i].key == kEmpty)
                return nullptr;
        }
    }

    size_t size() const { return size_; }

private:
    static constexpr uint64_t kEmpty = ~uint64_t(0);

    static size_t capacityFor(size_t points) {
        size_t capacity = 16;
        while (capacity < 2 * points)
            capacity *= 2;  // load factor at most 1/2
        return capacity;
    }

    void allocate(size_t capacity) {
        slots_.assign(capacity, Entry{kEmpty, 0, 0, false});
        mask_ = capacity - 1;
        shift_ = 64;
        for (size_t c = capacity; c > 1; c /= 2)
            --shift_;
    }

    // The lattice column (x, y) is Fibonacci-hashed and z added: a column's points get
    // consecutive slots, and quads visit them column by column, so lookups stay in cache
    // (on large noisy models a third faster than hashing z too).
    size_t slotIndex(uint64_t key) const {
        const uint64_t column = key & 0xFFFFFFFFull;
        return (size_t((column * 0x9E3779B97F4A7C15ull) >> shift_) + size_t(key >> 32)) & mask_;
    }

    void grow() {
        std::vector<Entry> old;
        old.swap(slots_);
        allocate(old.size() * 2);
        for (const Entry &e : old) {
            if (e.key == kEmpty)
                continue;
            size_t i = slotIndex(e.key);
            while (slots_[i].key != kEmpty)
                i = (i + 1) & mask_;
            slots_[i] = e;
        }
    }

    std::vector<Entry> slots_;
    size_t size_ = 0;
    size_t mask_ = 0;
    int shift_ = 64;
};

}  // namespace voxelfair
