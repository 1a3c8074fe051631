// MATL chunks (formats/vox_materials.h): generated files with every material type, bad values and
// ids, truncated chunks; and the shared files' materials (robo.vox's emitter, test-transform.vox's
// glass).
#include "fixtures/vox_writer.h"
#include "formats/file_bytes.h"
#include "formats/format_error.h"
#include "formats/vox.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace voxelfair;
using namespace voxelfair::fixtures;

namespace {
const std::filesystem::path kModels = VOXELFAIR_MODELS_DIR;

VoxFile read(const Bytes &bytes) { return readVox(bytes.data(), bytes.size()); }
}  // namespace

TEST(VoxMaterials, EveryTypeAndItsPropertiesAreRead) {
    const VoxFile file = read(VoxWriter()
                                  .model(1, 1, 1, {{0, 0, 0, 1}})
                                  .material(1, {{"_type", "_emit"}, {"_emit", "0.5"}, {"_flux", "2"}})
                                  .material(2, {{"_type", "_glass"}, {"_alpha", "0.7"}, {"_ior", "0.3"}})
                                  .material(3, {{"_type", "_metal"}, {"_metal", "1"}, {"_rough", "0.25"}})
                                  .material(4, {{"_type", "_blend"}, {"_trans", "0.5"}, {"_spec", "0.1"}})
                                  .material(5, {{"_type", "_media"}})
                                  .material(6, {{"_type", "_diffuse"}, {"_rough", "0.1"}})
                                  .bytes(200));
    const auto &m = file.materials.byIndex;
    EXPECT_EQ(file.materials.chunks, 6u);
    EXPECT_EQ(m[1].type, VoxMaterialType::Emit);
    EXPECT_FLOAT_EQ(*m[1].emission, 0.5f);
    EXPECT_FLOAT_EQ(*m[1].flux, 2.0f);
    EXPECT_EQ(m[2].type, VoxMaterialType::Glass);
    EXPECT_FLOAT_EQ(*m[2].alpha, 0.7f);
    EXPECT_FLOAT_EQ(*m[2].ior, 0.3f);
    EXPECT_FALSE(m[2].trans.has_value());
    EXPECT_EQ(m[3].type, VoxMaterialType::Metal);
    EXPECT_FLOAT_EQ(*m[3].rough, 0.25f);
    EXPECT_EQ(m[4].type, VoxMaterialType::Blend);
    EXPECT_EQ(m[5].type, VoxMaterialType::Media);
    EXPECT_EQ(m[6].type, VoxMaterialType::Diffuse);
    EXPECT_EQ(m[7].type, VoxMaterialType::Diffuse);  // no chunk
    EXPECT_TRUE(file.materials.any());
    EXPECT_FALSE(read(VoxWriter().model(1, 1, 1, {{0, 0, 0, 1}}).bytes()).materials.any());
}

TEST(VoxMaterials, BadValuesAndIdsAreIgnoredAndCounted) {
    const VoxFile file = read(VoxWriter()
                                  .model(1, 1, 1, {{0, 0, 0, 1}})
                                  .material(1, {{"_type", "_metal"}, {"_metal", "lots"}, {"_rough", "nan"}})
                                  .material(2, {{"_type", "_shiny"}, {"_emit", "1e9"}, {"_flux", "-3"}})
                                  .material(0, {{"_type", "_emit"}})
                                  .material(256, {{"_type", "_emit"}})
                                  .material(-7, {{"_type", "_emit"}})
                                  .bytes(200));
    const auto &m = file.materials.byIndex;
    EXPECT_EQ(m[1].type, VoxMaterialType::Metal);
    EXPECT_FALSE(m[1].metal.has_value());
    EXPECT_FALSE(m[1].rough.has_value());
    EXPECT_EQ(m[2].type, VoxMaterialType::Diffuse);  // unknown type
    EXPECT_FLOAT_EQ(*m[2].emission, 1.0f);           // clamped into 0..1
    EXPECT_FLOAT_EQ(*m[2].flux, 0.0f);
    EXPECT_EQ(m[0].type, VoxMaterialType::Diffuse);
    EXPECT_EQ(file.materials.ignoredValues, 3u);
    EXPECT_EQ(file.materials.ignoredChunks, 3u);
    EXPECT_EQ(file.materials.chunks, 2u);
}

TEST(VoxMaterials, TruncatedChunksAreFormatErrorsNamingTheChunk) {
    for (const Bytes &content :
         {Bytes{1, 0}, VoxContent().i32(1).i32(5).bytes(), VoxContent().i32(1).i32(1).i32(100).bytes()}) {
        const Bytes bytes = VoxWriter().model(1, 1, 1, {{0, 0, 0, 1}}).chunk("MATL", content).bytes();
        try {
            read(bytes);
            ADD_FAILURE() << "accepted a truncated MATL chunk";
        } catch (const FormatError &e) {
            EXPECT_NE(std::string(e.what()).find("chunk 'MATL'"), std::string::npos) << e.what();
        }
    }
}

TEST(VoxMaterials, SharedFilesHaveRobosEmitterAndTestTransformsGlass) {
    if (!std::filesystem::is_directory(kModels / "vox"))
        GTEST_SKIP() << "shared models folder " << kModels.string() << " is absent";
    const auto load = [&](const char *name) {
        const std::vector<uint8_t> bytes = readFileBytes((kModels / "vox" / name).string());
        return readVox(bytes.data(), bytes.size());
    };
    const VoxFile robo = load("robo.vox");
    EXPECT_EQ(robo.materials.byIndex[143].type, VoxMaterialType::Emit);
    EXPECT_FLOAT_EQ(robo.materials.byIndex[143].emission.value_or(0), 1.0f);
    const VoxFile glass = load("test-transform.vox");
    EXPECT_EQ(glass.materials.byIndex[211].type, VoxMaterialType::Glass);
    EXPECT_FLOAT_EQ(glass.materials.byIndex[211].alpha.value_or(0), 0.73f);
    EXPECT_EQ(glass.materials.ignoredValues, 0u);
}
