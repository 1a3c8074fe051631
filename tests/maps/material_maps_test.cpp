// VOX materials as PBR maps (maps/material_maps.h): the mapping per material type, and through the
// paper's chain (extraction, fairing, attributes, atlas) every face's interior samples carry its
// own material in every map, on generated blobs with random materials (fixed seeds) and on the
// shared files with materials (robo.vox's emitter, test-transform.vox's glass and blend).
#include "maps/material_maps.h"

#include "base/error.h"
#include "pipeline/face_value_runs.h"
#include "shapes/analytic_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

using namespace voxelfair;
using namespace voxelfair::pipeline;

namespace {

const std::filesystem::path kModels = VOXELFAIR_MODELS_DIR;

uint8_t unorm(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }
float linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

struct Checked {
    MaterialMaps maps;
    size_t samples = 0, wrongMetalRough = 0, wrongEmissive = 0, wrongTransmission = 0;
};

Checked checkMaps(const Model &model, const VoxMaterialTable &materials) {
    const FaceValueRun run = faceValueRun(model);
    const int w = run.atlas.texture.width, h = run.atlas.texture.height;
    const std::vector<glm::u8vec3> &colours = run.attributes.triangleColours;
    const FaceValueMesh view = run.view();
    Checked c;
    c.maps = bakeMaterialMaps(view, run.paletteIndex.data(), colours.data(), materials, w, h, 2);
    const MaterialMaps &m = c.maps;
    const auto at = [&](const std::vector<uint8_t> &image, int channels, int x, int y, int k) {
        return image[(size_t(h - 1 - y) * size_t(w) + size_t(x)) * size_t(channels) + size_t(k)];
    };
    forEachInteriorTexel(view.wedgeUv, view.faceCount, w, h, [&](size_t f, int x, int y) {
        const PbrVoxel p = pbrOf(materials.byIndex[run.paletteIndex[f]]);
        const glm::u8vec3 colour = colours[f];
        ++c.samples;
        if (!m.metallicRoughness.empty() && (at(m.metallicRoughness, 3, x, y, 1) != unorm(p.roughness) ||
                                             at(m.metallicRoughness, 3, x, y, 2) != unorm(p.metallic)))
            ++c.wrongMetalRough;
        if (!m.emissive.empty())
            for (int k = 0; k < 3; ++k) {  // decoded as a renderer does: linear colour * strength
                const float emitted = linear(at(m.emissive, 3, x, y, k) / 255.0f) * m.emissiveStrength;
                const float expected = linear(colour[k] / 255.0f) * p.emission;
                if (std::abs(emitted - expected) > 0.01f * std::max(1.0f, m.emissiveStrength))
                    ++c.wrongEmissive;
            }
        if (!m.transmission.empty() && at(m.transmission, 1, x, y, 0) != unorm(p.transmission))
            ++c.wrongTransmission;
    });
    return c;
}

}  // namespace

TEST(MaterialMaps, EachTypeMapsToItsGltfProperties) {
    VoxMaterial m;
    EXPECT_EQ(pbrOf(m).metallic, 0.0f);
    EXPECT_FLOAT_EQ(pbrOf(m).roughness, 0.9f);
    m.rough = 0.1f;  // a diffuse material's sliders do not apply
    EXPECT_FLOAT_EQ(pbrOf(m).roughness, 0.9f);
    m.type = VoxMaterialType::Metal;
    EXPECT_EQ(pbrOf(m).metallic, 1.0f);
    EXPECT_FLOAT_EQ(pbrOf(m).roughness, 0.1f);
    m = {};
    m.type = VoxMaterialType::Emit;
    m.emission = 0.5f;
    m.flux = 2.0f;
    EXPECT_FLOAT_EQ(pbrOf(m).emission, 2.0f);
    m = {};
    m.type = VoxMaterialType::Glass;
    m.alpha = 0.73f;
    m.ior = 0.3f;
    EXPECT_FLOAT_EQ(pbrOf(m).transmission, 0.73f);
    EXPECT_FLOAT_EQ(pbrOf(m).ior, 1.3f);
    m.trans = 0.2f;  // _trans wins over _alpha
    EXPECT_FLOAT_EQ(pbrOf(m).transmission, 0.2f);
    m = {};
    m.type = VoxMaterialType::Media;
    m.emission = 1.0f;
    EXPECT_EQ(pbrOf(m).emission, 0.0f);
}

