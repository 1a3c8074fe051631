#include "extraction/boundary_surface.h"

#include "shapes/dense_grid.h"
#include "reference_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numeric>
#include <string>
#include <unordered_map>

using namespace voxelfair;
using namespace voxelfair::test;

namespace {

struct NamedGrid {
    std::string name;
    DenseGrid grid;
};

// What the mesh checks measured, for the case-specific expectations.
struct MeshFacts {
    long long euler = 0;       // V - E + F
    size_t components = 0;     // connected through shared edges
    size_t latticePoints = 0;  // distinct vertex positions
    long long sixVolume = 0;   // six times the signed volume (divergence theorem)
};

class DisjointSets {
public:
    explicit DisjointSets(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), size_t(0)); }
    size_t find(size_t a) {
        while (parent_[a] != a)
            a = parent_[a] = parent_[parent_[a]];
        return a;
    }
    void unite(size_t a, size_t b) { parent_[find(a)] = find(b); }

private:
    std::vector<size_t> parent_;
};

using Point = std::array<long long, 3>;

Point latticePoint(const glm::vec3 &p) {
    EXPECT_EQ(p.x, std::floor(p.x));
    EXPECT_EQ(p.y, std::floor(p.y));
    EXPECT_EQ(p.z, std::floor(p.z));
    return {(long long)p.x, (long long)p.y, (long long)p.z};
}

long long det(const Point &a, const Point &b, const Point &c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// The voxel face a quad covers, read from its geometry: a unit square whose corners turn
// counter-clockwise around the outward axis; the solid voxel lies behind it.
Face faceOfQuad(const Point q[4]) {
    Point e[4];
    for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 3; ++i)
            e[k][i] = q[(k + 1) % 4][i] - q[k][i];
    for (int k = 0; k < 4; ++k)
        EXPECT_EQ(std::abs(e[k][0]) + std::abs(e[k][1]) + std::abs(e[k][2]), 1) << "side " << k;
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(e[2][i], -e[0][i]);
        EXPECT_EQ(e[3][i], -e[1][i]);
    }
    const Point n = {e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                     e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    int axis = 0;
    while (axis < 2 && n[axis] == 0)
        ++axis;
    EXPECT_EQ(std::abs(n[axis]), 1);
    Face face;
    for (int i = 0; i < 3; ++i)
        face[i] = int(std::min({q[0][i], q[1][i], q[2][i], q[3][i]}));
    const bool positive = n[axis] > 0;
    if (positive)
        --face[axis];  // the solid voxel is behind the outward normal
    face[3] = 2 * axis + positive;
    return face;
}

