// Fuzzes the boundary extraction with voxel grids decoded from the input, and checks the surface
// against a dense reference: a closed 2-manifold, consistently and outwardly oriented, exactly
// the exposed faces of the solid with its enclosed cavities filled, each quad carrying its
// voxel's payload, and a signed volume equal to the filled solid's voxel count.
//
// Input: byte 0..2 the grid's sides (1..16), byte 3 where the grid sits in the volume (margins,
// a z offset up to the largest side), then one bit per voxel, x fastest, then y, then z; the bits
// repeat when the input is shorter than the grid, so short inputs give periodic structures.
#include "extraction/boundary_surface.h"
#include "checks/surface_checks.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <vector>

using namespace voxelfair;
using namespace voxelfair::fuzz;

namespace {

// Small enough for thousands of executions per second; every local configuration fits.
constexpr int kMaxGridSide = 16;

Voxel payloadAt(int x, int y, int z) {
    return Voxel{uint8_t(1 + (x * 7 + y * 13 + z * 31) % 255), uint8_t((x + 2 * y + 3 * z) % 244)};
}

// The grid placed in a volume: voxel (x, y, z) of the grid is voxel (x, y, z) + offset.
struct Grid {
    int side[3] = {0, 0, 0};
    int offset[3] = {0, 0, 0};
    int volumeSide[3] = {0, 0, 0};
    std::vector<uint8_t> solid;  // x fastest