TEST(MaterialMaps, EveryFaceCarriesItsMaterialOnGeneratedBlobs) {
    for (uint32_t seed = 1; seed <= 3; ++seed) {
        SCOPED_TRACE(seed);
        std::mt19937 random(seed);
        Palette palette;
        for (int i = 0; i < 256; ++i)
            palette.colours[size_t(i)] = Rgb{uint8_t(i), uint8_t(255 - i), uint8_t(7 * i)};
        VoxMaterialTable materials;
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        for (size_t i = 1; i < 256; ++i) {
            VoxMaterial &m = materials.byIndex[i];
            m.type = VoxMaterialType(random() % 6);
            m.metal = u(random), m.rough = u(random), m.emission = u(random), m.alpha = u(random);
            m.flux = float(random() % 4), m.ior = u(random);
        }
        const double r = 6.0 + 4.0 * u(random);
        const uint32_t salt = random();
        auto payload = [&](int x, int y, int z) {
            uint32_t hash =
                uint32_t(x / 3) * 73856093u ^ uint32_t(y / 3) * 19349663u ^ uint32_t(z / 3) * 83492791u ^ salt;
            hash ^= hash >> 13;
            hash *= 0x5bd1e995u;
            return Voxel{uint8_t(1 + (hash >> 8) % 255), 0};
        };
        const auto model =
            volumeModel("blob", shapes::voxelize(shapes::sphere(glm::dvec3(r + 1.5), r), payload), palette);
        const Checked c = checkMaps(*model, materials);
        EXPECT_FALSE(c.maps.metallicRoughness.empty());
        EXPECT_FALSE(c.maps.emissive.empty());
        EXPECT_FALSE(c.maps.transmission.empty());
        EXPECT_GT(c.maps.emissiveStrength, 1.0f);
        EXPECT_GT(c.samples, 1000u);
        EXPECT_EQ(c.wrongMetalRough, 0u);
        EXPECT_EQ(c.wrongEmissive, 0u);
        EXPECT_EQ(c.wrongTransmission, 0u);
    }
}

TEST(MaterialMaps, SharedFilesGetTheirEmitterAndGlass) {
    if (!std::filesystem::is_directory(kModels / "vox"))
        GTEST_SKIP() << "shared models folder " << kModels.string() << " is absent";
    for (const char *name : {"robo", "test-transform", "crabby"}) {
        SCOPED_TRACE(name);
        const auto model = loadVox((kModels / "vox" / (std::string(name) + ".vox")).string());
        const Checked c = checkMaps(*model, model->vox.materials);
        const MaterialMaps &m = c.maps;
        std::printf("%-15s %5zu metal/rough, %5zu emissive (strength %.2f), %5zu transmissive (ior %.2f) faces, "
                    "%zu samples\n",
                    name, m.metalRoughFaces, m.emissiveFaces, double(m.emissiveStrength), m.transmissiveFaces,
                    double(m.ior), c.samples);
        EXPECT_EQ(c.wrongMetalRough + c.wrongEmissive + c.wrongTransmission, 0u);
        if (std::string(name) == "robo") {
            EXPECT_GT(m.emissiveFaces, 0u);
        }
        if (std::string(name) == "crabby") {
            EXPECT_TRUE(m.empty());  // all diffuse: no maps
        }
    }
}

TEST(MaterialMaps, BadInputIsAClearError) {
    const glm::vec3 positions[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const uint32_t triangles[3] = {0, 1, 2};
    const glm::vec2 uv[3] = {{0, 0}, {1, 0}, {0, 1}};
    const FaceValueMesh mesh{{positions, 3, triangles, 1}, uv};
    const uint8_t index[1] = {1};
    const glm::u8vec3 colour[1] = {{10, 20, 30}};
    EXPECT_THROW(bakeMaterialMaps(mesh, nullptr, colour, {}, 8, 8, 2), MeshError);
    EXPECT_THROW(bakeMaterialMaps(mesh, index, nullptr, {}, 8, 8, 2), MeshError);
    VoxMaterialTable metal;
    metal.byIndex[1].type = VoxMaterialType::Metal;
    EXPECT_THROW(bakeMaterialMaps(mesh, index, colour, metal, 8, 0, 2), OptionError);
    EXPECT_TRUE(bakeMaterialMaps(mesh, index, colour, {}, 8, 8, 2).empty());
}
