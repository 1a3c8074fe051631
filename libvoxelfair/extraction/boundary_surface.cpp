#include "extraction/boundary_surface.h"

#include "base/parallel_bands.h"
#include "extraction/boundary_faces.h"
#include "extraction/cavity_fill.h"
#include "extraction/lattice_point_map.h"
#include "extraction/lattice_vertex_sheets.h"

#include <algorithm>
#include <array>
#include <limits>
#include <memory>

namespace voxelfair {
namespace {

// Bit 0: voxel (x, y, z - 1) is solid; bit 1: voxel (x, y, z) is. One search for both.
unsigned solidBelowAndAt(const VoxelVolume &v, int x, int y, int z) {
    if (x < 0 || y < 0 || x >= v.sizeX || y >= v.sizeY)
        return 0;
    const size_t c = v.columnIndex(x, y);
    const VoxelRun *last = v.runs.data() + v.columnFirstRun[c + 1];
    // Runs never touch, so the first run ending at or above z is the only one that can hold either.
    const VoxelRun *run =
        std::partition_point(v.runs.data() + v.columnFirstRun[c], last, [z](const VoxelRun &r) { return r.zEnd < z; });
    if (run == last)
        return 0;
    return unsigned(run->zBegin < z) | unsigned(run->zBegin <= z && z < run->zEnd) << 1;
}

// The configuration of lattice point (x, y, z) (cell bit i + 2j + 4k, lattice_vertex_sheets.h).
uint8_t latticeConfig(const VoxelVolume &v, int x, int y, int z) {
    unsigned config = 0;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            const unsigned bits = solidBelowAndAt(v, x - 1 + i, y - 1 + j, z);
            config |= (bits & 1) << (i + 2 * j) | (bits >> 1) << (i + 2 * j + 4);
        }
    }
    return uint8_t(config);
}

// A quad corner relative to the face's voxel, and the quad's slot at that lattice point.
struct CornerStep {
    int dx, dy, dz, slot;
};

