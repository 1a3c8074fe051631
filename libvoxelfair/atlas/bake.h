// Stage 3 of the atlas (paper section 4.5 and the authors' diffuse texture, doc/method.md §6g):
// paint the mesh's colours into the packed texture.
//
// Every triangle is rasterised in UV space twice: first the texels whose centre lies inside it
// (each such texel belongs to exactly one face), then the texels it merely overlaps and no
// centre claimed (conservative coverage, so chart edges are fully painted). Then `dilation`
// rings of texels around the charts are filled with the mean of their painted neighbours, so
// bilinear filtering and the first mip levels read chart colours, not background. On a layout
// packed on 2 x 2 blocks (AtlasLayout::block, PackOptions::mipBlocks) the rest of every block
// a chart or its rings touch then takes the mean of the block's painted texels: the blocks
// hold one chart each, so a box-filtered mip level 1 keeps the charts apart too.
//
// Colour sources:
//   * FaceColours (default, crisp): a texel takes the colour of the face it lies in, so a
//     pixel-art model keeps every voxel's exact colour.
//   * VertexColours (the paper's): the smoothed vertex colours of 4.4, interpolated linearly
//     (Gouraud) at each texel centre. The authors splatted samples bilinearly instead and
//     dilated by one texel; the result is the same blend of vertex colours.
// When the chosen source is missing the other is used, and with neither a flat colour
// (AtlasTexture::source and ::note say what was baked).
#pragma once

#include "atlas/atlas_mesh.h"
#include "atlas/packing.h"
#include "base/huge_page_allocator.h"

#include <cstdint>
#include <string>
#include <vector>

#include <glm/gtc/type_precision.hpp>

namespace voxelfair {

enum class BakeSource { FaceColours, VertexColours, FlatColour };

const char *toString(BakeSource source);

struct BakeOptions {
    BakeSource source = BakeSource::FaceColours;
    // Rings of texels filled around every chart. -1: half the layout's gutter, the most that
    // keeps two charts' rings from meeting (gutter 4 -> 2 rings: bilinear filtering needs 1,
    // the first mip level 2; the default gutter 2 on blocks: 1 ring, then the blocks filled).
    int dilation = -1;
    // Texels outside every chart and its rings. Charts and rings are opaque (alpha 255).
    glm::u8vec4 background{0, 0, 0, 0};
    // Used when the mesh has no colours at all.
    glm::u8vec3 flatColour{200, 200, 200};
    // Threads painting the faces, each its own rows (0: one per hardware thread); the texture is
    // the same for any count.
    int threads = 0;
};

struct AtlasTexture {
    int size = 0;  // the width, kept from when textures were always square
    int width = 0, height = 0;
    // width x height RGBA8 texels, rows from the top of the image (v = 1) down, as PNG and QImage
    // store them: texel (x, y) of the layout (y up) is at row height - 1 - y. A ByteBuffer: the
    // bake writes every byte, band by band on the threads that paint them, never zeroing it first.
    ByteBuffer rgba;
    BakeSource source = BakeSource::FaceColours;  // what was actually baked
    int dilation = 0;                             // rings actually filled
    std::string note;                             // why the source differs from the request, if it does

    // The texel at layout coordinates (x, y), y up.
    glm::u8vec4 texel(int x, int y) const {
        const uint8_t *p = &rgba[(size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4];
        return {p[0], p[1], p[2], p[3]};
    }
};

// Throws MeshError when the layout was not packed for this mesh (3 UVs per face, a texture of
// positive size); an empty texture for a mesh without faces and its empty layout.
AtlasTexture bakeTexture(const AtlasMesh &mesh, const AtlasLayout &layout, const BakeOptions &options = {});

}  // namespace voxelfair
