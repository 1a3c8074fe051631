// Where the source's triangles lie in the target's UV space, for the normal bake (normal_bake.h):
// the bake's mapping reversed. The bake finds, for each target texel, the source point its
// target point projects onto (surface_walk.h), one walk or test per texel. Here each source
// VERTEX is carried onto the target once instead: from the target face under its UV (the atlas
// both share), along its normal, across the target's triangles (the walk of surface_walk.h,
// stepping by the ray's crossing of each face's plane) to the target point whose projection back
// onto the source is, to first order, the vertex itself; its target UV follows from the face's
// corners. A source triangle whose three corners land on one target chart, facing the way the
// source does, unflipped in UV, of at most 64 texels in UV (within 4x of its carried area), then
// covers the target texels inside its carried UV triangle, each with the source normal
// interpolated at its weights there (a linear map of the texel's UV onto the source triangle,
// exact at its corners: over a larger triangle, as a small atlas' finer map gives, the linear
// map strays from the projection, measured on the goal's models). Texels no such triangle covers
// (chart seams, folds, the far side of a thin part, vertices the ray misses, large triangles)
// are left to the per-texel search.
//
// SourceCover keeps, per source face (in the order of the mesh given: the bake's sorted source),
// its corners' target UVs (normalised like wedgeUv; NaN where the face covers nothing), as a
// NormalBakeMesh view for faceBands; coverFaces rasterises them per band of rows.
#pragma once

#include "maps/normal_bake.h"

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace voxelfair {

struct SourceCover {
    std::vector<glm::vec2> uv;  // 3 per source face: its corners' target UVs, NaN: no cover
    NormalBakeMesh mesh;        // the source with wedgeUv = uv
    size_t coveringFaces = 0;
    bool covers(uint32_t face) const { return uv[3 * size_t(face)].x == uv[3 * size_t(face)].x; }  // not NaN
};

// `source` the bake's (sorted) source, `target` its target; the map's size in texels.
SourceCover coverSource(const NormalBakeMesh &source, const NormalBakeMesh &target, int width, int height);

// A band's cover: for texel centre (x, y), y in [r0, r1), at i = (y - r0) * width + x: the source
// face covering it (UINT32_MAX: none; a later face in `faces` order overwrites) and the source's
// normal interpolated there (cornerNormals: 3 per source face, not normalised).
struct CoverRows {
    std::vector<uint32_t> face;
    std::vector<float> nx, ny, nz;
};
void coverFaces(const SourceCover &cover, const glm::vec3 *cornerNormals, const uint32_t *faces, size_t count,
                int width, int height, int r0, int r1, CoverRows &rows);

}  // namespace voxelfair
