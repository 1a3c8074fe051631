// Work memory for one call of fairConstrained: arrays carved out of a few big blocks that are
// reused between calls.
//
// Contract: take<T>(n) returns n default-initialized (for trivial types: uninitialized) elements
// starting on a 64-byte line; the arrays stay valid until the arena dies or is rewound past them.
// mark() / rewind(mark): the arrays taken since the mark are dead and their room serves the next
// ones. When a block is full, a new block is added and the arrays already taken stay where they
// are.
//
// Why: many vectors would each be mapped and faulted in anew on every call (the allocator hands big
// blocks back to the system); a few blocks of the same sizes are kept and reused by the allocator
// (benchmarks/fairing_benchmark shows the page faults otherwise).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace voxelfair::constrained {

class Arena {
public:
    explicit Arena(size_t bytes) { addBlock(bytes); }
    template <class T>
    T *take(size_t count) {
        if (used_ + bytes<T>(count) > size_)
            addBlock(bytes<T>(count));  // more than expected: the arrays already taken stay where they are
        T *items = reinterpret_cast<T *>(block_ + used_);
        std::uninitialized_default_construct_n(items, count);
        used_ += bytes<T>(count);
        return items;
    }
    struct Mark {
        size_t block, used;
    };
    Mark mark() const { return {blocks_.size() - 1, used_}; }
    void rewind(Mark mark) {
        block_ = blockStart(mark.block);
        size_ = sizes_[mark.block];
        used_ = mark.used;
    }
    // Bytes taken by `count` elements of T.
    template <class T>
    static size_t bytes(size_t count) {
        return (sizeof(T) * count + 63) & ~size_t(63);
    }

private:
    // Arrays start on 64-byte lines (whole-register loads need 16). Plain new, aligned by hand:
    // the allocator reuses a freed block of the same size for it (not always so with aligned new).
    void addBlock(size_t bytes) {
        blocks_.emplace_back(new std::byte[bytes + 63]);  // not zeroed
        sizes_.push_back(bytes);
        const uintptr_t start = reinterpret_cast<uintptr_t>(blocks_.back().get());
        block_ = blocks_.back().get() + ((64 - start % 64) % 64);
        size_ = bytes;
        used_ = 0;
    }
    std::byte *blockStart(size_t block) const {
        const uintptr_t start = reinterpret_cast<uintptr_t>(blocks_[block].get());
        return blocks_[block].get() + ((64 - start % 64) % 64);
    }
    std::vector<std::unique_ptr<std::byte[]>> blocks_;
    std::vector<size_t> sizes_;
    std::byte *block_ = nullptr;
    size_t size_ = 0, used_ = 0;
};

}  // namespace voxelfair::constrained
