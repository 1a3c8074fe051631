#include "atlas/edge_adjacency.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <numeric>
#include <tuple>

namespace voxelfair {

EdgeAdjacency buildEdgeAdjacency(const uint32_t *triangles, size_t faceCount, size_t vertexCount) {
    EdgeAdjacency adj;
    const size_t halfEdges = faceCount * 3;
    adj.opposite.assign(halfEdges, kNoOpposite);
    // Half-edge h = 3f + k runs from corner k of face f to corner k + 1 (mod 3): visit(h, lo, hi)
    // with its ends' smaller and larger vertex.
    auto forEachHalfEdge = [&](auto &&visit) {
        for (size_t f = 0; f < faceCount; ++f) {
            const uint32_t *t = triangles + 3 * f;
            const uint32_t a = t[0], b = t[1], c = t[2];
            visit(3 * f, std::min(a, b), std::max(a, b));
            visit(3 * f + 1, std::min(b, c), std::max(b, c));
            visit(3 * f + 2, std::min(c, a), std::max(c, a));
        }
    };

    // Counting sort by the smaller vertex.
    std::vector<uint32_t> first(vertexCount + 1, 0);
    forEachHalfEdge([&](size_t, uint32_t lo, uint32_t hi) {
        if (lo != hi)
            ++first[lo + 1];
    });
    for (size_t v = 0; v < vertexCount; ++v)
        first[v + 1] += first[v];
    // Each entry packs (larger vertex, half-edge) so a plain integer sort orders a bucket. Left
    // uninitialised (4.4 MB on a 185k-face mesh): the fill below writes every entry.
    const std::unique_ptr<uint64_t[]> keys(new uint64_t[first[vertexCount]]);
    std::vector<uint32_t> fill(first.begin(), first.end() - 1);
    forEachHalfEdge([&](size_t h, uint32_t lo, uint32_t hi) {
        if (lo != hi)
            keys[fill[lo]++] = (uint64_t(hi) << 32) | uint64_t(h);
    });

    for (size_t v = 0; v < vertexCount; ++v) {
        uint64_t *begin = keys.get() + first[v], *end = keys.get() + first[v + 1];
        // A bucket holds about a vertex's valence: a handful of entries, insertion-sorted.
        for (uint64_t *i = begin + 1; i < end; ++i)
            for (uint64_t *j = i; j > begin && j[-1] > j[0]; --j)
                std::swap(j[-1], j[0]);
        for (uint64_t *run = begin; run != end;) {
            uint64_t *next = run + 1;
            while (next != end && (*next >> 32) == (*run >> 32))
                ++next;
            const size_t faces = size_t(next - run);
            if (faces == 2) {
                const uint32_t h0 = uint32_t(run[0]), h1 = uint32_t(run[1]);
                adj.opposite[h0] = h1;
                adj.opposite[h1] = h0;
            } else if (faces == 1) {
                ++adj.borderEdges;
            } else {
                ++adj.nonManifoldEdges;
            }
            run = next;
        }
    }
    return adj;
}

std::vector<uint32_t> weldByPosition(const glm::vec3 *positions, size_t vertexCount, const uint32_t *triangles,
                                     size_t faceCount) {
    // Sort vertex indices by their coordinates' bit patterns (exact equality, NaNs included).
    auto key = [&](uint32_t v) {
        uint32_t k[3];
        std::memcpy(k, &positions[v], sizeof k);
        return std::make_tuple(k[0], k[1], k[2]);
    };
    std::vector<uint32_t> order(vertexCount);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [&](uint32_t a, uint32_t b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
    std::vector<uint32_t> canonical(vertexCount);
    for (size_t i = 0; i < vertexCount; ++i)
        canonical[order[i]] = i > 0 && key(order[i]) == key(order[i - 1]) ? canonical[order[i - 1]] : order[i];
    std::vector<uint32_t> welded(triangles, triangles + 3 * faceCount);
    for (uint32_t &v : welded)
        v = canonical[v];
    return welded;
}

}  // namespace voxelfair