// For each outward direction 2a + s, the corners counter-clockwise seen from outside: with
// u = (a + 1) % 3 and v = (a + 2) % 3, u x v = +a, so +a faces go (0,0) (1,0) (1,1) (0,1) in
// (u, v) and -a faces the other way round. The voxel is at p - 1 + bit on u and v, so a corner
// offset d on u gives slot bit 1 - d (lattice_vertex_sheets.h).
constexpr std::array<std::array<CornerStep, 4>, 6> buildCornerSteps() {
    constexpr int kOrder[2][4][2] = {{{0, 0}, {0, 1}, {1, 1}, {1, 0}}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    std::array<std::array<CornerStep, 4>, 6> steps{};
    for (int direction = 0; direction < 6; ++direction) {
        const int a = direction / 2, positive = direction % 2, u = (a + 1) % 3, v = (a + 2) % 3;
        for (int k = 0; k < 4; ++k) {
            const int du = kOrder[positive][k][0], dv = kOrder[positive][k][1];
            int d[3] = {0, 0, 0};
            d[a] = positive;  // the face's plane
            d[u] = du;
            d[v] = dv;
            steps[direction][k] = CornerStep{d[0], d[1], d[2], 4 * a + (1 - du) + 2 * (1 - dv)};
        }
    }
    return steps;
}

constexpr std::array<std::array<CornerStep, 4>, 6> kCornerSteps = buildCornerSteps();

// Gives each (lattice point, sheet) one vertex, made the first time a quad reaches the point,
// numbered in that order from 0. Points made on the lattice plane y = sharedY are listed, in
// order (a slab's points that the slab before it may have made too).
class SheetVertices {
public:
    SheetVertices(const VoxelVolume &solid, size_t quads, int sharedY)
        : solid_(solid), points_(quads + quads / 4 + 8), sharedY_(sharedY) {
        positions.reserve(quads + quads / 4 + 8);  // V = F + 2 - 2g, plus split copies
    }

    uint32_t vertex(int x, int y, int z, int slot) {
        auto [point, inserted] = points_.insert(LatticePointMap::key(x, y, z));
        if (inserted)
            makeVertices(*point, x, y, z);
        return point->firstVertex + sheetsOf(*point).sheetOfSlot[slot];
    }

    const LatticePointMap &points() const { return points_; }

    static const LatticeVertexSheets &sheetsOf(const LatticePointMap::Entry &point) {
        const LatticeVertexConfig &config = kLatticeVertexConfigs[point.config];
        return point.joined ? config.joined : config.separate;
    }

    // What one point adds to the stats (its split copies and edges, its joined tunnel).
    static void count(const LatticePointMap::Entry &point, BoundarySurfaceStats &stats) {
        const LatticeVertexConfig &config = kLatticeVertexConfigs[point.config];
        if (point.joined && (config.pinchedHalfEdge & 1))
            ++stats.pinchedEdgesJoined;
        stats.nonManifoldVerticesSplit += sheetsOf(point).sheetCount - 1u;
        stats.nonManifoldEdgesSplit += config.fourQuadEdgesForward;
    }

    std::vector<glm::vec3> positions;
    BoundarySurfaceStats stats;
    std::vector<uint64_t> sharedPoints;

private:
    void makeVertices(LatticePointMap::Entry &point, int x, int y, int z) {
        point.config = latticeConfig(solid_, x, y, z);
        const LatticeVertexConfig &config = kLatticeVertexConfigs[point.config];
        point.joined = false;
        // -1 when no half-edge is pinched, else an index below 12.
        if (const int h = config.pinchedHalfEdge; h >= 0) {  // NOLINT(bugprone-signed-char-misuse)
            // Join only when the other end is pinched along the same edge too, as it decides alike.
            int q[3] = {x, y, z};
            q[h / 2] += (h & 1) ? 1 : -1;
            point.joined = kLatticeVertexConfigs[latticeConfig(solid_, q[0], q[1], q[2])].pinchedHalfEdge == (h ^ 1);
        }
        point.firstVertex = uint32_t(positions.size());
        positions.insert(positions.end(), sheetsOf(point).sheetCount, glm::vec3(x, y, z));
        count(point, stats);
        if (y == sharedY_)
            sharedPoints.push_back(LatticePointMap::key(x, y, z));
    }

    const VoxelVolume &solid_;
    LatticePointMap points_;
    int sharedY_;
};

// A slab of the volume needs this many column runs to be meshed on a thread of its own.
constexpr size_t kLeastSlabRuns = size_t(1) << 12;

// One slab's faces, their quads (numbered by its own vertices) and those vertices.
struct Slab {
    int y0 = 0, y1 = 0;  // voxel rows y0 <= y < y1
    std::vector<BoundaryFace> faces;
    std::vector<Voxel> voxels;
    std::vector<uint32_t> quads;
    std::unique_ptr<SheetVertices> vertices;
};

}  // namespace

