// Westwood VXL (Command & Conquer: Tiberian Sun, Red Alert 2) reader and writer.
// Byte layout: the community VXL format (ra2ff; doc/formats/westwood.md §1-5). Voxel coordinates are those of the file (Westwood space:
// x, y horizontal, z up); voxel (x, y, z) is the unit cube [x, x+1] x [y, y+1] x [z, z+1].
#pragma once

#include "formats/palette.h"
#include "volume/voxel_volume.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace voxelfair {

// A 3x4 affine matrix as VXL and HVA files store it: row-major, (r00 r01 r02 tx, r10 ..., r20 ...).
using Matrix3x4 = std::array<float, 12>;
constexpr Matrix3x4 kIdentity3x4 = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

enum class VxlNormalType : uint8_t { TiberianSun = 2, RedAlert2 = 4 };
constexpr int kTiberianSunNormalCount = 36;
constexpr int kRedAlert2NormalCount = 244;

struct VxlSection {
    std::string name;
    VoxelVolume volume;
    float scale = 1.0f / 12.0f;          // "Det": scales HVA translations; 0 in a file is read as 1 (the editor's rule)
    Matrix3x4 transform = kIdentity3x4;  // the tailer matrix (translation already scaled)
    glm::vec3 minBounds{0.0f};
    glm::vec3 maxBounds{0.0f};
    // The file's normal type byte: 2 is Tiberian Sun (36 normals); 4, and anything else, Red Alert 2 (244).
    uint8_t normalType = 4;
    // Voxels whose normal index was past the table and was clamped to its last entry.
    size_t clampedNormals = 0;

    // Voxel-to-model scale per axis: (maxBounds - minBounds) / size, or 1 where that is degenerate.
    glm::vec3 voxelScale() const;
};

struct VxlModel {
    std::vector<VxlSection> sections;
    Palette embeddedPalette;  // 8 bits per channel; all zeros in many community files
    uint8_t remapFirst = kHouseColourFirst;
    uint8_t remapLast = kHouseColourLast;
};

// Parses a whole .vxl file. Throws FormatError naming the problem (bad magic, including the
// Ace of Spades maps that share the extension; truncation; offsets out of range; a run whose
// repeated count differs; a run past the column height; zero sizes; more columns than one per
// eight bytes of the file or more voxels than one per two, which only sections or columns sharing
// their span arrays or data can reach; ...). Never reads out of bounds, and allocates in
// proportion to the file's size.
VxlModel readVxl(const uint8_t *data, size_t size);

// Serialises a model (used by the tests' fixtures and the bundled example). Sections are written
// in the contiguous layout the editor uses; the result reads back to an equal model (names are
// cut to 15 characters, a scale of 0 reads back as 1). Throws FormatError for a model the format
// cannot hold: no sections, or a side outside 1..255.
std::vector<uint8_t> writeVxl(const VxlModel &model);

}  // namespace voxelfair
