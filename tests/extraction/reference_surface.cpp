#include "reference_surface.h"

#include <deque>

namespace voxelfair::test {
namespace {

constexpr int kSteps[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};

// The four cells around the lattice edge from p along axis b, at cell layer `layer` on b, in
// circular order around the edge.
std::array<bool, 4> ringCells(const ReferenceSolid &s, const int p[3], int b, int layer) {
    const int u = (b + 1) % 3, w = (b + 2) % 3;
    const int offsets[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::array<bool, 4> ring{};
    for (int k = 0; k < 4; ++k) {
        int c[3];
        c[b] = layer;
        c[u] = p[u] - 1 + offsets[k][0];
        c[w] = p[w] - 1 + offsets[k][1];
        ring[k] = s.at(c[0], c[1], c[2]);
    }
    return ring;
}

bool diagonal(const std::array<bool, 4> &r) { return r[0] == r[2] && r[1] == r[3] && r[0] != r[1]; }

// Around an end of a four-quad edge, the two solid cells join through the layer behind that end
// when both have a solid neighbour there and one of those two reaches the other.
bool joinedBehind(const std::array<bool, 4> &ring, const std::array<bool, 4> &behind) {
    const int a = ring[0] ? 0 : 1;  // the solid cells are a and a + 2
    return behind[a] && behind[a + 2] && (behind[a + 1] || behind[(a + 3) % 4]);
}

// The boundary curves of the solid region R on a small sphere around a lattice point: each
// component of R is a sphere with holes, so their number is 2 * components - euler(R), with R
// made of octants (cells), quarter-planes between two solid cells and half-edges with four.
size_t sheetsAround(const ReferenceSolid &s, const int p[3]) {
    bool solid[8];
    for (int k = 0; k < 8; ++k)
        solid[k] = s.at(p[0] - 1 + (k & 1), p[1] - 1 + (k >> 1 & 1), p[2] - 1 + (k >> 2));
    long long cells = 0, shared = 0, fullHalfEdges = 0;
    int component[8];
    for (int k = 0; k < 8; ++k) {
        cells += solid[k];
        component[k] = k;
    }
    auto find = [&](int k) {
        while (component[k] != k)
            k = component[k];
        return k;
    };
    for (int k = 0; k < 8; ++k)
        for (int axis = 0; axis < 3; ++axis) {
            const int n = k | 1 << axis;
            if (n == k || !solid[k] || !solid[n])
                continue;
            ++shared;
            component[find(k)] = find(n);
        }
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            bool all = true;
            for (int k = 0; k < 8; ++k)
                if ((k >> axis & 1) == side)
                    all = all && solid[k];
            fullHalfEdges += all;
        }
    long long components = 0;
    for (int k = 0; k < 8; ++k)
        components += solid[k] && find(k) == k;
    return size_t(2 * components - (cells - shared + fullHalfEdges));
}

}  // namespace

size_t ReferenceSolid::count() const {
    size_t n = 0;
    for (uint8_t v : solid)
        n += v;
    return n;
}

ReferenceSolid referenceSolid(const DenseGrid &grid) {
    ReferenceSolid s;
    s.grid = grid;
    const int px = grid.sizeX + 2, py = grid.sizeY + 2, pz = grid.sizeZ + 2;
    auto padded = [&](int x, int y, int z) { return (size_t(z) * py + y) * px + x; };
    std::vector<uint8_t> outside(size_t(px) * py * pz, 0);
    std::deque<std::array<int, 3>> queue{{0, 0, 0}};
    outside[0] = 1;
    while (!queue.empty()) {
        const auto c = queue.front();
        queue.pop_front();
        for (const auto &d : kSteps) {
            const int x = c[0] + d[0], y = c[1] + d[1], z = c[2] + d[2];
            if (x < 0 || y < 0 || z < 0 || x >= px || y >= py || z >= pz)
                continue;
            if (outside[padded(x, y, z)] || grid.at(x - 1, y - 1, z - 1))
                continue;
            outside[padded(x, y, z)] = 1;
            queue.push_back({x, y, z});
        }
    }
    s.solid.assign(grid.solid.size(), 0);
    for (int z = 0; z < grid.sizeZ; ++z)
        for (int y = 0; y < grid.sizeY; ++y)
            for (int x = 0; x < grid.sizeX; ++x) {
                const bool inside = !outside[padded(x + 1, y + 1, z + 1)];
                s.solid[grid.index(x, y, z)] = inside;
                s.cavityVoxels += inside && !grid.at(x, y, z);
            }
    return s;
}

ReferenceSurface referenceSurface(const ReferenceSolid &s) {
    ReferenceSurface r;
    const DenseGrid &g = s.grid;
    long long shared = 0;
    for (int z = 0; z < g.sizeZ; ++z)
        for (int y = 0; y < g.sizeY; ++y)
            for (int x = 0; x < g.sizeX; ++x) {
                if (!s.at(x, y, z))
                    continue;
                for (int d = 0; d < 6; ++d) {
                    const bool neighbour = s.at(x + kSteps[d][0], y + kSteps[d][1], z + kSteps[d][2]);
                    if (!neighbour)
                        r.faces.insert(Face{x, y, z, d});
                    shared += neighbour;
                }
            }
    long long fullEdges = 0, fullPoints = 0;
    for (int z = 0; z <= g.sizeZ; ++z)
        for (int y = 0; y <= g.sizeY; ++y)
            for (int x = 0; x <= g.sizeX; ++x) {
                const int p[3] = {x, y, z};
                bool all = true;
                for (int k = 0; k < 8; ++k)
                    all = all && s.at(x - 1 + (k & 1), y - 1 + (k >> 1 & 1), z - 1 + (k >> 2));
                fullPoints += all;
                const size_t sheets = sheetsAround(s, p);
                r.vertices += sheets;
                r.surfacePoints += sheets > 0;
                for (int b = 0; b < 3; ++b) {
                    const auto ring = ringCells(s, p, b, p[b]);
                    fullEdges += ring[0] && ring[1] && ring[2] && ring[3];
                    if (!diagonal(ring))
                        continue;
                    ++r.fourQuadEdges;
                    if (joinedBehind(ring, ringCells(s, p, b, p[b] - 1)) &&
                        joinedBehind(ring, ringCells(s, p, b, p[b] + 1))) {
                        ++r.pinchedEdges;
                        r.vertices += 2;
                    }
                }
            }
    r.solidEuler = (long long)s.count() - shared / 2 + fullEdges - fullPoints;

    std::vector<uint8_t> seen(s.solid.size(), 0);
    for (int z = 0; z < g.sizeZ; ++z)
        for (int y = 0; y < g.sizeY; ++y)
            for (int x = 0; x < g.sizeX; ++x) {
                if (!s.at(x, y, z) || seen[g.index(x, y, z)])
                    continue;
                ++r.solidComponents;
                std::deque<std::array<int, 3>> queue{{x, y, z}};
                seen[g.index(x, y, z)] = 1;
                while (!queue.empty()) {
                    const auto c = queue.front();
                    queue.pop_front();
                    for (const auto &d : kSteps) {
                        const int nx = c[0] + d[0], ny = c[1] + d[1], nz = c[2] + d[2];
                        if (!s.at(nx, ny, nz) || seen[g.index(nx, ny, nz)])
                            continue;
                        seen[g.index(nx, ny, nz)] = 1;
                        queue.push_back({nx, ny, nz});
                    }
                }
            }
    return r;
}

}  // namespace voxelfair::test
