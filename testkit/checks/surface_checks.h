// Invariants of a closed, consistently oriented 2-manifold quad mesh, for the fuzz targets. A
// violation prints what is wrong and aborts, so that libFuzzer keeps the input as a crash.
#pragma once

#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace voxelfair::fuzz {

[[noreturn]] inline void fail(const char *format, ...) {
    va_list args;
    va_start(args, format);
    std::fputs("surface invariant violated: ", stderr);
    std::vfprintf(stderr, format, args);
    std::fputc('\n', stderr);
    va_end(args);
    std::abort();
}

inline void check(bool ok, const char *what) {
    if (!ok)
        fail("%s", what);
}

// Quads are 4 vertex indices each. Checks that:
//  * every index is a vertex and every vertex is used;
//  * every directed edge occurs once and its reverse once: each undirected edge is shared by
//    exactly two quads, which run along it in opposite directions (consistent orientation);
//  * the quads around each vertex form a single fan, so every vertex is a manifold point.
inline void checkClosedManifold(const std::vector<uint32_t> &quads, size_t vertexCount) {
    check(quads.size() % 4 == 0, "quad array length is not a multiple of 4");
    const size_t corners = quads.size();
    const auto next = [](size_t c) { return c - c % 4 + (c + 1) % 4; };

    // Corners grouped by vertex (a counting sort): a vertex has a handful, so edges are found by
    // scanning the corners of their start vertex.
    std::vector<size_t> first(vertexCount + 1, 0), byVertex(corners);
    for (size_t c = 0; c < corners; ++c) {
        if (quads[c] >= vertexCount)
            fail("quad %zu uses vertex %u of %zu", c / 4, quads[c], vertexCount);
        if (quads[c] == quads[next(c)])
            fail("quad %zu has a degenerate edge at vertex %u", c / 4, quads[c]);
        ++first[quads[c] + 1];
    }
    for (size_t v = 0; v < vertexCount; ++v)
        first[v + 1] += first[v];
    std::vector<size_t> fill(first.begin(), first.end() - 1);
    for (size_t c = 0; c < corners; ++c)
        byVertex[fill[quads[c]]++] = c;
    // The corner the directed edge from -> to leaves from; it must exist and be unique.
    const auto cornerOf = [&](uint32_t from, uint32_t to) {
        size_t found = corners;
        for (size_t i = first[from]; i < first[from + 1]; ++i) {
            const size_t c = byVertex[i];
            if (quads[next(c)] != to)
                continue;
            if (found != corners)
                fail("directed edge %u -> %u is used twice (quads %zu and %zu): wrong orientation or a non-manifold "
                     "edge",
                     from, to, found / 4, c / 4);
            found = c;
        }
        if (found == corners)
            fail("edge %u -> %u has no opposite: the surface is open or inconsistently oriented", to, from);
        return found;
    };

    // Around vertex v, the corner after corner c (leaving v towards n) belongs to the quad holding
    // the reverse edge n -> v. That permutes the corners at v; a manifold point has one cycle.
    std::vector<uint32_t> fans(vertexCount, 0);
    std::vector<uint8_t> visited(corners, 0);
    for (size_t start = 0; start < corners; ++start) {
        if (visited[start])
            continue;
        const uint32_t v = quads[start];
        size_t c = start;
        do {
            visited[c] = 1;
            c = next(cornerOf(quads[next(c)], v));
        } while (c != start);
        ++fans[v];
    }
    for (size_t v = 0; v < vertexCount; ++v) {
        if (fans[v] == 0)
            fail("vertex %zu is used by no quad", v);
        if (fans[v] > 1)
            fail("vertex %zu joins %u separate fans of quads: not a manifold point", v, fans[v]);
    }
}

}  // namespace voxelfair::fuzz
