#include "fairing/lanczos_fairing.h"

#include "fairing/lanczos_kernel.h"
#include "fairing/voxel_size.h"
#include "base/error.h"
#include "base/parallel_bands.h"
#include "mesh/vector_helpers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

namespace voxelfair {

namespace {

// Meshes with fewer vertices are smoothed on one thread: starting a second would cost more.
constexpr size_t kLeastParallelVertices = 16384;

// Vertices [from, to) of a pass; maxMove2 the longest squared move among them.
void fairVertices(const glm::vec3 *in, glm::vec3 *out, const CsrAdjacency &neighbours, const uint8_t *vertexSelected,
                  float lambda, float voxelSize, size_t from, size_t to, size_t &moved, float &maxMove2) {
    constexpr float kMaxLength2 = std::numeric_limits<float>::max();
    constexpr float kCountedMove2 = 1e-12f;  // (1e-6 voxel)^2
    for (size_t v = from; v < to; ++v) {
        const glm::vec3 p = in[v];
        out[v] = p;
        if (vertexSelected && !vertexSelected[v])
            continue;
        // Eq. 8: mean of unit vectors. One test rejects coincident and non-finite neighbours
        // (NaN fails every comparison); a non-finite v rejects all of them and stays put.
        glm::vec3 sum(0.0f);
        uint32_t count = 0;
        for (const uint32_t *n = neighbours.begin(v), *end = neighbours.end(v); n != end; ++n) {
            const glm::vec3 e = in[*n] - p;
            const float length2 = glm::dot(e, e);
            if (!(length2 > 0.0f && length2 <= kMaxLength2))
                continue;
            sum += e * (1.0f / std::sqrt(length2));
            ++count;
        }
        if (count == 0)
            continue;
        const glm::vec3 d = sum * (lambda / float(count));
        // Eqs. 9-10, per axis, in voxels.
        const glm::vec3 move =
            voxelSize * glm::vec3(lanczosDisplacement(d.x), lanczosDisplacement(d.y), lanczosDisplacement(d.z));
        const float move2 = glm::dot(move, move);
        out[v] = p + move;
        maxMove2 = std::max(maxMove2, move2);
        // On flat regions the unit vectors cancel only up to float rounding (d ~ 1e-8, a move of
        // ~1e-16 voxel): count as moved only what moves by more than a millionth of a voxel.
        if (move2 > kCountedMove2 * voxelSize * voxelSize)
            ++moved;
    }
}

}  // namespace

FairingPassStats lanczosFairingPass(const glm::vec3 *in, glm::vec3 *out, const CsrAdjacency &neighbours,
                                    const uint8_t *vertexSelected, float lambda, float voxelSize, int threads) {
    // Each vertex reads `in` only, so bands of vertices run apart; their counts add up and their
    // longest moves compare exactly: the same pass for any thread count.
    const size_t vertexCount = neighbours.rowCount();
    const int workers = vertexCount >= kLeastParallelVertices ? bandThreads(threads, 2) : 1;
    const size_t bands = workers > 1 ? 2 * size_t(workers) : 1;
    std::vector<size_t> moved(bands, 0);
    std::vector<float> maxMove2(bands, 0.0f);
    runBands(bands, workers, [&](size_t b) {
        fairVertices(in, out, neighbours, vertexSelected, lambda, voxelSize, vertexCount * b / bands,
                     vertexCount * (b + 1) / bands, moved[b], maxMove2[b]);
    });
    FairingPassStats stats;
    float longest2 = 0.0f;
    for (size_t b = 0; b < bands; ++b) {
        stats.movedVertices += moved[b];
        longest2 = std::max(longest2, maxMove2[b]);
    }
    stats.maxDisplacement = std::sqrt(longest2);
    return stats;
}

FairingStatus checkFairingInput(const PolygonMesh &mesh, int passes, const char **message) {
    validate(mesh);
    if (mesh.vertexCount == 0 || mesh.polygonCount == 0) {
        *message = "no vertex or no polygon";
        return FairingStatus::NothingToDo;
    }
    if (passes == 0) {
        *message = "zero passes requested";
        return FairingStatus::NothingToDo;
    }
    *message = "ok";
    return FairingStatus::Ok;
}

FairingReport fairModifiedLanczos(const MutablePolygonMesh &mesh, const uint8_t *vertexSelected,
                                  const LanczosFairingOptions &options) {
    FairingReport report;
    if (!std::isfinite(options.lambda) || options.passes < 0 || !std::isfinite(options.voxelSize) ||
        options.voxelSize < 0.0f)
        throw OptionError("fairing: lambda and voxelSize must be finite, voxelSize and passes >= 0");
    if (const FairingStatus status = checkFairingInput(mesh, options.passes, &report.message);
        status != FairingStatus::Ok)
        return finishedReport(report, status, report.message);

    glm::vec3 *const positions = mesh.positions;
    const size_t vertexCount = mesh.vertexCount;
    for (size_t v = 0; v < vertexCount; ++v)
        if (!isFinite(positions[v]))
            ++report.skippedVertices;

    report.voxelSize = options.voxelSize > 0.0f ? options.voxelSize : detectVoxelSize(mesh);
    if (!(report.voxelSize > 0.0f))
        return finishedReport(report, FairingStatus::NothingToDo,
                              "no polygon edge of non-zero finite length to take the voxel size from");

    // The work arrays are kept from call to call (per thread): a filter runs once per click, and
    // fresh multi-megabyte arrays cost more in first-touch page faults than the pass itself.
    thread_local CsrAdjacency neighbours;
    thread_local std::vector<glm::vec3> previous;
    buildVertexNeighbours(mesh, neighbours, options.threads);
    // Jacobi: every vertex of a pass reads the positions from before that pass.
    previous.assign(positions, positions + vertexCount);
    for (int pass = 0; pass < options.passes; ++pass) {
        if (pass > 0)
            std::copy(positions, positions + vertexCount, previous.begin());
        const FairingPassStats stats = lanczosFairingPass(previous.data(), positions, neighbours, vertexSelected,
                                                          options.lambda, report.voxelSize, options.threads);
        report.movedVertices = stats.movedVertices;
        report.maxDisplacement = std::max(report.maxDisplacement, stats.maxDisplacement);
        ++report.passes;
    }
    return finishedReport(report, FairingStatus::Ok, "ok");
}

}  // namespace voxelfair