// Structure, geometry, orientation and topology of the surface against the dense reference.
MeshFacts checkSurface(const ReferenceSolid &ref, const ReferenceSurface &expected, const BoundarySurface &s) {
    MeshFacts facts;
    const size_t quadCount = s.quadCount(), vertexCount = s.positions.size();
    EXPECT_EQ(quadCount, expected.faces.size()) << "one quad per exposed voxel face";
    EXPECT_EQ(s.quads.size(), 4 * quadCount);
    if (s.quads.size() != 4 * quadCount)
        return facts;
    for (uint32_t v : s.quads) {
        EXPECT_LT(v, vertexCount);
        if (v >= vertexCount)
            return facts;
    }

    std::vector<Point> points(vertexCount);
    std::set<Point> distinct;
    for (size_t v = 0; v < vertexCount; ++v)
        distinct.insert(points[v] = latticePoint(s.positions[v]));
    facts.latticePoints = distinct.size();

    // Every quad covers a distinct exposed face and carries its voxel's payload.
    std::set<Face> covered;
    const uint32_t *quads = s.quads.data();
    for (size_t i = 0; i < quadCount; ++i) {
        const Point q[4] = {points[quads[4 * i]], points[quads[4 * i + 1]], points[quads[4 * i + 2]],
                            points[quads[4 * i + 3]]};
        const Face f = faceOfQuad(q);
        EXPECT_TRUE(covered.insert(f).second) << "face covered twice";
        EXPECT_TRUE(expected.faces.count(f)) << "quad " << i << " is not an exposed face (or faces inwards)";
        // Cavities are closed, so every quad bounds one of the original voxels.
        EXPECT_TRUE(ref.grid.at(f[0], f[1], f[2]));
        if (!ref.grid.at(f[0], f[1], f[2]))
            continue;
        const Voxel want = ref.grid.payload[ref.grid.index(f[0], f[1], f[2])];
        EXPECT_EQ(s.quadVoxels[i].colour, want.colour) << "quad " << i;
        EXPECT_EQ(s.quadVoxels[i].normal, want.normal) << "quad " << i;
        facts.sixVolume += det(q[0], q[1], q[2]) + det(q[0], q[2], q[3]);
    }

    // Edges: two quads each, in opposite directions. Corners meeting at an edge end are chained
    // so that each vertex's corners must form a single fan.
    std::unordered_map<uint64_t, std::vector<size_t>> edgeUses;  // key (from, to) unordered -> quad corner
    for (size_t c = 0; c < 4 * quadCount; ++c) {
        const uint32_t from = quads[c], to = quads[c - c % 4 + (c + 1) % 4];
        EXPECT_NE(from, to);
        edgeUses[uint64_t(std::min(from, to)) << 32 | std::max(from, to)].push_back(c);
    }
    DisjointSets corners(4 * quadCount), surfaces(quadCount);
    auto next = [](size_t c) { return c - c % 4 + (c + 1) % 4; };
    size_t badEdges = 0;
    for (const auto &[key, uses] : edgeUses) {
        if (uses.size() != 2 || quads[uses[0]] != quads[next(uses[1])] || quads[next(uses[0])] != quads[uses[1]]) {
            ++badEdges;
            continue;
        }
        corners.unite(uses[0], next(uses[1]));  // both at the vertex uses[0] leaves
        corners.unite(next(uses[0]), uses[1]);
        surfaces.unite(uses[0] / 4, uses[1] / 4);
    }
    EXPECT_EQ(badEdges, 0u) << "edges without exactly two oppositely directed quads";
    std::vector<size_t> fanOf(vertexCount, SIZE_MAX);
    size_t unused = 0, multiFan = 0;
    for (size_t c = 0; c < 4 * quadCount; ++c) {
        size_t &fan = fanOf[quads[c]];
        if (fan == SIZE_MAX)
            fan = corners.find(c);
        multiFan += fan != corners.find(c);
    }
    for (size_t fan : fanOf)
        unused += fan == SIZE_MAX;
    EXPECT_EQ(unused, 0u) << "unused vertices";
    EXPECT_EQ(multiFan, 0u) << "vertices whose quads form several fans";

    for (size_t i = 0; i < quadCount; ++i)
        facts.components += surfaces.find(i) == i;
    facts.euler = (long long)vertexCount - (long long)edgeUses.size() + (long long)quadCount;
    return facts;
}

// Extracts `grid` and checks everything that holds for any voxel set.
MeshFacts checkExtraction(const DenseGrid &grid, BoundarySurface *result = nullptr) {
    const ReferenceSolid ref = referenceSolid(grid);
    const ReferenceSurface expected = referenceSurface(ref);
    const BoundarySurface s = extractBoundarySurface(grid.toVolume());
    const MeshFacts facts = checkSurface(ref, expected, s);
    EXPECT_EQ(facts.sixVolume, 6 * (long long)ref.count()) << "enclosed volume != solid voxels";
    EXPECT_EQ(s.stats.cavityVoxelsFilled, ref.cavityVoxels);
    EXPECT_EQ(s.stats.nonManifoldEdgesSplit, expected.fourQuadEdges);
    EXPECT_EQ(s.stats.pinchedEdgesJoined, expected.pinchedEdges);
    EXPECT_EQ(facts.latticePoints, expected.surfacePoints);
    EXPECT_EQ(s.positions.size(), expected.vertices) << "one vertex per sheet";
    EXPECT_EQ(s.stats.nonManifoldVerticesSplit, expected.vertices - expected.surfacePoints);
    const bool noTunnels = expected.solidEuler == (long long)expected.solidComponents && expected.pinchedEdges == 0;
    if (noTunnels) {
        EXPECT_EQ(facts.euler, 2 * (long long)facts.components) << "a sphere per component";
        EXPECT_EQ(facts.components, expected.solidComponents);
    }
    if (result)
        *result = s;
    return facts;
}

