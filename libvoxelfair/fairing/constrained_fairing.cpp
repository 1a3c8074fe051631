// The driver of the second fairing mode (constrained_fairing.h): checks the options and the input,
// then runs the stages of fairing/constrained/ in order (fairing_state.h lists them) on quads or
// on general polygons.
//
// What makes it fast (benchmarks/fairing_benchmark.cpp measures it; figures in the README):
// - work arrays in two reused blocks (work_arena.h), not a vector each: no page faults per call;
// - a vertex's corners with their next and previous vertices in one counting-sorted list, from
//   which the twins, the creases and the sweeps' order come in one pass (corner_lists.cpp);
// - step 3 on offsets from the input, with n . d kept per vertex, so that an update reads only its
//   neighbours' 16-byte offsets; the Gauss-Seidel order split into waves of independent vertices
//   (sweep_layout.cpp), updated four at a time in SSE registers (position_kernel.h; same result as
//   the plain order);
// - a specialization for quad meshes (the voxel surface), and the hot loops in their own functions
//   with locals, in SSE where glm's vec3 code compiles to stack round trips (vec3_simd.h).
#include "fairing/constrained_fairing.h"

#include "fairing/constrained/fairing_state.h"
#include "base/error.h"

#include <algorithm>
#include <cmath>

namespace voxelfair {
namespace {

template <bool kQuads>
void run(constrained::FairingState<kQuads> &s) {
    using namespace constrained;
    s.takeArrays();
    if (!findNormals(s))
        return;
    buildCorners(s);
    std::fill(s.edgeFlags, s.edgeFlags + s.cornerCount, uint8_t(0));
    classifyEdges(s.k, s.twin, s.input, s.normal, s.options, s.V, s.creases, s.creaseCount, s.edgeFlags,
                  s.sharpBoundary, s.sharpCreases, s.notches, s.report, s.threads);
    findVertexKinds(s);
    buildLevels(s);
    buildSlots(s);
    // Step 5's set-up reads nothing the last pass's sweeps and feature fit write: it runs beside
    // them, on a helper thread (removeDrift waits for it).
    const int driftRounds = s.options.driftRounds, driftWideRounds = s.options.driftWideRounds;
    auto driftSetup = [&s, driftRounds, driftWideRounds](size_t) { prepareDrift(s, driftRounds, driftWideRounds); };
    for (int pass = 0; pass < s.options.passes; ++pass) {
        if (pass > 0)
            findFairedNormals(s);
        // Later passes start from the faired surface, whose normals need one level less (measured:
        // smaller errors on spheres, tori and cylinders than with all levels again).
        const int levels = s.options.normalLevels;
        filterNormals(s, pass == 0 ? levels : std::max(levels - 1, std::min(levels, 1)));
        if (pass == std::min(1, s.options.passes - 1) && s.options.fitPlanes)
            findPlaneRegions(s);
        lendAnchorNormals(s);
        fitFreeVertices(s);
        holdAnchors(s);
        if (pass + 1 == s.options.passes && driftRounds > 0) {
            takeDriftArrays(s, driftRounds, driftWideRounds);
            s.threads.startAside(driftSetup);
        }
        for (int i = 0; i < s.options.positionSweeps; ++i)
            sweep(s, i % 2 == 0);
        fitFeatureVertices(s);
        ++s.report.passes;
    }
    if (s.options.passes > 0 && driftRounds > 0)
        removeDrift(s, driftRounds, driftWideRounds);
    finish(s);
}

}  // namespace

inline namespace VOXELFAIR_SIMD_VARIANT {

ConstrainedFairingReport fairConstrained(const MutablePolygonMesh &mesh, const uint8_t *vertexSelected,
                                         const ConstrainedFairingOptions &options) {
    ConstrainedFairingReport report;
    if (options.passes < 0 || options.normalLevels < 0 || options.normalLevels > 8 || options.positionSweeps < 0 ||
        options.stepReach < 1 || options.featureReach < 0 || options.cornerFlats < 0 || options.driftRounds < 0 ||
        options.driftWideRounds < 0 || options.featureFitIterations < 0 || options.threads < 0 ||
        !(options.featureSpreadDegrees >= 0.0f && options.featureSpreadDegrees < 180.0f) ||
        !(options.featureFlatDegrees >= 0.0f && options.featureFlatDegrees < 90.0f) ||
        !(options.cellHalfWidth > 0.0f) || !std::isfinite(options.cellHalfWidth) ||
        !(options.creaseAngleDegrees > 0.0f && options.creaseAngleDegrees < 180.0f) ||
        !std::isfinite(options.voxelSize) || options.voxelSize < 0.0f)
        throw OptionError(
            "constrained fairing: passes, positionSweeps, driftRounds, driftWideRounds >= 0, normalLevels in [0, 8], "
            "featureFitIterations >= 0, threads >= 0, featureSpread in [0, 180), featureFlat in [0, 90), stepReach >= "
            "1, featureReach >= 0, cornerFlats >= 0, "
            "cellHalfWidth > 0, creaseAngle in (0, 180), voxelSize "
            "finite and >= 0");
    if (const FairingStatus status = checkFairingInput(mesh, options.passes, &report.message);
        status != FairingStatus::Ok)
        return finishedReport(report, status, report.message);
    glm::vec3 *const positions = mesh.positions;
    const size_t vertexCount = mesh.vertexCount, polygonCount = mesh.polygonCount;
    const uint32_t *const polygonOffsets = mesh.polygonOffsets, *const polygonIndices = mesh.polygonIndices;

    bool allQuads = polygonOffsets[polygonCount] == 4 * polygonCount;
    for (size_t p = 0; allQuads && p < polygonCount; ++p)
        allQuads = polygonOffsets[p + 1] - polygonOffsets[p] == 4;
    if (allQuads) {
        constrained::FairingState<true> state(positions, vertexCount, polygonOffsets, polygonIndices, polygonCount,
                                              vertexSelected, options, report);
        run(state);
    } else {
        constrained::FairingState<false> state(positions, vertexCount, polygonOffsets, polygonIndices, polygonCount,
                                               vertexSelected, options, report);
        run(state);
    }
    return report;
}

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair
