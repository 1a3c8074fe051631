// MagicaVoxel import speed. Target (issue 7): a 160k-voxel model imported -- parsed, its volume
// built and its scene made -- within 50 ms. The models are written by the testkit's fixture writer:
// the level-4 Menger sponge (81^3, exactly 160 000 voxels, like ephtracy's menger.vox) in the
// file's usual order and shuffled, and a dense 100 x 100 x 16 box in random order. The shared
// test-transform.vox (3 models, 20 instances) is measured too when the models folder is present.
#include "fixtures/vox_writer.h"
#include "formats/file_bytes.h"
#include "formats/vox.h"
#include "scene/vox_scene.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <random>

using namespace voxelfair;
using namespace voxelfair::fixtures;

namespace {

enum Model { kMenger, kMengerShuffled, kDenseRandom, kTestTransform };

Bytes makeModel(Model which) {
    std::mt19937 random(7);
    switch (which) {
    case kMenger: return VoxWriter().model(81, 81, 81, mengerSponge(4)).bytes();
    case kMengerShuffled: {
        std::vector<VoxVoxel> voxels = mengerSponge(4);
        std::shuffle(voxels.begin(), voxels.end(), random);
        return VoxWriter().model(81, 81, 81, voxels).bytes();
    }
    case kDenseRandom: {
        std::vector<VoxVoxel> voxels;
        for (int z = 0; z < 16; ++z)
            for (int y = 0; y < 100; ++y)
                for (int x = 0; x < 100; ++x)
                    voxels.push_back({uint8_t(x), uint8_t(y), uint8_t(z), uint8_t(1 + random() % 255)});
        std::shuffle(voxels.begin(), voxels.end(), random);
        return VoxWriter().model(100, 100, 16, voxels).bytes();
    }
    case kTestTransform: {
        const std::filesystem::path path = std::filesystem::path(VOXELFAIR_MODELS_DIR) / "vox" / "test-transform.vox";
        return std::filesystem::exists(path) ? readFileBytes(path.string()) : Bytes{};
    }
    }
    return {};
}

const Bytes &model(Model which) {
    static const Bytes models[] = {makeModel(kMenger), makeModel(kMengerShuffled), makeModel(kDenseRandom),
                                   makeModel(kTestTransform)};
    return models[which];
}

const char *const kNames[] = {"menger", "menger_shuffled", "dense_random", "test-transform"};

// Parse + build volumes + scene: the import measured against the 50 ms target.
void BM_VoxImport(benchmark::State &state) {
    const Model which = Model(state.range(0));
    const Bytes &bytes = model(which);
    state.SetLabel(kNames[which]);
    if (bytes.empty())
        return state.SkipWithError("shared models folder missing");
    size_t voxels = 0;
    for (auto _ : state) {
        const VoxFile file = readVox(bytes.data(), bytes.size());
        const VoxelScene scene = voxScene(file);
        benchmark::DoNotOptimize(scene.parts.data());
        voxels = 0;
        for (const VoxelVolume &m : file.models)
            voxels += m.voxelCount();
    }
    state.counters["voxels"] = double(voxels);
    state.counters["bytes"] = double(bytes.size());
}
BENCHMARK(BM_VoxImport)->DenseRange(kMenger, kTestTransform)->Unit(benchmark::kMillisecond);

// The meshing that follows the import (extractSceneSurface over every instance).
void BM_VoxExtractScene(benchmark::State &state) {
    const Model which = Model(state.range(0));
    const Bytes &bytes = model(which);
    state.SetLabel(kNames[which]);
    if (bytes.empty())
        return state.SkipWithError("shared models folder missing");
    const VoxFile file = readVox(bytes.data(), bytes.size());
    const VoxelScene scene = voxScene(file);
    size_t quads = 0;
    for (auto _ : state) {
        const SceneSurface surface = extractSceneSurface(scene);
        quads = surface.quadCount();
        benchmark::DoNotOptimize(surface.quads.data());
    }
    state.counters["quads"] = double(quads);
}
BENCHMARK(BM_VoxExtractScene)->Arg(kMenger)->Arg(kDenseRandom)->Arg(kTestTransform)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