void checkAll(const std::vector<NamedGrid> &family) {
    for (const NamedGrid &g : family) {
        SCOPED_TRACE(g.name);
        checkExtraction(g.grid);
    }
}

DenseGrid withVoxels(int sx, int sy, int sz, std::initializer_list<std::array<int, 3>> voxels) {
    DenseGrid g(sx, sy, sz);
    for (const auto &v : voxels)
        g.set(v[0], v[1], v[2]);
    return g;
}

// A square ring around the z axis: `side` x `side` x `height` with a `hole` x `hole` hole.
DenseGrid ring(int side, int hole, int height) {
    DenseGrid g = box(side, side, height);
    const int h0 = (side - hole) / 2;
    for (int z = 0; z < height; ++z)
        for (int y = h0; y < h0 + hole; ++y)
            for (int x = h0; x < h0 + hole; ++x)
                g.set(x, y, z, false);
    return g;
}

}  // namespace

TEST(BoundarySurface, SingleVoxelIsACube) {
    BoundarySurface s;
    const MeshFacts f = checkExtraction(withVoxels(1, 1, 1, {{0, 0, 0}}), &s);
    EXPECT_EQ(s.quadCount(), 6u);
    EXPECT_EQ(s.positions.size(), 8u);
    EXPECT_EQ(f.euler, 2);
    checkExtraction(withVoxels(3, 3, 3, {{1, 1, 1}}));
}

TEST(BoundarySurface, Boxes) {
    for (const auto &size : {std::array<int, 3>{1, 1, 2}, {2, 3, 4}, {5, 5, 5}, {7, 3, 2}, {1, 9, 1}, {12, 10, 11}}) {
        SCOPED_TRACE(testing::Message() << size[0] << "x" << size[1] << "x" << size[2]);
        BoundarySurface s;
        checkExtraction(box(size[0], size[1], size[2]), &s);
        const size_t faces = 2 * size_t(size[0] * size[1] + size[1] * size[2] + size[2] * size[0]);
        EXPECT_EQ(s.quadCount(), faces);
        EXPECT_EQ(s.positions.size(), faces + 2);  // a sphere of quads: V = F + 2
        EXPECT_EQ(s.stats.nonManifoldEdgesSplit + s.stats.nonManifoldVerticesSplit, 0u);
    }
}

TEST(BoundarySurface, Spheres) {
    for (int r : {1, 2, 3, 5, 8, 12}) {
        SCOPED_TRACE(testing::Message() << "radius " << r);
        checkExtraction(sphere(r, 1));
    }
}

TEST(BoundarySurface, LShapesAndChains) {
    checkAll({
        {"L in a plane", withVoxels(3, 3, 1, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 2, 0}})},
        {"L across planes", withVoxels(2, 3, 3, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 2, 0}, {1, 2, 1}, {1, 2, 2}})},
        {"thick L",
         [] {
             DenseGrid g = box(6, 6, 3);
             for (int z = 0; z < 3; ++z)
                 for (int y = 3; y < 6; ++y)
                     for (int x = 3; x < 6; ++x)
                         g.set(x, y, z, false);
             return g;
         }()},
        // A C-shaped chain whose ends touch only along an edge: not a ring (faces only connect).
        {"chain closed by an edge",
         withVoxels(1, 4, 4, {{0, 1, 1}, {0, 1, 0}, {0, 2, 0}, {0, 3, 0}, {0, 3, 1}, {0, 3, 2}, {0, 2, 2}})},
    });
}