    size_t index(int x, int y, int z) const { return (size_t(z) * side[1] + y) * side[0] + x; }
    bool inside(int x, int y, int z) const {
        return x >= 0 && y >= 0 && z >= 0 && x < side[0] && y < side[1] && z < side[2];
    }
    bool at(int x, int y, int z) const { return inside(x, y, z) && solid[index(x, y, z)]; }
};

Grid decode(const uint8_t *data, size_t size) {
    Grid g;
    for (int a = 0; a < 3; ++a)
        g.side[a] = 1 + (a < int(size) ? data[a] % kMaxGridSide : 0);
    const uint8_t place = size > 3 ? data[3] : 0;
    // Bits 0-2: a one-voxel margin before the grid on x, y, z; bits 3-5: after it; bits 6-7: the
    // z offset, up to the top of the largest volume (lattice keys and face coordinates near 2^11).
    static constexpr int kZOffsets[4] = {0, 1, 255, kMaxVolumeSide - kMaxGridSide - 2};
    for (int a = 0; a < 3; ++a) {
        g.offset[a] = (place >> a) & 1;
        g.volumeSide[a] = g.offset[a] + g.side[a] + ((place >> (3 + a)) & 1);
    }
    g.offset[2] += kZOffsets[place >> 6];
    g.volumeSide[2] += kZOffsets[place >> 6];

    g.solid.assign(size_t(g.side[0]) * g.side[1] * g.side[2], 0);
    const uint8_t *bits = data + std::min<size_t>(size, 4);
    const size_t bitCount = 8 * (size - std::min<size_t>(size, 4));
    if (bitCount == 0)
        return g;
    for (size_t i = 0; i < g.solid.size(); ++i) {
        const size_t b = i % bitCount;
        g.solid[i] = (bits[b / 8] >> (b % 8)) & 1;
    }
    return g;
}

VoxelVolume toVolume(const Grid &g) {
    VoxelVolumeBuilder builder(g.volumeSide[0], g.volumeSide[1], g.volumeSide[2]);
    check(builder.valid(), "decoded volume size rejected");
    for (int y = 0; y < g.side[1]; ++y)
        for (int x = 0; x < g.side[0]; ++x)
            for (int z = 0; z < g.side[2]; ++z)
                if (g.at(x, y, z))
                    check(builder.add(x + g.offset[0], y + g.offset[1], z + g.offset[2], payloadAt(x, y, z)),
                          "builder refused a voxel");
    return builder.finish();
}

// The grid with every empty cell the outside cannot reach through faces made solid (dense flood
// fill over the grid padded by one cell, independent of the run-based code under test).
struct Filled {
    std::vector<uint8_t> solid;
    size_t cavities = 0, count = 0;
};

Filled fillCavities(const Grid &g) {
    const int px = g.side[0] + 2, py = g.side[1] + 2, pz = g.side[2] + 2;
    const auto padded = [&](int x, int y, int z) { return (size_t(z) * py + y) * px + x; };
    std::vector<uint8_t> outside(size_t(px) * py * pz, 0);
    std::vector<std::array<int, 3>> stack{{0, 0, 0}};
    outside[0] = 1;
    while (!stack.empty()) {
        const auto [x, y, z] = stack.back();
        stack.pop_back();
        static constexpr int kSteps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (const auto &d : kSteps) {
            const int nx = x + d[0], ny = y + d[1], nz = z + d[2];
            if (nx < 0 || ny < 0 || nz < 0 || nx >= px || ny >= py || nz >= pz)
                continue;
            if (outside[padded(nx, ny, nz)] || g.at(nx - 1, ny - 1, nz - 1))
                continue;
            outside[padded(nx, ny, nz)] = 1;
            stack.push_back({nx, ny, nz});
        }
    }
    Filled f;
    f.solid.assign(g.solid.size(), 0);
    for (int z = 0; z < g.side[2]; ++z)
        for (int y = 0; y < g.side[1]; ++y)
            for (int x = 0; x < g.side[0]; ++x) {
                const bool in = g.at(x, y, z) || !outside[padded(x + 1, y + 1, z + 1)];
                f.solid[g.index(x, y, z)] = in;
                f.count += in;
                f.cavities += in && !g.at(x, y, z);
            }
    return f;
}

void checkSurface(const Grid &g, const BoundarySurface &s) {
    const Filled filled = fillCavities(g);
    const auto filledAt = [&](int x, int y, int z) { return g.inside(x, y, z) && filled.solid[g.index(x, y, z)]; };
    if (s.stats.cavityVoxelsFilled != filled.cavities)
        fail("%zu cavity voxels filled, the reference finds %zu", s.stats.cavityVoxelsFilled, filled.cavities);
    if (s.quads.size() != 4 * s.quadCount())
        fail("%zu quad indices for %zu quads", s.quads.size(), s.quadCount());
    checkClosedManifold(s.quads, s.positions.size());

    // Lattice points, in grid coordinates.
    std::vector<std::array<int64_t, 3>> p(s.positions.size());
    for (size_t v = 0; v < p.size(); ++v)
        for (int a = 0; a < 3; ++a) {
            const float c = s.positions[v][a];
            if (c != float(int64_t(c)) || c < 0 || c > float(g.volumeSide[a]))
                fail("vertex %zu is off the lattice", v);
            p[v][a] = int64_t(c) - g.offset[a];
        }

    // Each quad is a unit square on a face between a filled-solid voxel and an empty cell, turning
    // counter-clockwise seen from the empty side; the faces are distinct, and all are covered.
    size_t exposedFaces = 0;
    for (int z = 0; z < g.side[2]; ++z)
        for (int y = 0; y < g.side[1]; ++y)
            for (int x = 0; x < g.side[0]; ++x)
                if (filledAt(x, y, z))
                    exposedFaces += !filledAt(x - 1, y, z) + !filledAt(x + 1, y, z) + !filledAt(x, y - 1, z) +
                                    !filledAt(x, y + 1, z) + !filledAt(x, y, z - 1) + !filledAt(x, y, z + 1);
    if (s.quadCount() != exposedFaces)
        fail("%zu quads for %zu exposed voxel faces", s.quadCount(), exposedFaces);

    std::vector<uint8_t> covered(g.solid.size() * 6, 0);
    int64_t sixVolume = 0;
    for (size_t q = 0; q < s.quadCount(); ++q) {
        const std::array<int64_t, 3> *c[4];
        for (int k = 0; k < 4; ++k)
            c[k] = &p[s.quads[4 * q + size_t(k)]];
        int64_t e[4][3], normal[3];
        for (int k = 0; k < 4; ++k)
            for (int a = 0; a < 3; ++a)
                e[k][a] = (*c[(k + 1) % 4])[a] - (*c[k])[a];
        for (int k = 0; k < 4; ++k)
            if (std::abs(e[k][0]) + std::abs(e[k][1]) + std::abs(e[k][2]) != 1)
                fail("quad %zu is not a unit square", q);
        for (int a = 0; a < 3; ++a)
            if (e[2][a] != -e[0][a] || e[3][a] != -e[1][a])
                fail("quad %zu is not a unit square", q);
        for (int a = 0; a < 3; ++a)
            normal[a] = e[0][(a + 1) % 3] * e[1][(a + 2) % 3] - e[0][(a + 2) % 3] * e[1][(a + 1) % 3];
        int axis = 0;
        while (axis < 2 && normal[axis] == 0)
            ++axis;
        const bool positive = normal[axis] > 0;
        int voxel[3];
        for (int a = 0; a < 3; ++a)
            voxel[a] = int(std::min(std::min((*c[0])[a], (*c[1])[a]), std::min((*c[2])[a], (*c[3])[a])));
        if (positive)
            --voxel[axis];  // the outward normal points away from the solid voxel
        int beyond[3] = {voxel[0], voxel[1], voxel[2]};
        beyond[axis] += positive ? 1 : -1;
        if (!filledAt(voxel[0], voxel[1], voxel[2]) || filledAt(beyond[0], beyond[1], beyond[2]))
            fail("quad %zu does not face outwards from a solid voxel into an empty cell", q);
        if (!g.at(voxel[0], voxel[1], voxel[2]))
            fail("quad %zu bounds a filled cavity voxel", q);
        uint8_t &seen = covered[g.index(voxel[0], voxel[1], voxel[2]) * 6 + size_t(2 * axis + positive)];
        if (seen)
            fail("quad %zu covers a face covered already", q);
        seen = 1;
        const Voxel want = payloadAt(voxel[0], voxel[1], voxel[2]);
        if (s.quadVoxels[q].colour != want.colour || s.quadVoxels[q].normal != want.normal)
            fail("quad %zu carries another voxel's payload", q);
        // Divergence theorem, in grid coordinates: six times the volume, two triangles per quad.
        const auto det = [](const std::array<int64_t, 3> &a, const std::array<int64_t, 3> &b,
                            const std::array<int64_t, 3> &d) {
            return a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                   a[2] * (b[0] * d[1] - b[1] * d[0]);
        };
        sixVolume += det(*c[0], *c[1], *c[2]) + det(*c[0], *c[2], *c[3]);
    }
    if (sixVolume != 6 * int64_t(filled.count))
        fail("signed volume %lld / 6 differs from the %zu voxels of the filled solid", (long long)sixVolume,
             filled.count);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const Grid grid = decode(data, size);
    const BoundarySurface surface = extractBoundarySurface(toVolume(grid));
    checkSurface(grid, surface);
    return 0;
}
