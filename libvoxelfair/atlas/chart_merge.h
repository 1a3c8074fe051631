// Beyond the paper: fewer, larger charts. The paper's growth (section 4.5) leaves many charts of
// one to a few faces where no seed's cone reaches: on a faired voxel model mostly the rounded
// corners, whose normals point between three axes (54.7 degrees from each, outside the 45.6
// degree cone of the axis-aligned charts around them). The paper itself complains of
// "unnecessary micro partitions" in the texture; each costs a rim of gutter in the atlas.
//
// A small chart (at most `mostFaces` faces) is moved whole into an edge-adjacent chart of the
// same texel scale when every one of its faces lies within the wider cone `minCosine` around
// that chart's axis (default 0.5: the 60 degrees the paper's text states, for these faces only),
// and its faces, projected onto that chart's plane, overlap none of the chart's faces nor each
// other. The chart keeps its axis and origin, so its own faces keep their UVs exactly (voxel
// edges on texel rows stay there); the moved faces' stretch is at most 1 / minCosine. Of the
// neighbours that qualify the one closest in angle is taken (then the larger). Small charts are
// visited smallest first, and a chart that took others can itself move on later, all its faces
// tested again.
//
// The overlap test is exact on the projected triangles: two counter-clockwise triangles' interiors
// are disjoint exactly when one of their six edge lines has the other triangle on its closed
// outer side (separating axis theorem); vertices shared by the two charts project to the same
// UV, so touching along an edge or at a vertex is never an overlap.
#pragma once

#include "atlas/atlas_mesh.h"
#include "atlas/charts.h"

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace voxelfair {

// Per face: the unit normal the cones test (the caller's when usable) and the unit geometric
// normal; both zero for a degenerate face.
struct ChartFaceNormals {
    glm::vec3 cone, geometric;
};

struct ChartMergeOptions {
    size_t mostFaces = 8;
    float minCosine = 0.5f;
    // Threads for the set-up and the rebuilt charts, which take each chart alone (0: one per
    // hardware thread); the merges themselves run in order on one. The same charts for any count.
    int threads = 1;
};

// Merges small charts of `charts` (as computeCharts makes them, degenerate charts last and left
// alone) into their neighbours; `opposite` is the edge adjacency the charts grew over (
// edge_adjacency.h). Keeps the charts' order (seed order) and each chart's face order, moved faces
// after its own. Returns the number of charts merged away.
size_t mergeSmallCharts(const AtlasMesh &mesh, const uint32_t *opposite, const ChartFaceNormals *normals,
                        const ChartMergeOptions &options, AtlasCharts &charts);

}  // namespace voxelfair