TEST(BoundarySurface, RandomGrids) {
    uint32_t seed = 100;
    for (const double density : {0.2, 0.45, 0.6, 0.8})
        for (const auto &size : {std::array<int, 3>{3, 3, 3}, std::array<int, 3>{5, 6, 7}, std::array<int, 3>{9, 9, 9}})
            for (int i = 0; i < 8; ++i, ++seed) {
                SCOPED_TRACE(testing::Message() << "seed " << seed << " density " << density);
                checkExtraction(randomGrid(size[0], size[1], size[2], density, seed));
            }
}

TEST(BoundarySurface, EnclosedCavityAddsNoQuads) {
    for (int side : {3, 5, 8}) {
        SCOPED_TRACE(side);
        BoundarySurface hollow, solid;
        checkExtraction(hollowBox(side), &hollow);
        checkExtraction(box(side, side, side), &solid);
        EXPECT_EQ(hollow.quadCount(), solid.quadCount());
        EXPECT_EQ(hollow.positions.size(), solid.positions.size());
        EXPECT_EQ(hollow.stats.cavityVoxelsFilled, size_t((side - 2) * (side - 2) * (side - 2)));
    }
}

TEST(BoundarySurface, CavityOpenThroughAHoleIsLinedWithQuads) {
    DenseGrid g = hollowBox(6);
    g.set(0, 2, 3, false);
    BoundarySurface s;
    const MeshFacts f = checkExtraction(g, &s);
    EXPECT_EQ(s.stats.cavityVoxelsFilled, 0u);
    // Outside 6 * 36, inside 6 * 16, minus the two faces of the removed voxel, plus the hole's 4 sides.
    EXPECT_EQ(s.quadCount(), 6u * 36 + 6 * 16 - 2 + 4);
    EXPECT_EQ(f.euler, 2);
}

TEST(BoundarySurface, VoxelsTouchingAlongAnEdgeGetSeparateSurfaces) {
    const std::vector<NamedGrid> pairs = {
        {"along z", withVoxels(2, 2, 1, {{0, 0, 0}, {1, 1, 0}})},
        {"along z, other diagonal", withVoxels(2, 2, 1, {{1, 0, 0}, {0, 1, 0}})},
        {"along x", withVoxels(1, 2, 2, {{0, 0, 0}, {0, 1, 1}})},
        {"along y", withVoxels(2, 1, 2, {{0, 0, 1}, {1, 0, 0}})},
    };
    for (const NamedGrid &g : pairs) {
        SCOPED_TRACE(g.name);
        BoundarySurface s;
        const MeshFacts f = checkExtraction(g.grid, &s);
        EXPECT_EQ(s.stats.nonManifoldEdgesSplit, 1u);
        EXPECT_EQ(s.stats.nonManifoldVerticesSplit, 2u);  // both ends of the edge
        EXPECT_EQ(s.stats.pinchedEdgesJoined, 0u);
        EXPECT_EQ(s.positions.size(), 16u);
        EXPECT_EQ(f.components, 2u);
        EXPECT_EQ(f.euler, 4);
    }
}

TEST(BoundarySurface, VoxelsTouchingAtACornerGetSeparateSurfaces) {
    for (int c = 0; c < 4; ++c) {
        const int x = c & 1, y = c >> 1;
        SCOPED_TRACE(c);
        BoundarySurface s;
        const MeshFacts f = checkExtraction(withVoxels(2, 2, 2, {{x, y, 0}, {1 - x, 1 - y, 1}}), &s);
        EXPECT_EQ(s.stats.nonManifoldEdgesSplit, 0u);
        EXPECT_EQ(s.stats.nonManifoldVerticesSplit, 1u);
        EXPECT_EQ(s.positions.size(), 16u);
        EXPECT_EQ(f.latticePoints, 15u);
        EXPECT_EQ(f.components, 2u);
        EXPECT_EQ(f.euler, 4);
    }
}

