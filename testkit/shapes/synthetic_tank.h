// A synthetic tank the size of the paper's largest model (the Warhammer: 63150 opaque voxels in
// two sections of 66 x 30 x 130 and 60 x 25 x 115), for benchmarks and the report. Built like
// the game's voxel models: hollow, with walls two voxels thick (the extraction fills the inside),
// so the opaque count follows the surface, as in the real files. Hull with tracks, fenders and
// rivets; turret with hatch, mantlet and a long barrel; camouflage colours.
#pragma once

#include "pipeline/pipeline_stages.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace voxelfair::pipeline {

// The voxels of `inside` within `wall` voxels (Chebyshev distance) of its outside, coloured by
// `colour`. z-up, x forward.
inline VoxelVolume hollowVolume(int sizeX, int sizeY, int sizeZ, const std::function<bool(int, int, int)> &inside,
                                const std::function<uint8_t(int, int, int)> &colour, int wall = 2) {
    std::vector<uint8_t> solid(size_t(sizeX) * size_t(sizeY) * size_t(sizeZ));
    auto at = [&](int x, int y, int z) { return (size_t(z) * size_t(sizeY) + size_t(y)) * size_t(sizeX) + size_t(x); };
    for (int z = 0; z < sizeZ; ++z)
        for (int y = 0; y < sizeY; ++y)
            for (int x = 0; x < sizeX; ++x)
                solid[at(x, y, z)] = inside(x, y, z);
    auto nearOutside = [&](int x, int y, int z) {
        for (int dz = -wall; dz <= wall; ++dz)
            for (int dy = -wall; dy <= wall; ++dy)
                for (int dx = -wall; dx <= wall; ++dx) {
                    const int nx = x + dx, ny = y + dy, nz = z + dz;
                    if (nx < 0 || ny < 0 || nz < 0 || nx >= sizeX || ny >= sizeY || nz >= sizeZ ||
                        !solid[at(nx, ny, nz)])
                        return true;
                }
        return false;
    };
    VoxelVolumeBuilder builder(sizeX, sizeY, sizeZ);
    for (int y = 0; y < sizeY; ++y)
        for (int x = 0; x < sizeX; ++x)
            for (int z = 0; z < sizeZ; ++z)
                if (solid[at(x, y, z)] && nearOutside(x, y, z))
                    builder.add(x, y, z, Voxel{colour(x, y, z), 0});
    return builder.finish();
}

inline std::unique_ptr<Model> syntheticTankModel() {
    enum : uint8_t { Olive = 1, Tan, Dark, Track, Metal, Rivet };
    Palette palette;
    palette.colours[Olive] = {96, 108, 60};
    palette.colours[Tan] = {150, 132, 88};
    palette.colours[Dark] = {58, 66, 42};
    palette.colours[Track] = {62, 62, 64};
    palette.colours[Metal] = {118, 122, 126};
    palette.colours[Rivet] = {172, 170, 156};
    // Low-frequency blotches.
    auto camo = [](int x, int y, int z) {
        const double v = std::sin(x * 0.13) + std::cos(y * 0.17 + z * 0.11) + 1.5 * std::sin((x + y) * 0.07);
        return uint8_t(Olive + int(std::floor(v + 4.0)) % 3);
    };
    auto centre = [](int v) { return double(v) + 0.5; };

    // Hull: 130 long (x), 66 wide (y), 30 high (z).
    auto trackDistance = [&](int x, int z) {  // to the axis of a stadium-shaped track, in x-z
        const double cx = std::clamp(centre(x), 12.0, 118.0);
        return std::hypot(centre(x) - cx, centre(z) - 8.0);
    };
    auto inTrack = [&](int x, int y, int z) {
        if (!((y >= 1 && y < 13) || (y >= 53 && y < 65)))
            return false;
        const double d = trackDistance(x, z);
        return d < 8.0 && !(d > 6.6 && x % 4 == 0);  // links: a notch every 4 voxels
    };
    auto inHull = [&](int x, int y, int z) {
        if (y < 9 || y >= 57 || x < 3 || x >= 127 || z < 9 || z >= 24)
            return false;
        if ((y == 9 || y == 56) && x % 6 == 0)  // panel seams along the sides
            return false;
        const double front = std::max(0.0, centre(x) - 104.0) * 0.8, rear = std::max(0.0, 14.0 - centre(x)) * 0.6;
        return centre(z) < 24.0 - std::max(front, rear);
    };
    auto inFender = [&](int x, int y, int z) { return z == 17 && x >= 8 && x < 122 && y >= 1 && y < 65; };
    auto isRivet = [&](int x, int y, int z) {
        return z == 24 && x % 6 == 3 && y % 6 == 3 && x >= 16 && x < 100 && y >= 12 && y < 54;
    };
    VoxelVolume hull = hollowVolume(
        130, 66, 30,
        [&](int x, int y, int z) {
            return inTrack(x, y, z) || inHull(x, y, z) || inFender(x, y, z) || isRivet(x, y, z);
        },
        [&](int x, int y, int z) -> uint8_t {
            if (isRivet(x, y, z))
                return Rivet;
            if (inTrack(x, y, z) && !inHull(x, y, z) && !inFender(x, y, z))
                return Track;
            return camo(x, y, z);
        });

    // Turret: 115 long with the barrel, 46 wide, 22 high; its ring centred at (24, 23).
    auto inBody = [&](int x, int y, int z) {
        return z < 15 && std::hypot(centre(x) - 24.0, centre(y) - 23.0) < 20.0 - std::max(0.0, centre(z) - 9.0);
    };
    auto inHatch = [&](int x, int y, int z) {
        return z >= 15 && z < 18 && std::hypot(centre(x) - 18.0, centre(y) - 30.0) < 5.0;
    };
    auto inMantlet = [&](int x, int y, int z) { return x >= 40 && x < 50 && y >= 15 && y < 31 && z >= 3 && z < 13; };
    auto inBarrel = [&](int x, int y, int z) {
        const double r = std::hypot(centre(y) - 23.0, centre(z) - 8.0);
        return (x >= 48 && x < 106 && r < 3.2) || (x >= 102 && x < 114 && r < 4.6);
    };
    VoxelVolume turret = hollowVolume(
        115, 46, 22,
        [&](int x, int y, int z) {
            return inBody(x, y, z) || inHatch(x, y, z) || inMantlet(x, y, z) || inBarrel(x, y, z);
        },
        [&](int x, int y, int z) -> uint8_t {
            if (inBarrel(x, y, z) && !inMantlet(x, y, z))
                return Metal;
            if (inHatch(x, y, z))
                return Dark;
            return camo(x + 40, y + 10, z + 24);
        });

    std::vector<VoxelVolume> volumes;
    volumes.push_back(std::move(hull));
    volumes.push_back(std::move(turret));
    // Hull centred on the origin; turret ring a little behind the hull's middle, on its roof.
    std::vector<glm::mat4> place = {glm::translate(glm::mat4(1.0f), glm::vec3(-65.0f, -33.0f, 0.0f)),
                                    glm::translate(glm::mat4(1.0f), glm::vec3(-65.0f + 34.0f, -33.0f + 10.0f, 24.0f))};
    return volumesModel("synthetic tank", std::move(volumes), std::move(place), palette);
}

}  // namespace voxelfair::pipeline
