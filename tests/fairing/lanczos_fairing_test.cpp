#include "fairing/lanczos_fairing.h"
#include "base/error.h"

#include "shapes/box_lattice.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

using namespace voxelfair;
using shapes::QuadMesh;

namespace {

FairingReport fair(QuadMesh &m, const uint8_t *selected = nullptr, const LanczosFairingOptions &o = {}) {
    return fairModifiedLanczos(
        {m.positions.data(), m.positions.size(), m.offsets.data(), m.indices.data(), m.quadCount()}, selected, o);
}

void expectMove(const QuadMesh &before, const QuadMesh &after, glm::ivec3 at, glm::vec3 move, float scale = 1.0f) {
    const int v = before.find(at.x, at.y, at.z);
    ASSERT_GE(v, 0);
    const glm::vec3 actual = (after.positions[v] - before.positions[v]) / scale;
    EXPECT_NEAR(actual.x, move.x, 1e-3f) << at.x << "," << at.y << "," << at.z;
    EXPECT_NEAR(actual.y, move.y, 1e-3f) << at.x << "," << at.y << "," << at.z;
    EXPECT_NEAR(actual.z, move.z, 1e-3f) << at.x << "," << at.y << "," << at.z;
}

bool allFinite(const std::vector<glm::vec3> &positions) {
    for (const glm::vec3 &p : positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return false;
    return true;
}

}  // namespace

// doc/method.md §4 worked examples: u = (0.402, 0.402, 0.402) at a convex corner, (0.302, 0.302, 0)
// on a convex edge, 0 on a flat face.
TEST(FairingLanczos, MovesBoxCornersEdgesAndFacesLikeTheAuthors) {
    const QuadMesh box = shapes::boxLattice(4, 4, 4);
    QuadMesh faired = box;
    const FairingReport r = fair(faired);
    ASSERT_EQ(r.status, FairingStatus::Ok) << r.message;
    EXPECT_EQ(r.voxelSize, 1.0f);
    EXPECT_EQ(r.passes, 1);
    expectMove(box, faired, {0, 0, 0}, glm::vec3(0.441f));
    expectMove(box, faired, {4, 4, 4}, glm::vec3(-0.441f));
    expectMove(box, faired, {4, 0, 4}, glm::vec3(-0.441f, 0.441f, -0.441f));
    expectMove(box, faired, {2, 0, 0}, glm::vec3(0.0f, 0.268f, 0.268f));
    expectMove(box, faired, {4, 2, 4}, glm::vec3(-0.268f, 0.0f, -0.268f));
    expectMove(box, faired, {2, 2, 4}, glm::vec3(0.0f));
    expectMove(box, faired, {0, 2, 3}, glm::vec3(0.0f));
    // 8 corners + 12 edges * 3 inner vertices move; the 6 * 9 face-interior vertices do not.
    EXPECT_EQ(r.movedVertices, 8u + 12u * 3u);
    EXPECT_NEAR(r.maxDisplacement, 0.441f * std::sqrt(3.0f), 1e-3f);
}

TEST(FairingLanczos, LambdaScalesTheFrequency) {
    // The paper's printed lambda 1.3 instead of the code's 4/3: the corner's d = 1.3 * 0.402.
    const QuadMesh box = shapes::boxLattice(3, 3, 3);
    QuadMesh faired = box;
    LanczosFairingOptions o;
    o.lambda = 1.3f;
    fair(faired, nullptr, o);
    const double u = (1.0 + std::sqrt(2.0)) / 6.0;  // (1 + 2 / sqrt 2) / 6 neighbours
    const double d = 1.3 * u;
    const double f = 1.0 - 3.0 * std::sin(M_PI * d) * std::sin(M_PI * d / 3.0) / (M_PI * M_PI * d * d);
    expectMove(box, faired, {0, 0, 0}, glm::vec3(float(f)));
}

TEST(FairingLanczos, ScaledModelSmoothsTheSameInVoxelUnits) {
    const QuadMesh box = shapes::boxLattice(4, 3, 5);
    QuadMesh scaled = box;
    const float s = 0.1f;
    const glm::vec3 t(12.0f, -3.0f, 0.5f);
    for (glm::vec3 &p : scaled.positions)
        p = p * s + t;
    const QuadMesh scaledBefore = scaled;
    QuadMesh faired = box;
    fair(faired);
    const FairingReport r = fair(scaled);
    EXPECT_NEAR(r.voxelSize, s, 1e-6f);
    for (size_t v = 0; v < box.positions.size(); ++v) {
        const glm::vec3 expected = (faired.positions[v] - box.positions[v]) * s;
        const glm::vec3 actual = scaled.positions[v] - scaledBefore.positions[v];
        EXPECT_NEAR(glm::distance(expected, actual), 0.0f, 1e-5f) << v;
    }
    // An explicit voxel size overrides detection: the displacement unit doubles.
    QuadMesh twice = box;
    LanczosFairingOptions o;
    o.voxelSize = 2.0f;
    EXPECT_EQ(fair(twice, nullptr, o).voxelSize, 2.0f);
    expectMove(box, twice, {0, 0, 0}, glm::vec3(0.882f));
}

TEST(FairingLanczos, OnlySelectedVerticesMoveOthersStillPull) {
    const QuadMesh box = shapes::boxLattice(4, 4, 4);
    std::vector<uint8_t> selected(box.positions.size(), 0);
    for (glm::ivec3 at : {glm::ivec3(0, 0, 0), glm::ivec3(1, 0, 0)}) {
        const int v = box.find(at.x, at.y, at.z);
        ASSERT_GE(v, 0);
        selected[size_t(v)] = 1;
    }
    QuadMesh faired = box;
    const FairingReport r = fair(faired, selected.data());
    EXPECT_EQ(r.movedVertices, 2u);
    expectMove(box, faired, {0, 0, 0}, glm::vec3(0.441f));  // as without selection: Jacobi
    expectMove(box, faired, {1, 0, 0}, glm::vec3(0.0f, 0.268f, 0.268f));
    expectMove(box, faired, {0, 1, 0}, glm::vec3(0.0f));
    expectMove(box, faired, {4, 4, 4}, glm::vec3(0.0f));
}

TEST(FairingLanczos, JacobiUpdateIgnoresVertexOrder) {
    // Renumber the vertices in reverse: every vertex must land at the same place.
    const QuadMesh box = shapes::boxLattice(3, 4, 2);
    QuadMesh reversed = box;
    const size_t n = box.positions.size();
    for (size_t v = 0; v < n; ++v)
        reversed.positions[n - 1 - v] = box.positions[v];
    for (uint32_t &i : reversed.indices)
        i = uint32_t(n - 1 - i);
    QuadMesh faired = box;
    fair(faired);
    fair(reversed);
    for (size_t v = 0; v < n; ++v)
        EXPECT_EQ(faired.positions[v], reversed.positions[n - 1 - v]);
}

TEST(FairingLanczos, MorePassesSmoothMore) {
    const QuadMesh box = shapes::boxLattice(6, 6, 6);
    QuadMesh once = box, thrice = box;
    LanczosFairingOptions o;
    o.passes = 3;
    EXPECT_EQ(fair(thrice, nullptr, o).passes, 3);
    fair(once);
    const int corner = box.find(0, 0, 0);
    EXPECT_GT(thrice.positions[corner].x, once.positions[corner].x + 0.1f);
    o.passes = 0;
    QuadMesh none = box;
    EXPECT_EQ(fair(none, nullptr, o).status, FairingStatus::NothingToDo);
    EXPECT_EQ(none.positions, box.positions);
}

TEST(FairingLanczos, NonFiniteVerticesAreSkippedAndDoNotPoisonNeighbours) {
    const QuadMesh box = shapes::boxLattice(4, 4, 4);
    QuadMesh broken = box;
    const int bad = box.find(2, 2, 4);
    broken.positions[bad] = glm::vec3(std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f);
    const int inf = box.find(0, 2, 2);
    broken.positions[inf] = glm::vec3(0.0f, std::numeric_limits<float>::infinity(), 0.0f);
    const FairingReport r = fair(broken);
    ASSERT_EQ(r.status, FairingStatus::Ok) << r.message;
    EXPECT_EQ(r.skippedVertices, 2u);
    EXPECT_TRUE(std::isnan(broken.positions[bad].x));  // left as it was
    EXPECT_TRUE(std::isinf(broken.positions[inf].y));
    for (size_t v = 0; v < broken.positions.size(); ++v) {
        if (int(v) == bad || int(v) == inf)
            continue;
        EXPECT_TRUE(std::isfinite(broken.positions[v].x) && std::isfinite(broken.positions[v].y) &&
                    std::isfinite(broken.positions[v].z))
            << v;
    }
    // A corner whose neighbours are all finite moves exactly as before.
    expectMove(box, broken, {4, 4, 4}, glm::vec3(-0.441f));
}

TEST(FairingLanczos, CoincidentAndIsolatedVerticesStayFinite) {
    // Two quads sharing an edge; vertex 4 duplicates vertex 1 and is used too, vertex 6 is
    // unused; the last quad has all four corners at one point.
    std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 0}, {2, 0, 1},
                                {9, 9, 9}, {5, 5, 5}, {5, 5, 5}, {5, 5, 5}, {5, 5, 5}};
    const std::vector<uint32_t> offsets = {0, 4, 8, 12};
    const std::vector<uint32_t> indices = {0, 1, 2, 3, 4, 5, 2, 1, 7, 8, 9, 10};
    const FairingReport r = fairModifiedLanczos({p.data(), p.size(), offsets.data(), indices.data(), 3}, nullptr, {});
    ASSERT_EQ(r.status, FairingStatus::Ok) << r.message;
    EXPECT_TRUE(allFinite(p));
    EXPECT_EQ(p[6], glm::vec3(9.0f));
    EXPECT_EQ(p[7], glm::vec3(5.0f));  // no neighbour at non-zero distance: stays
}

