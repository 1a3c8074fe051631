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

// Twice the signed area of UV triangle (a, b, c): positive when it turns counter-clockwise. The
// one orientation test of the atlas' overlap checks (here and chart_merge.cpp).
inline double orientUv(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

struct ChartBoundaryEdge {
    glm::vec2 a, b;   // UV ends
    uint32_t va, vb;  // their vertices: edges sharing a vertex never count as crossing
};

// True when two of the edges cross properly (touching at a point or along a line does not
// count: neither covers any area twice).
bool boundaryCrossesItself(const std::vector<ChartBoundaryEdge> &edges);

// The boundary can also touch itself at a vertex whose faces, around it, cover some angle twice
// (the chart goes round the vertex past a gap of faces it left out, and its two sides overlap
// near the vertex without any two edges crossing). A corner: a face's vertex and the angles
// of its two edges there in UV, the face's sector going counter-clockwise from `from` by
// `width` (0..pi), in radians or any measure monotonic in them with a full turn of 2 pi (charts.cpp
// uses a trigonometry-free one). True when two sectors at one vertex overlap by more than 1e-3.
struct ChartCorner {
    uint32_t vertex;
    double from, width;
};
bool cornersOverlap(std::vector<ChartCorner> &corners);

// The same for corners whose `vertex` is a group number below `groups` (a chart's boundary
// vertices numbered as met: charts.cpp): grouped by a counting sort, linear in the corners and
// groups, where the general test sorts by vertex. `scratch` holds the grouped corners.
struct CornerGroups {
    std::vector<uint32_t> start;
    std::vector<ChartCorner> corners;
};
bool cornersOverlap(const std::vector<ChartCorner> &corners, size_t groups, CornerGroups &scratch);

}  // namespace voxelfair
