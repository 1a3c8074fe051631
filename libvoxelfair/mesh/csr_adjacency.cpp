#include "mesh/csr_adjacency.h"

#include "base/error.h"
#include "base/parallel_bands.h"

#include <algorithm>
#include <limits>
#include <string>

namespace voxelfair {

namespace {

constexpr size_t kMaxIndex = std::numeric_limits<uint32_t>::max();

// Fewer rows than this are sorted on one thread: starting threads would cost more.
constexpr size_t kLeastParallelRows = 8192;

// Closes the gaps left by rows that kept fewer items than were reserved for them.
// `rowEnd[v]` is where row v's kept items end inside its reserved range.
void compactRows(CsrAdjacency &csr, const std::vector<uint32_t> &rowEnd) {
    uint32_t write = 0;
    const size_t rows = csr.rowCount();
    for (size_t v = 0; v < rows; ++v) {
        const uint32_t first = csr.offsets[v];
        csr.offsets[v] = write;
        for (uint32_t i = first; i < rowEnd[v]; ++i)
            csr.items[write++] = csr.items[i];
    }
    csr.offsets[rows] = write;
    csr.items.resize(write);  // capacity kept: callers may reuse `csr` for the next mesh
}

// Turns per-row counts (stored in offsets[1..]) into start offsets; fails past 32 bits.
bool prefixSum(std::vector<uint32_t> &offsets, const std::vector<uint64_t> &counts) {
    uint64_t total = 0;
    offsets[0] = 0;
    for (size_t v = 0; v < counts.size(); ++v) {
        total += counts[v];
        if (total > kMaxIndex)
            return false;
        offsets[v + 1] = uint32_t(total);
    }
    return true;
}

}  // namespace

void buildVertexNeighbours(const PolygonMesh &mesh, CsrAdjacency &out, int threads) {
    // Cleared, not freed: a caller that keeps `out` reuses its memory on the next build.
    out.offsets.clear();
    out.items.clear();
    validatePolygons(mesh);
    const size_t vertexCount = mesh.vertexCount, polygonCount = mesh.polygonCount;
    const uint32_t *const polygonOffsets = mesh.polygonOffsets, *const polygonIndices = mesh.polygonIndices;

    // Reserve (arity - 1) slots per incidence, fill all pairs, then sort and dedupe each row:
    // cheaper than a set per vertex, and rows are short (about 12 before dedupe on quads).
    std::vector<uint64_t> counts(vertexCount, 0);
    for (size_t p = 0; p < polygonCount; ++p) {
        const uint32_t first = polygonOffsets[p], last = polygonOffsets[p + 1];
        if (last - first < 2)
            continue;
        for (uint32_t i = first; i < last; ++i)
            counts[polygonIndices[i]] += last - first - 1;
    }
    out.offsets.assign(vertexCount + 1, 0);
    if (!prefixSum(out.offsets, counts)) {
        out = {};
        throw MeshError("more vertex adjacencies than 32-bit offsets can address");
    }
    out.items.resize(out.offsets[vertexCount]);

    std::vector<uint32_t> cursor(out.offsets.begin(), out.offsets.end() - 1);
    uint32_t *const items = out.items.data();
    for (size_t p = 0; p < polygonCount; ++p) {
        const uint32_t first = polygonOffsets[p], last = polygonOffsets[p + 1];
        if (last - first < 2)
            continue;
        if (last - first == 4) {  // a quad (the voxel surfaces'): as the loop below, unrolled
            const uint32_t *q = polygonIndices + first;
            for (int i = 0; i < 4; ++i) {
                uint32_t *row = items + cursor[q[i]];
                cursor[q[i]] += 3;
                for (int j = 0, k = 0; j < 4; ++j)
                    if (j != i)
                        row[k++] = q[j];
            }
            continue;
        }
        for (uint32_t i = first; i < last; ++i) {
            const uint32_t v = polygonIndices[i];
            for (uint32_t j = first; j < last; ++j)
                if (j != i)
                    out.items[cursor[v]++] = polygonIndices[j];
        }
    }

    // Each row on its own: runs of rows on up to `threads` threads.
    const int workers = vertexCount >= kLeastParallelRows ? bandThreads(threads, vertexCount) : 1;
    const size_t bands = workers > 1 ? 4 * size_t(workers) : 1;
    runBands(bands, workers, [&](size_t band) {
        for (size_t v = vertexCount * band / bands; v < vertexCount * (band + 1) / bands; ++v) {
            uint32_t *row = out.items.data() + out.offsets[v];
            uint32_t *rowEnd = out.items.data() + cursor[v];
            std::sort(row, rowEnd);
            rowEnd = std::unique(row, rowEnd);
            rowEnd = std::remove(row, rowEnd, uint32_t(v));  // a polygon repeating v
            cursor[v] = uint32_t(rowEnd - out.items.data());
        }
    });
    compactRows(out, cursor);
}

CsrAdjacency buildVertexPolygons(const PolygonMesh &mesh) {
    CsrAdjacency out;
    validatePolygons(mesh);
    const size_t vertexCount = mesh.vertexCount, polygonCount = mesh.polygonCount;
    const uint32_t *const polygonOffsets = mesh.polygonOffsets, *const polygonIndices = mesh.polygonIndices;
    if (polygonCount > kMaxIndex)
        throw MeshError(std::to_string(polygonCount) + " polygons: more than 32-bit indices can address");

    std::vector<uint64_t> counts(vertexCount, 0);
    const uint32_t indexCount = polygonCount ? polygonOffsets[polygonCount] : 0;
    for (uint32_t i = 0; i < indexCount; ++i)
        ++counts[polygonIndices[i]];
    out.offsets.assign(vertexCount + 1, 0);
    prefixSum(out.offsets, counts);  // at most indexCount, which fits
    out.items.resize(indexCount);

    // Polygons are visited in order, so a polygon repeating v would be the row's last item.
    std::vector<uint32_t> cursor(out.offsets.begin(), out.offsets.end() - 1);
    bool repeated = false;
    for (size_t p = 0; p < polygonCount; ++p) {
        for (uint32_t i = polygonOffsets[p]; i < polygonOffsets[p + 1]; ++i) {
            const uint32_t v = polygonIndices[i];
            if (cursor[v] > out.offsets[v] && out.items[cursor[v] - 1] == p) {
                repeated = true;
                continue;
            }
            out.items[cursor[v]++] = uint32_t(p);
        }
    }
    if (repeated)
        compactRows(out, cursor);
    return out;
}

}  // namespace voxelfair
