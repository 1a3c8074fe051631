// Tangent-space normal map baking, the "normal maps" of the paper's future work (section 6):
// the shading of a source mesh (the undecimated faired surface) carried onto a target mesh (its
// decimation) through the texture atlas both share.
//
// MeshLab's quadric decimation with texture keeps the atlas' UVs (texture coordinates are part of
// its quadrics), so the target shows, at UV (u, v), the base colour of the source point with the
// same UV. The source triangle under a target texel's UV is where the search for its source
// point starts; the point itself is found by geometry: a walk over the source's triangles
// (surface_walk.h: the projection onto the local sheet, or the closest facing point where the
// target is well off the source or the sheet faces away from the target's shading normal, the
// far side of a fold). Where the projection falls inside the previous texel's source triangle,
// near it and facing the texel's way (most texels), that is the answer at once; else, in turn,
// the triangle across the edge the projection left that one by (the walk's first step: a row
// crosses a source triangle every few texels) and the triangle under the texel's UV; else the
// walk from the previous texel's triangle (for a triangle's first texel, from the one under its
// UV). The source's interpolated vertex normal n there is what the texel encodes. The target
// triangle under the texel gives the shading frame a glTF / Blender /
// MikkTSpace pixel shader rebuilds there: N and T interpolated from the target's vertex normals
// and MikkTSpace tangents (mikktspace.h) and normalised, B = w * cross(N, T). The texel stores
// the unit solution of x T + y B + z N = n (the exact inverse of that shader), as (c + 1) / 2 in
// RGB: +X along increasing u, +Y along increasing v (OpenGL / glTF / Blender convention: v up,
// green up in the image).
//
// Coverage follows the base colour bake (atlas/bake.h): texel centres inside a target triangle
// first, then texels a triangle merely overlaps; then `dilation` rings of texels around the
// charts take the renormalised mean of their painted neighbours, and on a layout of 2 x 2 blocks
// the blocks are filled (the gutter, NormalBakeOptions). Texels no target
// triangle touches keep the flat normal (0, 0, 1).
//
// The texture is split into bands of texel rows baked on `threads` threads (base/parallel_bands.h);
// each band walks from its own starting points, so the map is the same for any thread count.
// Within a band each target triangle's texels are gathered (source normals found one by one),
// then their frames are solved in one branch-free loop the compiler vectorises.
#pragma once

#include "base/huge_page_allocator.h"
#include "base/error.h"
#include "mesh/triangle_mesh.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace voxelfair {

// A triangle mesh (mesh/triangle_mesh.h) with per-vertex normals and per-corner UVs in [0, 1]^2, v up.
struct NormalBakeMesh : TriangleMesh {
    const glm::vec3 *normals = nullptr;  // per vertex, any non-zero length
    const glm::vec2 *wedgeUv = nullptr;  // 3 per face
};

// The view on vectors: one normal per position, 3 indices and 3 UVs per face.
inline NormalBakeMesh normalBakeMesh(const std::vector<glm::vec3> &positions, const std::vector<glm::vec3> &normals,
                                     const std::vector<uint32_t> &triangles, const std::vector<glm::vec2> &wedgeUv) {
    NormalBakeMesh m;
    static_cast<TriangleMesh &>(m) = triangleMesh(positions, triangles);
    m.normals = normals.data();
    m.wedgeUv = wedgeUv.data();
    return m;
}

struct NormalBakeOptions {
    // The atlas' texture in texels (the base colour's: UVs are normalised per axis, so a 2:1
    // atlas gets a 2:1 map); height 0 means width (square).
    int width = 0, height = 0;
    // The map's resolution level, as a mip level of the atlas: 0 the size above; 1 half each side
    // (rounded up), one texel per aligned 2 x 2 texel block of the atlas. The atlas packs its
    // charts on such blocks with whole blocks of gutter between them (atlas/packing.h), so every
    // level-1 texel a chart touches lies in a block of that chart alone: the level-1 map is the
    // atlas' mip 1 of the full-size map's layout, a quarter of its texels and memory. Smooth
    // faired surfaces lose little at level 1 (README: the per-model angle table has both).
    int level = 0;
    // At level 0, a small atlas gets a finer map (same UVs; glTF lets a normalTexture have its own
    // size): each side times the smallest power of two f = 1, 2 or 4 that brings the long side
    // to at least `minSide` texels. Default 1024: atlases of 1024 texels or more on the long side
    // stay 1:1, smaller ones get 2x or 4x (a 300-texel atlas: 4x, 1200). The faired surface
    // turns within an atlas texel where a unit is small (measured, README: the angle table).
    // 0: the atlas' size. Level 1 ignores it. normalMapScale gives f.
    int minSide = 1024;
    // The gutter, as the base colour's (atlas/bake.h): `dilation` rings of atlas texels (f rings
    // of the map's own), then, with `blocks` (an atlas packed on 2 x 2 blocks,
    // PackOptions::mipBlocks, the default) at level 0, the rest of every aligned 2 x 2 block of
    // the atlas (2f x 2f texels of the map) a chart or its rings touch takes the renormalised
    // mean of the block's painted texels, so a box-filtered mip 1 (and every mip down to the
    // atlas' mip 1) never mixes charts. The defaults are the base colour's for the atlas' default
    // gutter of 2.
    int dilation = 1;
    bool blocks = true;
    int threads = 0;  // 0: one per hardware thread
};

struct NormalMap {
    int width = 0, height = 0;
    // width x height RGBA8, rows from the top (v = 1) down like AtlasTexture; alpha 255. A
    // std::vector of bytes whose resize() does not zero them, on huge pages
    // (base/huge_page_allocator.h): the bake writes each texel once, on the thread baking its rows.
    ByteBuffer rgba;
    // The target's MikkTSpace tangents, 3 per face (xyz, w = bitangent sign): the frame the map
    // was baked against, for exporters (glTF TANGENT).
    std::vector<glm::vec4> cornerTangents;
    size_t texelsBaked = 0;          // target texels given a source normal
    size_t texelsWithoutSource = 0;  // target texels left flat (no source face near their UV, or no frame)
};

// The factor f (1, 2 or 4) by which the map's sides exceed the atlas' at level 0 (minSide above);
// 1 at level 1 or with minSide 0.
int normalMapScale(const NormalBakeOptions &options);

// Throws MeshError for empty or inconsistent meshes (no faces, null arrays, indices out of range;
// the message names the source or target mesh) and OptionError for a side outside [1, 16384],
// a level outside [0, 1] or a negative minSide
// (the library's one error style, base/error.h).
NormalMap bakeNormalMap(const NormalBakeMesh &source, const NormalBakeMesh &target, const NormalBakeOptions &options);

// The target's per-corner tangents alone (positions, normals and UVs per corner, as MikkTSpace
// reads them).
std::vector<glm::vec4> targetTangents(const NormalBakeMesh &target);

// Decoding as a shader does: the texel's unit vector in the frame of a target point with
// interpolated normal n and tangent t (w = sign); used by the tests and measures.
glm::vec3 applyNormalMapTexel(glm::vec3 texel, glm::vec3 n, glm::vec4 t);

}  // namespace voxelfair