TEST(BoundarySurface, Checkerboards) {
    auto checkerboard = [](int sx, int sy, int sz, int parity) {
        DenseGrid g(sx, sy, sz);
        for (int z = 0; z < sz; ++z)
            for (int y = 0; y < sy; ++y)
                for (int x = 0; x < sx; ++x)
                    if ((x + y + z) % 2 == parity)
                        g.set(x, y, z);
        return g;
    };
    // In 3D the inner empty cells are walled in by their six solid neighbours and get filled.
    checkAll({
        {"layer 5x5 even", checkerboard(5, 5, 1, 0)},
        {"layer 6x4 odd", checkerboard(6, 4, 1, 1)},
        {"3x3x3 even", checkerboard(3, 3, 3, 0)},
        {"4x4x4 odd", checkerboard(4, 4, 4, 1)},
        {"5x5x5 even", checkerboard(5, 5, 5, 0)},
    });
    BoundarySurface s;
    checkExtraction(checkerboard(3, 3, 3, 0), &s);
    EXPECT_EQ(s.stats.cavityVoxelsFilled, 1u);
}

TEST(BoundarySurface, AllConfigurationsOfATwoByTwoByTwoBlock) {
    for (int config = 0; config < 256; ++config) {
        SCOPED_TRACE(testing::Message() << "config " << config);
        DenseGrid g(2, 2, 2);
        for (int cell = 0; cell < 8; ++cell)
            if (config >> cell & 1)
                g.set(cell & 1, cell >> 1 & 1, cell >> 2);
        checkExtraction(g);
    }
}

TEST(BoundarySurface, RingsHaveEulerCharacteristicZero) {
    for (const NamedGrid &g : std::vector<NamedGrid>{
             {"3x3x1", ring(3, 1, 1)}, {"5x5x2 hole 3", ring(5, 3, 2)}, {"6x6x3 hole 2", ring(6, 2, 3)}}) {
        SCOPED_TRACE(g.name);
        const MeshFacts f = checkExtraction(g.grid);
        EXPECT_EQ(f.euler, 0);
        EXPECT_EQ(f.components, 1u);
    }
    // Two linked rings, touching nowhere: two tori.
    DenseGrid linked(7, 5, 5);
    for (int a = 0; a < 5; ++a)
        for (int b = 0; b < 5; ++b)
            if (a == 0 || b == 0 || a == 4 || b == 4) {
                linked.set(a, b, 2);      // in the plane z = 2, around x, y in [1, 3]
                linked.set(a + 2, 2, b);  // in the plane y = 2 through that hole, around the bar x = 4
            }
    SCOPED_TRACE("linked");
    const MeshFacts f = checkExtraction(linked);
    EXPECT_EQ(f.euler, 0);
    EXPECT_EQ(f.components, 2u);
}

TEST(BoundarySurface, TunnelPinchedToAnEdgeAtBothEndsIsClosed) {
    // Slabs x = 0 and x = 2 hold an L of three voxels; slab x = 1 only the two ends of the L, which
    // touch along the edge x in [1, 2], y = z = 1. The ring of eight voxels would be a torus whose
    // hole has zero width along that edge: the sheets join across it, giving a sphere.
    DenseGrid g(3, 2, 2);
    for (int x : {0, 2}) {
        g.set(x, 0, 0);
        g.set(x, 1, 0);
        g.set(x, 1, 1);
    }
    g.set(1, 0, 0);
    g.set(1, 1, 1);
    BoundarySurface s;
    const MeshFacts f = checkExtraction(g, &s);
    EXPECT_EQ(s.stats.nonManifoldEdgesSplit, 1u);
    EXPECT_EQ(s.stats.pinchedEdgesJoined, 1u);
    EXPECT_EQ(f.euler, 2);

    // Pinched at one end only (no slab x = 2): the edge is split as usual.
    g.set(2, 0, 0, false);
    g.set(2, 1, 0, false);
    g.set(2, 1, 1, false);
    const MeshFacts open = checkExtraction(g, &s);
    EXPECT_EQ(s.stats.nonManifoldEdgesSplit, 1u);
    EXPECT_EQ(s.stats.pinchedEdgesJoined, 0u);
    EXPECT_EQ(open.euler, 2);
}