// In slabs. The faces are collected row by row (y-major), so slabs of rows meet only on the
// lattice plane y = y0 between two slabs, and one slab's faces follow the one's before it. Each
// slab numbers its own vertices from 0 in first-reached order; then, slab by slab, its points on
// the plane that the slab before it made too take that slab's vertices, and its other vertices
// are numbered on in their order. That is the numbering of one scan of all faces: the same surface
// for any count.
BoundarySurface extractBoundarySurface(const VoxelVolume &volume, int threads) {
    BoundarySurface surface;
    const VoxelVolume solid = fillEnclosedCavities(volume, &surface.stats.cavityVoxelsFilled);

    // Rows cut where the runs before reach each slab's share.
    const int workers = bandThreads(threads, std::max<size_t>(1, solid.runs.size() / kLeastSlabRuns));
    std::vector<Slab> slabs(1);
    for (int y = 0, s = 1; y < solid.sizeY && s < workers; ++y) {
        const size_t runsBefore = solid.columnFirstRun[solid.columnIndex(0, y)];
        if (runsBefore >= solid.runs.size() * size_t(s) / size_t(workers)) {
            if (y > slabs.back().y0) {
                slabs.back().y1 = y;
                slabs.emplace_back().y0 = y;
            }
            ++s;
        }
    }
    slabs.back().y1 = std::max(solid.sizeY, 0);

    runBands(slabs.size(), int(slabs.size()), [&](size_t s) {
        Slab &slab = slabs[s];
        collectBoundaryFaces(solid, slab.y0, slab.y1, slab.faces, slab.voxels);
        slab.vertices = std::make_unique<SheetVertices>(solid, slab.faces.size(), s == 0 ? -1 : slab.y0);
        slab.quads.resize(4 * slab.faces.size());
        uint32_t *out = slab.quads.data();
        for (const BoundaryFace &face : slab.faces) {
            for (const CornerStep &c : kCornerSteps[face.direction])
                *out++ = slab.vertices->vertex(face.x + c.dx, face.y + c.dy, face.z + c.dz, c.slot);
        }
    });

    if (slabs.size() == 1) {
        surface.positions = std::move(slabs[0].vertices->positions);
        surface.quads = std::move(slabs[0].quads);
        surface.quadVoxels = std::move(slabs[0].voxels);
    } else {
        // Numbered slab by slab (each after the one before), then copied side by side.
        constexpr uint32_t kUnset = std::numeric_limits<uint32_t>::max();
        std::vector<std::vector<uint32_t>> number(slabs.size());  // per slab, its vertices' final numbers
        std::vector<size_t> firstQuad(slabs.size() + 1, 0);
        std::vector<uint32_t> firstNew(slabs.size(), 0);  // per slab, its first vertex not shared
        uint32_t vertexCount = 0;
        for (size_t s = 0; s < slabs.size(); ++s) {
            SheetVertices &vertices = *slabs[s].vertices;
            number[s].assign(vertices.positions.size(), kUnset);
            BoundarySurfaceStats shared;  // what the points made before count already
            for (const uint64_t key : vertices.sharedPoints) {
                const LatticePointMap::Entry *old = slabs[s - 1].vertices->points().find(key);
                if (old == nullptr)
                    continue;
                const LatticePointMap::Entry &point = *vertices.points().find(key);
                for (uint32_t i = 0; i < SheetVertices::sheetsOf(point).sheetCount; ++i)
                    number[s][point.firstVertex + i] = number[s - 1][old->firstVertex + i];
                SheetVertices::count(point, shared);
            }
            firstNew[s] = vertexCount;
            for (uint32_t &n : number[s])
                if (n == kUnset)
                    n = vertexCount++;
            firstQuad[s + 1] = firstQuad[s] + slabs[s].faces.size();
            vertices.stats.nonManifoldEdgesSplit -= shared.nonManifoldEdgesSplit;
            vertices.stats.nonManifoldVerticesSplit -= shared.nonManifoldVerticesSplit;
            vertices.stats.pinchedEdgesJoined -= shared.pinchedEdgesJoined;
        }
        surface.positions.resize(vertexCount);
        surface.quads.resize(4 * firstQuad.back());
        surface.quadVoxels.resize(firstQuad.back());
        runBands(slabs.size(), int(slabs.size()), [&](size_t s) {
            const std::vector<glm::vec3> &positions = slabs[s].vertices->positions;
            for (size_t v = 0; v < positions.size(); ++v)
                if (number[s][v] >= firstNew[s])  // not shared: the slab before wrote those
                    surface.positions[number[s][v]] = positions[v];
            uint32_t *quads = surface.quads.data() + 4 * firstQuad[s];
            for (const uint32_t v : slabs[s].quads)
                *quads++ = number[s][v];
            std::copy(slabs[s].voxels.begin(), slabs[s].voxels.end(), surface.quadVoxels.begin() + firstQuad[s]);
        });
    }
    for (const Slab &slab : slabs) {
        surface.stats.nonManifoldEdgesSplit += slab.vertices->stats.nonManifoldEdgesSplit;
        surface.stats.nonManifoldVerticesSplit += slab.vertices->stats.nonManifoldVerticesSplit;
        surface.stats.pinchedEdgesJoined += slab.vertices->stats.pinchedEdgesJoined;
    }
    return surface;
}

}  // namespace voxelfair
