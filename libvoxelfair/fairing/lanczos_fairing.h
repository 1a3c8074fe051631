// Section 4.3 of the paper: surface fairing with the modified discrete Laplacian, the way the
// authors coded it (doc/method.md §4). For every vertex v, from the positions before the pass:
//   eq. 8   d = lambda * mean over neighbours n at non-zero distance of (p_n - p_v) / |p_n - p_v|
//   eq. 9   F(d) = sign(d) (1 - L3(d)) per axis (fairing/lanczos_kernel.h)
//   eq. 10  p_v' = p_v + voxelSize * (F(d.x), F(d.y), F(d.z))
// Neighbours are all vertices sharing a polygon with v (quad diagonals included). The unit
// vectors make d scale-free, so only the displacement needs the voxel size.
//
// Worked examples on a voxel box (lambda 4/3): a convex corner moves 0.441 voxel inward per
// axis, a convex edge 0.268 on its two axes, a flat interior vertex not at all.
#pragma once

#include "mesh/csr_adjacency.h"
#include "mesh/polygon_mesh.h"

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace voxelfair {

struct LanczosFairingOptions {
    // Eq. 8's lambda. 4/3 is the authors' C_FREQ_NORMALIZER; the paper's text says 1.3.
    float lambda = 4.0f / 3.0f;
    // The paper uses one pass; each further pass smooths more (0 leaves the mesh alone).
    int passes = 1;
    // Size of a voxel in the positions' units: the displacement unit. 0 = detectVoxelSize().
    float voxelSize = 0.0f;
    // Threads smoothing the vertices and sorting their neighbours (0: one per hardware thread;
    // meshes under 16384 vertices smooth on one). Every vertex reads the positions from before
    // the pass: the same result for any count.
    int threads = 0;
};

// What a fairing call did. Invalid input is not a status: it throws (base/error.h).
enum class FairingStatus {
    Ok,
    NothingToDo,  // no vertex, no polygon, no pass or no edge of non-zero length: no change
};

// The input checks both fairing modes make before touching anything. Throws MeshError when the
// mesh is invalid (mesh/polygon_mesh.h validate()); returns NothingToDo with a static message
// saying why when there is nothing to smooth, else Ok.
FairingStatus checkFairingInput(const PolygonMesh &mesh, int passes, const char **message);

// Both modes' reports (FairingReport, ConstrainedFairingReport) end a call this way: the status
// and its static message set, the report returned.
template <class Report>
Report finishedReport(Report &report, FairingStatus status, const char *message) {
    report.status = status;
    report.message = message;
    return report;
}

struct FairingReport {
    FairingStatus status = FairingStatus::Ok;
    const char *message = "ok";    // static text saying why when status != Ok
    float voxelSize = 0.0f;        // the displacement unit used (given or detected)
    int passes = 0;                // passes run
    size_t movedVertices = 0;      // vertices the last pass moved by more than 1e-6 voxel
    size_t skippedVertices = 0;    // vertices with non-finite coordinates: never moved, never neighbours
    float maxDisplacement = 0.0f;  // longest move of one vertex in one pass, in position units
};

// Smooths the mesh's positions in place. With `vertexSelected` (nullable, one byte per vertex),
// only vertices with a non-zero byte move; the others still act as neighbours. Never produces
// NaN: non-finite vertices are skipped and ignored as neighbours, coincident neighbours are
// ignored. Throws MeshError for an invalid mesh and OptionError for options out of range, before
// touching anything.
FairingReport fairModifiedLanczos(const MutablePolygonMesh &mesh, const uint8_t *vertexSelected,
                                  const LanczosFairingOptions &options = {});

struct FairingPassStats {
    size_t movedVertices = 0;
    float maxDisplacement = 0.0f;
};

// One Jacobi pass of eqs. 8-10 with a prebuilt buildVertexNeighbours() adjacency: reads `in`,
// writes every vertex of `out` (a different array of the same size), on up to `threads` threads
// (0: one per hardware thread; the same result for any count). No validation: lambda and
// voxelSize must be finite, the adjacency must match the arrays.
FairingPassStats lanczosFairingPass(const glm::vec3 *in, glm::vec3 *out, const CsrAdjacency &neighbours,
                                    const uint8_t *vertexSelected, float lambda, float voxelSize, int threads = 1);

}  // namespace voxelfair
