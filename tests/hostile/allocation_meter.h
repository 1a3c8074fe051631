// Peak heap use of a piece of code, measured in-process: the hostile-input tests link
// allocation_meter.cpp, which replaces the global operator new and delete with counting versions.
// Only C++ allocations are seen (the readers allocate through std::vector and std::string only).
#pragma once

#include <cstddef>

namespace voxelfair::test {

// Bytes allocated and not yet freed by the whole program.
size_t liveHeapBytes();

// Peak heap use above the level at construction, while the meter lives. Meters do not nest.
class AllocationMeter {
public:
    AllocationMeter();
    ~AllocationMeter();
    AllocationMeter(const AllocationMeter &) = delete;
    AllocationMeter &operator=(const AllocationMeter &) = delete;

    size_t peakBytes() const;

private:
    size_t baseline_;
};

}  // namespace voxelfair::test
