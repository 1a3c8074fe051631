#include "extraction/boundary_surface.h"

#include "extraction/boundary_faces.h"
#include "extraction/cavity_fill.h"
#include "extraction/lattice_point_map.h"
#include "extraction/lattice_vertex_sheets.h"

#include <algorithm>
#include <array>

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

// Gives each (lattice point, sheet) one vertex, made the first time a quad reaches the point.
class SheetVertices {
public:
    SheetVertices(const VoxelVolume &solid, size_t quads, BoundarySurface &surface)
        : solid_(solid), surface_(surface), points_(quads + quads / 4 + 8) {
        surface_.positions.reserve(quads + quads / 4 + 8);  // V = F + 2 - 2g, plus split copies
    }

    uint32_t vertex(int x, int y, int z, int slot) {
        auto [point, inserted] = points_.insert(LatticePointMap::key(x, y, z));
        if (inserted)
            makeVertices(*point, x, y, z);
        const LatticeVertexConfig &config = kLatticeVertexConfigs[point->config];
        const LatticeVertexSheets &sheets = point->joined ? config.joined : config.separate;
        return point->firstVertex + sheets.sheetOfSlot[slot];
    }

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
            if (point.joined && (h & 1))
                ++surface_.stats.pinchedEdgesJoined;
        }
        const LatticeVertexSheets &sheets = point.joined ? config.joined : config.separate;
        point.firstVertex = uint32_t(surface_.positions.size());
        for (int i = 0; i < sheets.sheetCount; ++i)
            surface_.positions.emplace_back(x, y, z);
        surface_.stats.nonManifoldVerticesSplit += sheets.sheetCount - 1u;
        surface_.stats.nonManifoldEdgesSplit += config.fourQuadEdgesForward;
    }

    const VoxelVolume &solid_;
    BoundarySurface &surface_;
    LatticePointMap points_;
};

}  // namespace

BoundarySurface extractBoundarySurface(const VoxelVolume &volume) {
    BoundarySurface surface;
    const VoxelVolume solid = fillEnclosedCavities(volume, &surface.stats.cavityVoxelsFilled);
    std::vector<BoundaryFace> faces;
    collectBoundaryFaces(solid, faces, surface.quadVoxels);

    SheetVertices vertices(solid, faces.size(), surface);
    surface.quads.resize(4 * faces.size());
    uint32_t *out = surface.quads.data();
    for (const BoundaryFace &face : faces) {
        for (const CornerStep &c : kCornerSteps[face.direction])
            *out++ = vertices.vertex(face.x + c.dx, face.y + c.dy, face.z + c.dz, c.slot);
    }
    return surface;
}

}  // namespace voxelfair
