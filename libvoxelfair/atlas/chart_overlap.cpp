#include "atlas/chart_overlap.h"

#include "base/radix_sort.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/common.hpp>

namespace voxelfair {
namespace {

bool cross(const ChartBoundaryEdge &e, const ChartBoundaryEdge &f) {
    if (e.va == f.va || e.va == f.vb || e.vb == f.va || e.vb == f.vb)
        return false;
    const glm::dvec2 ea(e.a), eb(e.b), fa(f.a), fb(f.b);
    const double o1 = orientUv(ea, eb, fa), o2 = orientUv(ea, eb, fb);
    const double o3 = orientUv(fa, fb, ea), o4 = orientUv(fa, fb, eb);
    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

// Corners ordered by (vertex, from), equal pairs in their given order: radix-sorted by vertex
// (base/radix_sort.h), then each vertex's handful insertion-sorted by angle: linear in the
// corners where a comparison sort was a third of the fold checks on large meshes.
void insertionSort(ChartCorner *begin, ChartCorner *end) {
    auto before = [](const ChartCorner &a, const ChartCorner &b) {
        return a.vertex != b.vertex ? a.vertex < b.vertex : a.from < b.from;
    };
    for (ChartCorner *i = begin + 1; i < end; ++i) {
        const ChartCorner c = *i;
        ChartCorner *j = i;
        for (; j > begin && before(c, j[-1]); --j)
            *j = j[-1];
        *j = c;
    }
}

void sortCorners(std::vector<ChartCorner> &corners) {
    std::vector<ChartCorner> scratch;
    radixSortStable(corners, scratch, [](const ChartCorner &c) { return c.vertex; });
    for (size_t i = 0; i < corners.size();) {
        size_t j = i + 1;
        while (j < corners.size() && corners[j].vertex == corners[i].vertex)
            ++j;
        insertionSort(corners.data() + i, corners.data() + j);
        i = j;
    }
}

}  // namespace

bool boundaryCrossesItself(const std::vector<ChartBoundaryEdge> &edges) {
    const size_t n = edges.size();
    if (n < 4)  // a triangle's three edges cannot cross
        return false;
    if (n <= 32) {
        for (size_t i = 0; i < n; ++i)
            for (size_t j = i + 1; j < n; ++j)
                if (cross(edges[i], edges[j]))
                    return true;
        return false;
    }
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const ChartBoundaryEdge &e : edges) {
        lo = glm::min(lo, glm::min(e.a, e.b));
        hi = glm::max(hi, glm::max(e.a, e.b));
    }
    const int cells = int(std::ceil(std::sqrt(double(n))));
    const glm::vec2 extent = glm::max(hi - lo, glm::vec2(1e-20f));
    auto cellOf = [&](float v, int axis) {
        return std::clamp(int((v - lo[axis]) / extent[axis] * float(cells)), 0, cells - 1);
    };
    // Edges bucketed by the cells their boxes touch (counting sort: count, offsets, fill).
    std::vector<uint32_t> first(size_t(cells) * cells + 1, 0), items;
    auto forCells = [&](const ChartBoundaryEdge &e, auto &&visit) {
        const glm::vec2 a = glm::min(e.a, e.b), b = glm::max(e.a, e.b);
        for (int y = cellOf(a.y, 1); y <= cellOf(b.y, 1); ++y)
            for (int x = cellOf(a.x, 0); x <= cellOf(b.x, 0); ++x)
                visit(size_t(y) * cells + x);
    };
    for (const ChartBoundaryEdge &e : edges)
        forCells(e, [&](size_t cell) { ++first[cell + 1]; });
    for (size_t c = 0; c + 1 < first.size(); ++c)
        first[c + 1] += first[c];
    items.resize(first.back());
    std::vector<uint32_t> fill(first.begin(), first.end() - 1);
    for (size_t i = 0; i < n; ++i)
        forCells(edges[i], [&](size_t cell) { items[fill[cell]++] = uint32_t(i); });
    for (size_t c = 0; c + 1 < first.size(); ++c)
        for (uint32_t i = first[c]; i < first[c + 1]; ++i)
            for (uint32_t j = i + 1; j < first[c + 1]; ++j)
                if (cross(edges[items[i]], edges[items[j]]))
                    return true;
    return false;
}

namespace {

// Whether two of one vertex's corners, sorted by `from`, overlap.
bool sectorsOverlap(const ChartCorner *begin, const ChartCorner *end) {
    constexpr double kTurn = 6.283185307179586, kSlack = 1e-3;
    for (const ChartCorner *k = begin; k + 1 < end; ++k)  // each sector ends before the next one starts
        if (k->from + k->width > k[1].from + kSlack)
            return true;
    // The last one, past a full turn, into the first.
    return end - begin > 1 && end[-1].from + end[-1].width > begin->from + kTurn + kSlack;
}

}  // namespace

bool cornersOverlap(std::vector<ChartCorner> &corners) {
    sortCorners(corners);
    for (size_t i = 0; i < corners.size();) {
        size_t j = i + 1;
        while (j < corners.size() && corners[j].vertex == corners[i].vertex)
            ++j;
        if (sectorsOverlap(corners.data() + i, corners.data() + j))
            return true;
        i = j;
    }
    return false;
}

bool cornersOverlap(const std::vector<ChartCorner> &corners, size_t groups, CornerGroups &scratch) {
    // Stable counting sort by group, then each group insertion-sorted by angle: the same order
    // within a group as the general test's, and a group's answer does not depend on the others.
    std::vector<uint32_t> &start = scratch.start;
    start.assign(groups + 1, 0);
    for (const ChartCorner &c : corners)
        ++start[c.vertex + 1];
    for (size_t g = 0; g < groups; ++g)
        start[g + 1] += start[g];
    scratch.corners.resize(corners.size());
    ChartCorner *grouped = scratch.corners.data();
    for (const ChartCorner &c : corners)
        grouped[start[c.vertex]++] = c;
    // start[g] is now group g's end.
    for (size_t g = 0, begin = 0; g < groups; begin = start[g++]) {
        if (start[g] - begin < 2)
            continue;  // one sector overlaps nothing
        insertionSort(grouped + begin, grouped + start[g]);
        if (sectorsOverlap(grouped + begin, grouped + start[g]))
            return true;
    }
    return false;
}

}  // namespace voxelfair
