// Fixed sizes and constants of the VXL layout shared by the reader and the writer (Westwood VXL §1-4, doc/formats/westwood.md).
#pragma once

#include <cstddef>

namespace voxelfair {
namespace vxl {

constexpr size_t kHeaderBytes = 802;
constexpr size_t kSectionHeaderBytes = 28;
constexpr size_t kTailerBytes = 92;
constexpr size_t kNameBytes = 16;
constexpr size_t kPaletteOffset = 34;
constexpr int kMaxSide = 255;  // sizes, skips and counts are bytes

constexpr char kMagic[] = "Voxel Animation";  // then a NUL; readers compare these 15 characters
constexpr size_t kMagicLength = sizeof kMagic - 1;

constexpr int kEmptyColumn = -1;  // spanStart and spanEnd of a column without voxels

}  // namespace vxl
}  // namespace voxelfair
