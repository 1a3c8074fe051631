// Every real .vox file in the shared folder loads with the numbers an independent reading gave
// (a throwaway Python parser of the spec's layout, flattening the scene graph with integer
// matrices): models, instances, voxels and the world bounds of all instance voxels.
#include "formats/file_bytes.h"
#include "formats/format_error.h"
#include "formats/vox.h"
#include "scene/vox_scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <glm/common.hpp>

using namespace voxelfair;
namespace fs = std::filesystem;

namespace {

struct ModelFacts {
    int sizeX, sizeY, sizeZ;
    size_t voxels;
};

struct FileFacts {
    const char *name;
    std::vector<ModelFacts> models;
    size_t instances;
    size_t instanceVoxels;  // summed over instances
    glm::vec3 lo, hi;       // world bounds of the instances' voxel cubes
    std::vector<std::string> firstNames;
};

// clang-format off
const std::vector<FileFacts> kFiles = {
    {"8ontop", std::vector<ModelFacts>(8, {12, 14, 1, 168}), 72, 12096, {-213, -247, 7}, {239, 244, 87},
     {"1", "2", "3", "4"}},
    {"crabby", {{50, 50, 50, 0}, {10, 8, 7, 100}}, 2, 100, {-5, -4, 0}, {5, 4, 7}, {"Matrix", "crabby"}},
    {"robo", {{7, 9, 7, 186}, {7, 6, 4, 63}, {22, 21, 23, 1042}}, 3, 1291, {-26, 5, 0}, {-4, 26, 30},
     {"Head_Upper", "Head_Lower", "Head_Neck"}},
    {"test-transform", {{128, 128, 128, 98304}, {39, 40, 40, 8262}, {40, 40, 30, 20240}}, 20, 621232,
     {-129, -128, 0}, {127, 128, 50}, {"original", "clone", "top red", "front red"}},
};
// clang-format on

fs::path voxFolder() { return fs::path(VOXELFAIR_MODELS_DIR) / "vox"; }

std::vector<uint8_t> load(const std::string &name) { return readFileBytes((voxFolder() / (name + ".vox")).string()); }

}  // namespace

TEST(VoxSharedModels, LoadWithTheExpectedFacts) {
    if (!fs::is_directory(voxFolder()))
        GTEST_SKIP() << "shared models folder missing: " << voxFolder();
    for (const FileFacts &facts : kFiles) {
        SCOPED_TRACE(facts.name);
        const std::vector<uint8_t> bytes = load(facts.name);
        const VoxFile file = readVox(bytes.data(), bytes.size());
        EXPECT_EQ(file.version, 150);
        EXPECT_FALSE(file.defaultPalette);
        EXPECT_EQ(file.frameCount, 1);
        ASSERT_EQ(file.models.size(), facts.models.size());
        for (size_t m = 0; m < facts.models.size(); ++m) {
            EXPECT_EQ(file.models[m].sizeX, facts.models[m].sizeX) << "model " << m;
            EXPECT_EQ(file.models[m].sizeY, facts.models[m].sizeY) << "model " << m;
            EXPECT_EQ(file.models[m].sizeZ, facts.models[m].sizeZ) << "model " << m;
            EXPECT_EQ(file.models[m].voxelCount(), facts.models[m].voxels) << "model " << m;
        }

        const VoxelScene scene = voxScene(file);
        ASSERT_EQ(scene.parts.size(), facts.instances);
        for (size_t i = 0; i < facts.firstNames.size(); ++i)
            EXPECT_EQ(scene.parts[i].name, facts.firstNames[i]);
        size_t voxels = 0;
        glm::vec3 lo(INFINITY), hi(-INFINITY);
        for (const PlacedVolume &part : scene.parts) {
            const VoxelVolume &v = *part.volume;
            voxels += v.voxelCount();
            for (int y = 0; y < v.sizeY; ++y)
                for (int x = 0; x < v.sizeX; ++x)
                    for (uint32_t r = v.columnFirstRun[v.columnIndex(x, y)];
                         r < v.columnFirstRun[v.columnIndex(x, y) + 1]; ++r)
                        for (int z = v.runs[r].zBegin; z < v.runs[r].zEnd; ++z) {
                            const glm::vec3 a(part.toModel * glm::vec4(x, y, z, 1));
                            const glm::vec3 b(part.toModel * glm::vec4(x + 1, y + 1, z + 1, 1));
                            lo = glm::min(lo, glm::min(a, b));
                            hi = glm::max(hi, glm::max(a, b));
                        }
        }
        EXPECT_EQ(voxels, facts.instanceVoxels);
        EXPECT_EQ(lo, facts.lo);
        EXPECT_EQ(hi, facts.hi);
    }
}

TEST(VoxSharedModels, TeardownCompressedModelsLoad) {
    if (!fs::is_directory(voxFolder()))
        GTEST_SKIP() << "shared models folder missing: " << voxFolder();
    // teardown.vox stores its 8 models as TDCZ chunks; the solid voxels per model are those of an
    // independent reading (Python's zlib.decompressobj over each stream, non-zero bytes counted).
    const std::vector<uint8_t> bytes = load("teardown");
    const VoxFile file = readVox(bytes.data(), bytes.size());
    const std::vector<ModelFacts> expected = {{10, 2, 13, 142}, {10, 9, 1, 86},   {4, 11, 11, 316}, {4, 11, 11, 316},
                                              {4, 11, 11, 316}, {4, 11, 11, 316}, {4, 11, 11, 316}, {34, 54, 20, 9056}};
    ASSERT_EQ(file.models.size(), expected.size());
    size_t total = 0;
    for (size_t m = 0; m < expected.size(); ++m) {
        EXPECT_EQ(file.models[m].sizeX, expected[m].sizeX) << "model " << m;
        EXPECT_EQ(file.models[m].sizeY, expected[m].sizeY) << "model " << m;
        EXPECT_EQ(file.models[m].sizeZ, expected[m].sizeZ) << "model " << m;
        EXPECT_EQ(file.models[m].voxelCount(), expected[m].voxels) << "model " << m;
        total += file.models[m].voxelCount();
    }
    EXPECT_EQ(total, 10864u);
    EXPECT_FALSE(file.defaultPalette);
    const VoxelScene scene = voxScene(file);
    EXPECT_EQ(scene.parts.size(), 8u);
}
