// Section 4.2 mesh extraction (cavity fill + manifold boundary quads). Target: a 64k-voxel
// section in at most 20 ms.
#include "extraction/boundary_surface.h"
#include "shapes/dense_grid.h"
#include "formats/file_bytes.h"
#include "formats/vxl.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <exception>
#include <random>
#include <string>

using namespace voxelfair;
using namespace voxelfair::test;

namespace {

// Extracts every volume once per iteration; counters describe one iteration.
void extract(benchmark::State &state, const std::vector<VoxelVolume> &volumes) {
    size_t voxels = 0, quads = 0, vertices = 0;
    for (const VoxelVolume &v : volumes)
        voxels += v.voxelCount();
    for (auto _ : state) {
        quads = vertices = 0;
        for (const VoxelVolume &v : volumes) {
            const BoundarySurface s = extractBoundarySurface(v);
            benchmark::DoNotOptimize(s.quads.data());
            quads += s.quadCount();
            vertices += s.positions.size();
        }
    }
    state.counters["voxels"] = double(voxels);
    state.counters["quads"] = double(quads);
    state.counters["vertices"] = double(vertices);
}

// Overlapping balls along a random walk until 64k voxels: a lumpy organic shape.
DenseGrid blob(size_t targetVoxels) {
    const int side = 64;
    DenseGrid g(side, side, side);
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> step(-4, 4), radius(3, 8);
    int c[3] = {side / 2, side / 2, side / 2};
    size_t count = 0;
    while (count < targetVoxels) {
        const int r = radius(rng);
        for (int z = c[2] - r; z <= c[2] + r; ++z)
            for (int y = c[1] - r; y <= c[1] + r; ++y)
                for (int x = c[0] - r; x <= c[0] + r; ++x) {
                    const int dx = x - c[0], dy = y - c[1], dz = z - c[2];
                    if (dx * dx + dy * dy + dz * dz > r * r || !g.inside(x, y, z) || g.at(x, y, z))
                        continue;
                    g.set(x, y, z);
                    ++count;
                }
        for (int &ci : c)
            ci = std::clamp(ci + step(rng), 10, side - 11);
    }
    return g;
}

void BM_Sphere24(benchmark::State &state) { extract(state, {sphere(24).toVolume()}); }
void BM_Box40(benchmark::State &state) { extract(state, {box(40, 40, 40).toVolume()}); }
// A VXL-like hull: 40^3 with 3-voxel walls around a cavity the fill closes.
void BM_Shell40(benchmark::State &state) { extract(state, {hollowBox(40, 3).toVolume()}); }
void BM_Blob64k(benchmark::State &state) { extract(state, {blob(64000).toVolume()}); }
// Worst case: independent random voxels (58% of 48^3), full of edge and corner contacts.
void BM_RandomNoise64k(benchmark::State &state) { extract(state, {randomGrid(48, 48, 48, 0.58, 1).toVolume()}); }

// All sections of a shared model.
void BM_VxlModel(benchmark::State &state, const std::string &file) {
    const std::string path = std::string(VOXELFAIR_MODELS_DIR) + "/vxl/" + file;
    std::vector<VoxelVolume> volumes;
    try {
        const std::vector<uint8_t> bytes = readFileBytes(path);
        for (VxlSection &section : readVxl(bytes.data(), bytes.size()).sections)
            volumes.push_back(std::move(section.volume));
    } catch (const std::exception &e) {
        state.SkipWithError(e.what());
        return;
    }
    extract(state, volumes);
}

}  // namespace

BENCHMARK(BM_Sphere24)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Box40)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Shell40)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Blob64k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RandomNoise64k)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VxlModel, subapc, std::string("subapc.vxl"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VxlModel, cc, std::string("cc.vxl"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VxlModel, legs, std::string("legs.vxl"))->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