TEST(BoundarySurface, EmptyVolumeGivesAnEmptySurface) {
    const BoundarySurface s = extractBoundarySurface(VoxelVolumeBuilder(3, 4, 5).finish());
    EXPECT_EQ(s.quadCount(), 0u);
    EXPECT_TRUE(s.positions.empty());
    EXPECT_TRUE(extractBoundarySurface(VoxelVolume{}).positions.empty());
}

TEST(BoundarySurface, WorksInTheLargestVolumeWithoutTouchingItsBoundingBox) {
    VoxelVolumeBuilder b(kMaxVolumeSide, kMaxVolumeSide, kMaxVolumeSide);
    const int o = kMaxVolumeSide - 5;  // against the far corner of the lattice
    for (int y = o; y < o + 5; ++y)
        for (int x = o; x < o + 5; ++x)
            for (int z = o; z < o + 5; ++z)
                if (x == o || y == o || z == o || x == o + 4 || y == o + 4 || z == o + 4) {
                    ASSERT_TRUE(b.add(x, y, z, {}));
                }
    const BoundarySurface s = extractBoundarySurface(b.finish());
    EXPECT_EQ(s.quadCount(), 150u);
    EXPECT_EQ(s.positions.size(), 152u);
    EXPECT_EQ(s.stats.cavityVoxelsFilled, 27u);
    for (const glm::vec3 &p : s.positions)
        EXPECT_EQ(std::max({p.x, p.y, p.z}) <= float(kMaxVolumeSide), true);
}

// Welding in slabs of rows on several threads gives the one-thread surface bit for bit: the same
// positions, vertex numbers, quad order, voxels and counts, on grids noisy enough that the slabs
// meet on planes full of split vertices, joined tunnels and filled cavities.
TEST(BoundarySurface, SlabsOnAnyThreadCountGiveTheSameSurface) {
    uint32_t seed = 7;
    for (const double density : {0.3, 0.5, 0.7}) {
        SCOPED_TRACE(testing::Message() << "density " << density);
        const VoxelVolume volume = randomGrid(72, 64, 40, density, seed++).toVolume();
        ASSERT_GE(volume.runs.size(), size_t(7) << 12);  // enough runs for seven slabs
        const BoundarySurface one = extractBoundarySurface(volume, 1);
        EXPECT_GT(one.stats.nonManifoldVerticesSplit, 0u);
        EXPECT_GT(one.stats.nonManifoldEdgesSplit, 0u);
        EXPECT_GT(one.stats.pinchedEdgesJoined, 0u);
        EXPECT_GT(one.stats.cavityVoxelsFilled, 0u);
        for (const int threads : {2, 3, 4, 7}) {
            SCOPED_TRACE(testing::Message() << threads << " threads");
            const BoundarySurface many = extractBoundarySurface(volume, threads);
            ASSERT_EQ(many.positions.size(), one.positions.size());
            EXPECT_EQ(
                0, std::memcmp(many.positions.data(), one.positions.data(), one.positions.size() * sizeof(glm::vec3)));
            EXPECT_EQ(many.quads, one.quads);
            ASSERT_EQ(many.quadVoxels.size(), one.quadVoxels.size());
            EXPECT_EQ(
                0, std::memcmp(many.quadVoxels.data(), one.quadVoxels.data(), one.quadVoxels.size() * sizeof(Voxel)));
            EXPECT_EQ(many.stats.cavityVoxelsFilled, one.stats.cavityVoxelsFilled);
            EXPECT_EQ(many.stats.nonManifoldEdgesSplit, one.stats.nonManifoldEdgesSplit);
            EXPECT_EQ(many.stats.nonManifoldVerticesSplit, one.stats.nonManifoldVerticesSplit);
            EXPECT_EQ(many.stats.pinchedEdgesJoined, one.stats.pinchedEdgesJoined);
        }
    }
}
