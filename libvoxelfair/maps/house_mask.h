// The house colour mask of a Westwood VXL model: which texels of the atlas show a voxel painted
// with the palette's remap range (indices 16..31), the colours Tiberian Sun and Red Alert 2 tint
// per player ("house colours"; ModEnc: "Palette", "Remap"). An engine re-tints those texels and
// keeps the others; the base colour keeps the palette's own colours.
//
// The mask is baked in the base colour's atlas layout (face_value_bake.h): a texel is 255 where
// the face whose voxel colours it has a remap index, 0 elsewhere, and the gutter rings carry the
// mean of their chart neighbours (a soft edge for bilinear sampling, as the base colour's).
#pragma once

#include "maps/face_value_bake.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace voxelfair {

constexpr uint8_t kFirstRemapIndex = 16;
constexpr uint8_t kLastRemapIndex = 31;

inline bool isRemapIndex(uint8_t paletteIndex) {
    return paletteIndex >= kFirstRemapIndex && paletteIndex <= kLastRemapIndex;
}

struct HouseMask {
    int width = 0, height = 0;
    std::vector<uint8_t> grey;  // width x height, rows from the top (v = 1) down, as PNG stores them
    size_t houseFaces = 0;      // faces with a remap index
    size_t houseTexels = 0;     // texels at 255 (charts only, before the gutter)

    uint8_t texel(int x, int y) const { return grey[size_t(height - 1 - y) * size_t(width) + size_t(x)]; }
};

// `facePaletteIndex` holds each face's voxel palette index; the gutter (`dilation`, `blocks`) as
// bakeFaceValues'. Throws as bakeFaceValues does.
HouseMask bakeHouseMask(const FaceValueMesh &mesh, const uint8_t *facePaletteIndex, int width, int height, int dilation,
                        bool blocks = false);

}  // namespace voxelfair
