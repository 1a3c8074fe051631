// The house colour mask (maps/house_mask.h) on the shared VXL models (their bodies with turret and
// barrel, as the importer loads them) and on generated blobs with random palette indices (fixed
// seeds): through the paper's chain (extraction, fairing, attributes, atlas), the mask is 255 at
// every interior sample of every face whose voxel uses the remap range (16..31) and 0 at those of
// every other face, and the base colour there keeps the palette's own colour.
#include "maps/house_mask.h"

#include "base/error.h"
#include "pipeline/face_value_runs.h"
#include "shapes/analytic_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

using namespace voxelfair;
using namespace voxelfair::pipeline;

namespace {

const std::filesystem::path kModels = VOXELFAIR_MODELS_DIR;

struct Checked {
    size_t houseFaces = 0, samples = 0, wrong = 0, wrongColour = 0;
};

Checked checkMask(const Model &model) {
    const FaceValueRun run = faceValueRun(model);
    const AtlasTexture &base = run.atlas.texture;
    const FaceValueMesh view = run.view();
    const HouseMask mask = bakeHouseMask(view, run.paletteIndex.data(), base.width, base.height, 2);
    EXPECT_EQ(mask.width, base.width);
    EXPECT_EQ(mask.height, base.height);

    Checked out;
    out.houseFaces = mask.houseFaces;
    forEachInteriorTexel(view.wedgeUv, view.faceCount, base.width, base.height, [&](size_t f, int x, int y) {
        const bool house = isRemapIndex(run.paletteIndex[f]);
        const Rgb colour = model.scene.palette.colours[run.paletteIndex[f]];
        ++out.samples;
        if (mask.texel(x, y) != (house ? 255 : 0))
            ++out.wrong;
        const glm::u8vec4 c = base.texel(x, y);
        if (c.r != colour.r || c.g != colour.g || c.b != colour.b)
            ++out.wrongColour;
    });
    return out;
}

}  // namespace

TEST(HouseMask, CoversExactlyTheRemapVoxelsOfEverySharedVxlModel) {
    if (!std::filesystem::is_directory(kModels / "vxl"))
        GTEST_SKIP() << "shared models folder " << kModels.string() << " is absent";
    size_t models = 0, withHouse = 0;
    for (const auto &entry : std::filesystem::directory_iterator(kModels / "vxl")) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() != ".vxl")
            continue;
        // A turret or barrel file comes with its body (a turret without one, art2tur, on its own).
        if (isUnitCompanionStem(stem) &&
            (std::filesystem::exists(entry.path().parent_path() / (stem.substr(0, stem.size() - 3) + ".vxl")) ||
             std::filesystem::exists(entry.path().parent_path() / (stem.substr(0, stem.size() - 4) + ".vxl"))))
            continue;
        std::unique_ptr<Model> model;
        try {
            model = loadVxl(entry.path().string(), (kModels / "pal").string(), true);
        } catch (const Error &e) {
            std::printf("%-14s not accepted by the reader: %s\n", stem.c_str(), e.what());
            continue;
        }
        if (model->solidVoxels() == 0)
            continue;
        SCOPED_TRACE(stem);
        const Checked c = checkMask(*model);
        std::printf("%-14s %6zu house faces, %7zu samples, %zu wrong mask, %zu wrong colour\n", stem.c_str(),
                    c.houseFaces, c.samples, c.wrong, c.wrongColour);
        EXPECT_EQ(c.wrong, 0u);
        EXPECT_EQ(c.wrongColour, 0u);
        ++models;
        withHouse += c.houseFaces > 0 ? 1 : 0;
    }
    EXPECT_GE(models, 13u);
    EXPECT_GE(withHouse, 5u);  // the unit models paint their team stripes in the remap range
}

TEST(HouseMask, CoversExactlyTheRemapVoxelsOfGeneratedBlobs) {
    for (uint32_t seed = 1; seed <= 4; ++seed) {
        SCOPED_TRACE(seed);
        std::mt19937 random(seed);
        Palette palette;
        for (int i = 0; i < 256; ++i)  // distinct colours: index i -> (i, 255 - i, 7 * i)
            palette.colours[size_t(i)] = Rgb{uint8_t(i), uint8_t(255 - i), uint8_t(7 * i)};
        std::uniform_real_distribution<double> radius(5.0, 11.0);
        const double r = radius(random);
        const shapes::Shape shape = shapes::sphere(glm::dvec3(r + 1.5), r);
        // Patches of 3 x 3 x 3 voxels share an index, half of them in the remap range.
        const uint32_t salt = random();
        auto payload = [&](int x, int y, int z) {
            uint32_t h = uint32_t(x / 3) * 73856093u ^ uint32_t(y / 3) * 19349663u ^ uint32_t(z / 3) * 83492791u ^ salt;
            h ^= h >> 13;
            h *= 0x5bd1e995u;
            const uint8_t index = (h >> 7) % 2 ? uint8_t(16 + (h >> 9) % 16) : uint8_t(32 + (h >> 9) % 200);
            return Voxel{index, 0};
        };
        const auto model = volumeModel("blob", shapes::voxelize(shape, payload), palette);
        const Checked c = checkMask(*model);
        EXPECT_GT(c.houseFaces, 0u);
        EXPECT_GT(c.samples, 1000u);
        EXPECT_EQ(c.wrong, 0u);
        EXPECT_EQ(c.wrongColour, 0u);
    }
}

TEST(HouseMask, BadInputIsAClearError) {
    const glm::vec3 positions[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const uint32_t triangles[3] = {0, 1, 5};
    const glm::vec2 uv[3] = {{0, 0}, {1, 0}, {0, 1}};
    const uint8_t index[1] = {20};
    FaceValueMesh mesh{{positions, 3, triangles, 1}, uv};
    EXPECT_THROW(bakeHouseMask(mesh, index, 8, 8, 2), MeshError);
    const uint32_t good[3] = {0, 1, 2};
    mesh.triangles = good;
    EXPECT_THROW(bakeHouseMask(mesh, nullptr, 8, 8, 2), MeshError);
    EXPECT_THROW(bakeHouseMask(mesh, index, 0, 8, 2), OptionError);
    EXPECT_THROW(bakeHouseMask(mesh, index, 8, 8, -1), OptionError);
    const HouseMask mask = bakeHouseMask(mesh, index, 8, 8, 2);
    EXPECT_EQ(mask.houseFaces, 1u);
    EXPECT_EQ(mask.texel(1, 1), 255);
    EXPECT_EQ(mask.texel(7, 7), 0);
}
