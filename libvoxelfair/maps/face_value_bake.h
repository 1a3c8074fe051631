// Per-face values baked into the texture atlas' layout exactly as the base colour is: the house
// colour mask, the material maps (paper §6's "material maps"; house_mask.h, material_maps.h).
//
// A value is an RGB triple per face, painted by the atlas' own crisp bake (atlas/bake.h, face
// colours): the texels whose centre a face holds, then the texels it merely overlaps, the faces
// too thin for the centre rule over their interior points, then `dilation` gutter rings with the
// mean of their painted neighbours, and with `blocks` (an atlas packed on 2 x 2 blocks, the
// atlas' default) the rest of every block a chart or its rings touch with the block's mean, as
// the base colour does, so mip level 1 keeps the charts apart too. So every texel of every map belongs to the face whose voxel
// colours it in the base colour texture, and a map lines up with the base colour texel for texel.
//
// Throws MeshError for inconsistent arrays (null arrays, indices out of range) and OptionError for
// a size outside 1..16384 or a negative dilation.
#pragma once

#include "base/huge_page_allocator.h"
#include "mesh/triangle_mesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/gtc/type_precision.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace voxelfair {

// A textured triangle mesh: the atlas' input arrays and its per-corner UVs (v up, [0, 1]^2).
struct FaceValueMesh : TriangleMesh {
    const glm::vec2 *wedgeUv = nullptr;  // 3 per face
};

struct FaceValueImage {
    int width = 0, height = 0;
    // width x height RGBA8, rows from the top (v = 1) down as PNG stores them, like AtlasTexture;
    // alpha 255 on charts and their rings, 0 elsewhere.
    ByteBuffer rgba;

    // The texel at layout coordinates (x, y), y up.
    glm::u8vec4 texel(int x, int y) const {
        const uint8_t *p = &rgba[(size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4];
        return {p[0], p[1], p[2], p[3]};
    }
};

// `faceValues` holds one triple per face; texels outside every chart and ring stay `background`.
FaceValueImage bakeFaceValues(const FaceValueMesh &mesh, const glm::u8vec3 *faceValues, int width, int height,
                              int dilation, glm::u8vec3 background = {0, 0, 0}, bool blocks = false);

}  // namespace voxelfair