TEST(FairingLanczos, BadInputIsReportedAndLeavesPositionsUntouched) {
    const QuadMesh box = shapes::boxLattice(2, 2, 2);
    QuadMesh m = box;
    m.indices[5] = uint32_t(m.positions.size());
    try {
        fair(m);
        ADD_FAILURE() << "an index out of range was accepted";
    } catch (const MeshError &e) {
        EXPECT_NE(std::string(e.what()).find("uses vertex " + std::to_string(m.positions.size())), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(m.positions, box.positions);

    m = box;
    m.offsets[3] = 1;
    EXPECT_THROW(fair(m), MeshError);

    m = box;
    LanczosFairingOptions o;
    o.lambda = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(fair(m, nullptr, o), OptionError);
    o = {};
    o.voxelSize = -1.0f;
    EXPECT_THROW(fair(m, nullptr, o), OptionError);
    o = {};
    o.passes = -2;
    EXPECT_THROW(fair(m, nullptr, o), OptionError);
    EXPECT_EQ(m.positions, box.positions);

    EXPECT_EQ(fairModifiedLanczos({nullptr, 0, nullptr, nullptr, 0}, nullptr, {}).status, FairingStatus::NothingToDo);
    EXPECT_THROW(
        fairModifiedLanczos({nullptr, box.positions.size(), box.offsets.data(), box.indices.data(), box.quadCount()},
                            nullptr, {}),
        MeshError);
    glm::vec3 lonely(1.0f);
    const uint32_t zero = 0;
    EXPECT_EQ(fairModifiedLanczos({&lonely, 1, &zero, nullptr, 0}, nullptr, {}).status, FairingStatus::NothingToDo);
    // Every edge of zero length: no voxel size to detect.
    std::vector<glm::vec3> same(4, glm::vec3(2.0f));
    const uint32_t offsets[] = {0, 4};
    const uint32_t quad[] = {0, 1, 2, 3};
    const FairingReport r = fairModifiedLanczos({same.data(), 4, offsets, quad, 1}, nullptr, {});
    EXPECT_EQ(r.status, FairingStatus::NothingToDo);
}
