// A dense voxel grid for building test and benchmark volumes from code (small sizes only).
#pragma once

#include "volume/voxel_volume.h"

#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

namespace voxelfair::test {

struct DenseGrid {
    int sizeX = 0, sizeY = 0, sizeZ = 0;
    std::vector<uint8_t> solid;
    std::vector<Voxel> payload;

    DenseGrid() = default;
    DenseGrid(int sx, int sy, int sz)
        : sizeX(sx), sizeY(sy), sizeZ(sz), solid(size_t(sx) * sy * sz, 0), payload(size_t(sx) * sy * sz) {}

    bool inside(int x, int y, int z) const { return x >= 0 && y >= 0 && z >= 0 && x < sizeX && y < sizeY && z < sizeZ; }
    size_t index(int x, int y, int z) const { return (size_t(z) * sizeY + y) * sizeX + x; }
    bool at(int x, int y, int z) const { return inside(x, y, z) && solid[index(x, y, z)]; }

    // Distinct payloads for face neighbours, so a quad given the wrong voxel's payload shows.
    static Voxel payloadFor(int x, int y, int z) {
        return Voxel{uint8_t(1 + (x + 7 * y + 31 * z) % 251), uint8_t((3 * x + 5 * y + 11 * z) % 256)};
    }
    void set(int x, int y, int z, bool on = true) {
        if (!inside(x, y, z))
            throw std::out_of_range("DenseGrid::set");
        solid[index(x, y, z)] = on;
        payload[index(x, y, z)] = payloadFor(x, y, z);
    }

    size_t count() const {
        size_t n = 0;
        for (uint8_t s : solid)
            n += s;
        return n;
    }

    VoxelVolume toVolume() const {
        VoxelVolumeBuilder builder(sizeX, sizeY, sizeZ);
        for (int y = 0; y < sizeY; ++y)
            for (int x = 0; x < sizeX; ++x)
                for (int z = 0; z < sizeZ; ++z)
                    if (at(x, y, z) && !builder.add(x, y, z, payload[index(x, y, z)]))
                        throw std::logic_error("DenseGrid::toVolume");
        return builder.finish();
    }
};

inline DenseGrid box(int sx, int sy, int sz) {
    DenseGrid g(sx, sy, sz);
    for (int z = 0; z < sz; ++z)
        for (int y = 0; y < sy; ++y)
            for (int x = 0; x < sx; ++x)
                g.set(x, y, z);
    return g;
}

// A cube of side `side` whose inside (all but `wall` voxels from each face) is empty: a closed
// cavity.
inline DenseGrid hollowBox(int side, int wall = 1) {
    DenseGrid g = box(side, side, side);
    for (int z = wall; z < side - wall; ++z)
        for (int y = wall; y < side - wall; ++y)
            for (int x = wall; x < side - wall; ++x)
                g.set(x, y, z, false);
    return g;
}

// Voxels whose centre lies within `radius` of the grid centre, with `margin` empty voxels around.
inline DenseGrid sphere(int radius, int margin = 0) {
    const int side = 2 * radius + 1 + 2 * margin;
    const double c = side / 2.0, r2 = double(radius) * radius;
    DenseGrid g(side, side, side);
    for (int z = 0; z < side; ++z)
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const double dx = x + 0.5 - c, dy = y + 0.5 - c, dz = z + 0.5 - c;
                if (dx * dx + dy * dy + dz * dz <= r2)
                    g.set(x, y, z);
            }
    return g;
}

// Each voxel solid with probability `density` (deterministic for a seed).
inline DenseGrid randomGrid(int sx, int sy, int sz, double density, uint32_t seed) {
    DenseGrid g(sx, sy, sz);
    std::mt19937 rng(seed);
    std::bernoulli_distribution on(density);
    for (int z = 0; z < sz; ++z)
        for (int y = 0; y < sy; ++y)
            for (int x = 0; x < sx; ++x)
                if (on(rng))
                    g.set(x, y, z);
    return g;
}

}  // namespace voxelfair::test
