// The second fairing mode (constrained_fairing.h) on small meshes whose answer is known: sharp
// voxel features stay put, the staircase moves, every vertex stays in its cell, and the options,
// selection, scale and bad input behave.
#include "fairing/constrained_fairing.h"
#include "base/error.h"

#include "extraction/boundary_surface.h"
#include "shapes/analytic_shapes.h"
#include "shapes/box_lattice.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

using namespace voxelfair;
using shapes::QuadMesh;

namespace {

ConstrainedFairingReport fair(QuadMesh &m, const uint8_t *selected = nullptr, const ConstrainedFairingOptions &o = {}) {
    return fairConstrained({m.positions.data(), m.positions.size(), m.offsets.data(), m.indices.data(), m.quadCount()},
                           selected, o);
}

// The boundary quads (section 4.2) of the voxels of an sx * sy * sz box where `solid` holds.
QuadMesh voxelSurface(int sx, int sy, int sz, const std::function<bool(int, int, int)> &solid) {
    VoxelVolumeBuilder builder(sx, sy, sz);
    for (int y = 0; y < sy; ++y)
        for (int x = 0; x < sx; ++x)
            for (int z = 0; z < sz; ++z)
                if (solid(x, y, z))
                    builder.add(x, y, z, Voxel{1, 0});
    const BoundarySurface s = extractBoundarySurface(builder.finish());
    QuadMesh m;
    m.positions = s.positions;
    m.indices = s.quads;
    for (size_t q = 0; q <= s.quadCount(); ++q)
        m.offsets.push_back(uint32_t(4 * q));
    return m;
}

float maxMove(const QuadMesh &before, const QuadMesh &after) {
    float m = 0.0f;
    for (size_t v = 0; v < before.positions.size(); ++v)
        m = std::max(m, glm::distance(before.positions[v], after.positions[v]));
    return m;
}

void expectInCells(const QuadMesh &before, const QuadMesh &after, float half) {
    for (size_t v = 0; v < before.positions.size(); ++v) {
        const glm::vec3 d = glm::abs(after.positions[v] - before.positions[v]);
        EXPECT_LE(std::max(d.x, std::max(d.y, d.z)), half * (1.0f + 1e-5f)) << v;
    }
}

bool allFinite(const std::vector<glm::vec3> &positions) {
    for (const glm::vec3 &p : positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return false;
    return true;
}

// A ball of radius 5.3 voxels off the lattice: all staircase, no genuine edge.
QuadMesh ball() {
    return voxelSurface(14, 14, 14, [](int x, int y, int z) {
        return glm::length(glm::vec3(x, y, z) + 0.5f - glm::vec3(6.81f, 6.67f, 6.93f)) < 5.3f;
    });
}

}  // namespace

TEST(FairingConstrained, BoxStaysExactWithItsEdgesSharp) {
    const QuadMesh box = shapes::boxLattice(6, 5, 4);
    QuadMesh faired = box;
    const ConstrainedFairingReport r = fair(faired);
    ASSERT_EQ(r.status, FairingStatus::Ok) << r.message;
    EXPECT_EQ(r.passes, 2);
    EXPECT_EQ(faired.positions, box.positions);
    EXPECT_EQ(r.movedVertices, 0u);
    // 12 box edges of 6, 5 and 4 lattice edges: all genuine, their inner vertices on edge lines,
    // the 8 corners pinned.
    EXPECT_EQ(r.creaseEdges, 4u * (6 + 5 + 4));
    EXPECT_EQ(r.sharpEdges, r.creaseEdges);
    EXPECT_EQ(r.edgeLineVertices, 4u * (5 + 4 + 3));
    EXPECT_EQ(r.pinnedVertices, 8u);
}

TEST(FairingConstrained, OneVoxelPlateAndRodKeepTheirThickness) {
    // A round plate one voxel thick (its rim is a staircase in x-y only) and a 1x1 rod.
    const QuadMesh plate = voxelSurface(14, 14, 1, [](int x, int y, int) {
        return glm::length(glm::vec2(x, y) + 0.5f - glm::vec2(6.9f, 7.1f)) < 6.2f;
    });
    QuadMesh faired = plate;
    ASSERT_EQ(fair(faired).status, FairingStatus::Ok);
    EXPECT_GT(maxMove(plate, faired), 0.1f);  // the outline is smoothed
    for (size_t v = 0; v < plate.positions.size(); ++v)
        // Both faces stay flat (to 0.001 voxel: the drift removal, step 5, leans on the rim).
        EXPECT_NEAR(faired.positions[v].z, plate.positions[v].z, 1e-3f) << v;
    expectInCells(plate, faired, 0.5f);

    const QuadMesh rod = voxelSurface(1, 1, 9, [](int, int, int) { return true; });
    faired = rod;
    fair(faired);
    EXPECT_EQ(faired.positions, rod.positions);
}

TEST(FairingConstrained, SmoothsTheStaircaseInsideTheCells) {
    const QuadMesh raw = ball();
    QuadMesh faired = raw;
    const ConstrainedFairingReport r = fair(faired);
    ASSERT_EQ(r.status, FairingStatus::Ok);
    EXPECT_EQ(r.sharpEdges, 0u);  // every crease of a ball is a staircase step
    EXPECT_GT(r.creaseEdges, 0u);
    EXPECT_GT(r.movedVertices, raw.positions.size() * 9 / 10);
    EXPECT_GT(r.maxDisplacement, 0.3f);
    expectInCells(raw, faired, 0.5f);
    // Closer to the true sphere: distances of the vertices, RMS.
    auto rms = [](const QuadMesh &m) {
        double sum = 0.0;
        for (const glm::vec3 &p : m.positions) {
            const double d = glm::length(glm::dvec3(p) - glm::dvec3(6.81, 6.67, 6.93)) - 5.3;
            sum += d * d;
        }
        return std::sqrt(sum / double(m.positions.size()));
    };
    EXPECT_LT(rms(faired), 0.5 * rms(raw));

    // A narrower cell is respected too.
    ConstrainedFairingOptions o;
    o.cellHalfWidth = 0.2f;
    QuadMesh narrow = raw;
    fair(narrow, nullptr, o);
    expectInCells(raw, narrow, 0.2f);
    EXPECT_GT(fair(narrow = raw, nullptr, o).clampedVertices, 0u);
}

TEST(FairingConstrained, WithoutSharpEdgesTheBoxRounds) {
    const QuadMesh box = shapes::boxLattice(4, 4, 4);
    QuadMesh faired = box;
    ConstrainedFairingOptions o;
    o.keepSharpEdges = false;
    const ConstrainedFairingReport r = fair(faired, nullptr, o);
    EXPECT_EQ(r.sharpEdges, 0u);
    EXPECT_GT(maxMove(box, faired), 0.1f);
    expectInCells(box, faired, 0.5f);
}

TEST(FairingConstrained, ScaledModelSmoothsTheSameInVoxelUnits) {
    const QuadMesh raw = ball();
    QuadMesh scaled = raw;
    const float s = 0.25f;
    const glm::vec3 t(3.0f, -2.0f, 0.5f);
    for (glm::vec3 &p : scaled.positions)
        p = p * s + t;
    const QuadMesh scaledBefore = scaled;
    QuadMesh faired = raw;
    fair(faired);
    const ConstrainedFairingReport r = fair(scaled);
    EXPECT_NEAR(r.voxelSize, s, 1e-6f);
    for (size_t v = 0; v < raw.positions.size(); ++v) {
        const glm::vec3 expected = (faired.positions[v] - raw.positions[v]) * s;
        const glm::vec3 actual = scaled.positions[v] - scaledBefore.positions[v];
        EXPECT_NEAR(glm::distance(expected, actual), 0.0f, 1e-4f) << v;
    }
}

TEST(FairingConstrained, OnlySelectedVerticesMove) {
    const QuadMesh raw = ball();
    std::vector<uint8_t> selected(raw.positions.size(), 0);
    for (size_t v = 0; v < selected.size(); v += 3)
        selected[v] = 1;
    QuadMesh faired = raw;
    const ConstrainedFairingReport r = fair(faired, selected.data());
    EXPECT_GT(r.movedVertices, 0u);
    for (size_t v = 0; v < selected.size(); ++v) {
        if (!selected[v]) {
            EXPECT_EQ(faired.positions[v], raw.positions[v]) << v;
        }
    }
}

TEST(FairingConstrained, OpenAndTriangleMeshesKeepTheirFlatPartsAndBorders) {
    // A flat 4x4 patch: its border is sharp (a boundary), nothing moves.
    QuadMesh patch = shapes::boxLattice(4, 4, 4);
    const size_t topFaces = 16;  // the boxLattice's first 16 quads are the x = 0 side
    patch.indices.resize(4 * topFaces);
    patch.offsets.resize(topFaces + 1);
    QuadMesh faired = patch;
    const ConstrainedFairingReport r = fair(faired);
    ASSERT_EQ(r.status, FairingStatus::Ok) << r.message;
    EXPECT_EQ(r.sharpEdges, 16u);
    EXPECT_EQ(faired.positions, patch.positions);

    // The box as triangles (no quad, so no staircase test): its 90-degree creases stay sharp,
    // the diagonals are flat.
    const QuadMesh box = shapes::boxLattice(3, 3, 3);
    QuadMesh triangles = box;
    triangles.indices.clear();
    triangles.offsets.assign(1, 0);
    for (size_t q = 0; q < box.quadCount(); ++q) {
        const uint32_t *c = &box.indices[4 * q];
        for (uint32_t t : {c[0], c[1], c[2], c[0], c[2], c[3]})
            triangles.indices.push_back(t);
        triangles.offsets.push_back(uint32_t(triangles.indices.size() - 3));
        triangles.offsets.push_back(uint32_t(triangles.indices.size()));
    }
    faired = triangles;
    const ConstrainedFairingReport t =
        fairConstrained({faired.positions.data(), faired.positions.size(), faired.offsets.data(), faired.indices.data(),
                         faired.offsets.size() - 1},
                        nullptr);
    ASSERT_EQ(t.status, FairingStatus::Ok) << t.message;
    EXPECT_EQ(t.sharpEdges, 12u * 3u);
    EXPECT_EQ(faired.positions, triangles.positions);
}

TEST(FairingConstrained, NonFiniteVerticesAreSkippedAndNothingBecomesNaN) {
    QuadMesh raw = ball();
    raw.positions[5] = glm::vec3(std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f);
    raw.positions[40].y = std::numeric_limits<float>::infinity();
    QuadMesh faired = raw;
    const ConstrainedFairingReport r = fair(faired);
    ASSERT_EQ(r.status, FairingStatus::Ok) << r.message;
    EXPECT_EQ(r.skippedVertices, 2u);
    EXPECT_TRUE(std::isnan(faired.positions[5].x));
    EXPECT_TRUE(std::isinf(faired.positions[40].y));
    faired.positions[5] = raw.positions[5] = glm::vec3(0.0f);
    faired.positions[40] = raw.positions[40] = glm::vec3(0.0f);
    EXPECT_TRUE(allFinite(faired.positions));
    expectInCells(raw, faired, 0.5f);
}

TEST(FairingConstrained, RejectsBadOptionsAndMeshesWithoutTouchingThem) {
    const QuadMesh box = shapes::boxLattice(2, 2, 2);
    auto badOptions = [&](const std::function<void(ConstrainedFairingOptions &)> &set) {
        ConstrainedFairingOptions o;
        set(o);
        QuadMesh m = box;
        EXPECT_THROW(fair(m, nullptr, o), OptionError);
        EXPECT_EQ(m.positions, box.positions);
    };
    badOptions([](ConstrainedFairingOptions &o) { o.passes = -1; });
    badOptions([](ConstrainedFairingOptions &o) { o.normalLevels = 9; });
    badOptions([](ConstrainedFairingOptions &o) { o.positionSweeps = -1; });
    badOptions([](ConstrainedFairingOptions &o) { o.cellHalfWidth = 0.0f; });
    badOptions([](ConstrainedFairingOptions &o) { o.cellHalfWidth = std::numeric_limits<float>::infinity(); });
    badOptions([](ConstrainedFairingOptions &o) { o.creaseAngleDegrees = 180.0f; });
    badOptions([](ConstrainedFairingOptions &o) { o.stepReach = 0; });
    badOptions([](ConstrainedFairingOptions &o) { o.voxelSize = std::numeric_limits<float>::quiet_NaN(); });

    QuadMesh m = box;
    m.indices[3] = uint32_t(m.positions.size());
    EXPECT_THROW(fair(m), MeshError);
    EXPECT_EQ(m.positions, box.positions);
    m = box;
    m.offsets[0] = 1;
    EXPECT_THROW(fair(m), MeshError);
    EXPECT_THROW(fairConstrained({nullptr, 3, m.offsets.data(), m.indices.data(), 0}, nullptr), MeshError);
}

TEST(FairingConstrained, NothingToDo) {
    QuadMesh box = shapes::boxLattice(2, 2, 2);
    ConstrainedFairingOptions o;
    o.passes = 0;
    EXPECT_EQ(fair(box, nullptr, o).status, FairingStatus::NothingToDo);
    EXPECT_EQ(fairConstrained({nullptr, 0, nullptr, nullptr, 0}, nullptr).status, FairingStatus::NothingToDo);
    // All vertices in one point: no edge length to take the voxel size from.
    for (glm::vec3 &p : box.positions)
        p = glm::vec3(1.0f);
    EXPECT_EQ(fair(box).status, FairingStatus::NothingToDo);
}

TEST(FairingConstrained, TheSameOutputOnAnyThreadCount) {
    // A ball, a box turned 8.2 degrees about y (notch edges) and a tilted rod side by side: over
    // 49,152 vertices, so 3 threads are used (constrained_fairing.h: 16,384 a thread at most).
    const float turn = 8.2f * 3.14159265f / 180.0f, c = std::cos(turn), s = std::sin(turn);
    const QuadMesh quads = voxelSurface(150, 92, 92, [&](int x, int y, int z) {
        const glm::vec3 p = glm::vec3(x, y, z) + 0.5f;
        const glm::vec3 b = p - glm::vec3(108.3f, 46.1f, 45.7f);
        const glm::vec3 r(c * b.x + s * b.z, b.y, -s * b.x + c * b.z);
        const glm::vec3 a = glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f)), q = p - glm::vec3(44.2f, 45.3f, 45.9f);
        const float along = glm::dot(q, a);
        return glm::length(p - glm::vec3(44.31f, 45.17f, 45.43f)) < 41.3f ||
               (std::abs(r.x) < 24.0f && std::abs(r.y) < 33.0f && std::abs(r.z) < 28.0f) ||
               (std::abs(along) < 44.0f && glm::length(q - along * a) < 4.6f);
    });
    ASSERT_GE(quads.positions.size(), 3u * 16384u);
    QuadMesh triangles = quads;  // the general path: the first quad as two triangles
    const uint32_t *corner = &quads.indices[0];
    triangles.indices.insert(triangles.indices.begin() + 4, {corner[0], corner[2]});
    triangles.indices[2] = corner[2];  // (corner[0], corner[1], corner[2]), (corner[0], corner[2], corner[3])
    triangles.offsets.assign(1, 0);
    triangles.offsets.push_back(3);
    for (uint32_t end = 6; end <= triangles.indices.size(); end += 4)
        triangles.offsets.push_back(end);
    for (const QuadMesh *mesh : {&quads, static_cast<const QuadMesh *>(&triangles)})
        for (const bool fitPlanes : {false, true}) {
            std::vector<glm::vec3> first;
            for (const int threads : {1, 2, 3}) {
                ConstrainedFairingOptions o;
                o.threads = threads;
                o.fitPlanes = fitPlanes;
                QuadMesh faired = *mesh;
                const ConstrainedFairingReport r =
                    fairConstrained({faired.positions.data(), faired.positions.size(), faired.offsets.data(),
                                     faired.indices.data(), faired.offsets.size() - 1},
                                    nullptr, o);
                ASSERT_EQ(r.status, FairingStatus::Ok) << r.message;
                EXPECT_GT(r.movedVertices, faired.positions.size() / 2);
                if (threads == 1)
                    first = faired.positions;
                else  // bit for bit
                    EXPECT_TRUE(faired.positions == first)
                        << threads << " threads, " << (mesh == &quads ? "quads" : "triangles") << ", fitPlanes "
                        << fitPlanes;
            }
        }
}
