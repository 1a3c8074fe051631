// Westwood HVA: per-frame, per-section 3x4 matrices that place VXL sections (Westwood HVA, doc/formats/westwood.md §9).
#pragma once

#include "formats/vxl.h"

#include <string>
#include <vector>

namespace voxelfair {

struct HvaAnimation {
    int frameCount = 0;
    std::vector<std::string> sectionNames;
    std::vector<Matrix3x4> matrices;  // frame-major, section-fastest: matrices[frame * sections + section]

    int sectionCount() const { return int(sectionNames.size()); }
    const Matrix3x4 &matrix(int frame, int section) const {
        return matrices[size_t(frame) * sectionNames.size() + size_t(section)];
    }
};

// Throws FormatError on a bad size, zero frames or sections, or non-finite matrix entries.
HvaAnimation readHva(const uint8_t *data, size_t size);
// Throws FormatError unless there are frameCount * sections matrices and at least one of each.
std::vector<uint8_t> writeHva(const HvaAnimation &animation);

}  // namespace voxelfair
