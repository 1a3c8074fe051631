// The constrained fairing's two variants (base/simd_variant.h), linked side by side: the SSE2
// kernels and the scalar code give the same surface up to float rounding. The SIMD kernels sum in
// another order, and 16 Gauss-Seidel sweeps over two passes carry those last-bit differences on,
// so the check is on positions, not bits: every vertex within kTolerance voxel of the other
// variant's, the same edge classes and vertex kinds (both read the input with the same operations),
// on quads and on mixed polygons, with and without selection, over several option sets.
// CI builds both configurations (VOXELFAIR_NO_SIMD off and on, .ci/run), and this test runs in each.
#include "fairing/constrained_fairing.h"
#include "smoothers/smoothing_comparison.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

// Both variants, whichever of them the header made the default.
namespace voxelfair::sse2 {
ConstrainedFairingReport fairConstrained(const MutablePolygonMesh &, const uint8_t *,
                                         const ConstrainedFairingOptions &);
}
namespace voxelfair::scalar {
ConstrainedFairingReport fairConstrained(const MutablePolygonMesh &, const uint8_t *,
                                         const ConstrainedFairingOptions &);
}

using namespace voxelfair;

namespace {

// Largest allowed distance between the variants' vertices, in voxels, and the largest root mean
// square distance over all vertices of all runs. Measured: at most 6.3e-4 (a sphere of mixed
// polygons, 3 passes, with a selection: the recomputed normals of thin triangles carry the
// rounding on), RMS 8.6e-7. A kernel bug (a wrong lane, a missed neighbour) moves vertices by
// tenths of a voxel.
constexpr float kTolerance = 2e-3f;
constexpr double kRmsTolerance = 1e-5;

struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> offsets, indices;
};

Mesh voxelMesh(const shapes::Shape &shape) {
    const BoundarySurface s = extractBoundarySurface(shapes::voxelize(shape));
    Mesh m{shape.name, s.positions, {}, s.quads};
    for (size_t q = 0; q <= s.quadCount(); ++q)
        m.offsets.push_back(uint32_t(4 * q));
    return m;
}

// Every third quad kept, the others split into two triangles: the general-polygon path.
Mesh mixedPolygons(const Mesh &quads) {
    Mesh m{quads.name + " mixed", quads.positions, {0}, {}};
    for (size_t p = 0; p + 1 < quads.offsets.size(); ++p) {
        const uint32_t *q = &quads.indices[4 * p];
        if (p % 3 == 0) {
            m.indices.insert(m.indices.end(), q, q + 4);
        } else {
            m.indices.insert(m.indices.end(), {q[0], q[1], q[2]});
            m.offsets.push_back(uint32_t(m.indices.size()));
            m.indices.insert(m.indices.end(), {q[0], q[2], q[3]});
        }
        m.offsets.push_back(uint32_t(m.indices.size()));
    }
    return m;
}

std::vector<Mesh> meshes() {
    std::vector<Mesh> list;
    for (const comparison::FamilyShape &f : comparison::fidelityShapes())
        list.push_back(voxelMesh(f.shape));
    const size_t quadMeshes = list.size();
    for (size_t i = 0; i < quadMeshes; i += 4)
        list.push_back(mixedPolygons(list[i]));
    return list;
}

std::vector<std::pair<std::string, ConstrainedFairingOptions>> optionSets() {
    std::vector<std::pair<std::string, ConstrainedFairingOptions>> sets;
    sets.push_back({"defaults", {}});
    ConstrainedFairingOptions o;
    o.passes = 3;
    o.normalLevels = 4;
    sets.push_back({"3 passes, 4 levels", o});
    o = {};
    o.keepSharpEdges = false;
    o.normalLevels = 1;
    sets.push_back({"no sharp edges, 1 level", o});
    o = {};
    o.fitPlanes = true;
    o.driftRounds = 0;
    sets.push_back({"planes, no drift removal", o});
    return sets;
}

}  // namespace

TEST(FairingSimdEquivalence, VariantsAgreeWithinTolerance) {
    float worst = 0.0f;
    double sum2 = 0.0;
    size_t vertices = 0;
    int runs = 0;
    for (const Mesh &mesh : meshes())
        for (const auto &[optionsName, options] : optionSets())
            for (bool selection : {false, true}) {
                std::vector<uint8_t> selected(mesh.positions.size());
                for (size_t v = 0; v < selected.size(); ++v)
                    selected[v] = v % 7 != 0;
                const uint8_t *mask = selection ? selected.data() : nullptr;
                std::vector<glm::vec3> simd = mesh.positions, scalar = mesh.positions;
                const size_t polygons = mesh.offsets.size() - 1;
                const ConstrainedFairingReport a = sse2::fairConstrained(
                    {simd.data(), simd.size(), mesh.offsets.data(), mesh.indices.data(), polygons}, mask, options);
                const ConstrainedFairingReport b = scalar::fairConstrained(
                    {scalar.data(), scalar.size(), mesh.offsets.data(), mesh.indices.data(), polygons}, mask, options);
                const std::string what = mesh.name + ", " + optionsName + (selection ? ", selection" : "");
                ASSERT_EQ(a.status, FairingStatus::Ok) << what;
                ASSERT_EQ(b.status, FairingStatus::Ok) << what;
                EXPECT_EQ(a.voxelSize, b.voxelSize) << what;
                EXPECT_EQ(a.creaseEdges, b.creaseEdges) << what;
                EXPECT_EQ(a.sharpEdges, b.sharpEdges) << what;
                EXPECT_EQ(a.edgeLineVertices, b.edgeLineVertices) << what;
                EXPECT_EQ(a.pinnedVertices, b.pinnedVertices) << what;
                float largest = 0.0f;
                for (size_t v = 0; v < simd.size(); ++v) {
                    const float d = glm::distance(simd[v], scalar[v]) / a.voxelSize;
                    largest = std::max(largest, d);
                    sum2 += double(d) * d;
                }
                vertices += simd.size();
                EXPECT_LE(largest, kTolerance) << what;
                worst = std::max(worst, largest);
                ++runs;
            }
    const double rms = std::sqrt(sum2 / double(std::max<size_t>(vertices, 1)));
    std::printf("%d runs: the variants' vertices at most %.3g voxel apart (tolerance %.3g), RMS %.3g (%.3g)\n", runs,
                worst, kTolerance, rms, kRmsTolerance);
    EXPECT_LE(rms, kRmsTolerance);
}
