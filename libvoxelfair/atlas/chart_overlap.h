// Whether a projected chart overlaps itself.
//
// The cone keeps every face of a chart facing the seed plane, so the projection is locally one
// to one; it can still wind over itself globally (a helical ramp, a spiral staircase). A locally
// one-to-one map of a surface patch is one to one exactly when its boundary stays simple, so it
// suffices to look for two boundary edges that cross in UV. Edges are bucketed on a uniform grid
// of about one edge per cell, so the test is linear in the boundary length.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace voxelfair {

struct ChartBoundaryEdge {
    glm::vec2 a, b;   // UV ends
    uint32_t va, vb;  // their vertices: edges sharing a vertex never count as crossing
};

// True when two of the edges cross properly (touching at a point or along a line does not
// count: neither covers any area twice).
bool boundaryCrossesItself(const std::vector<ChartBoundaryEdge> &edges);

}  // namespace voxelfair
