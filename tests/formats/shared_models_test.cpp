// Every real model in the shared folder loads with the numbers an independent reading of the
// files gave (a throwaway Python parser of the layout in doc/formats/westwood.md), with and without each palette.
#include "fixtures/vxl_fixtures.h"
#include "formats/file_bytes.h"
#include "formats/hva.h"
#include "formats/palette.h"
#include "formats/vxl.h"
#include "formats/vxl_placement.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>
#include <ostream>
#include <set>
#include <string>
#include <vector>

using namespace voxelfair;
namespace fs = std::filesystem;

namespace {

struct SectionFacts {
    int sizeX, sizeY, sizeZ;
    size_t voxels;
    int normalType;
    size_t clampedNormals;
    glm::vec3 minBounds, maxBounds;
};

struct ModelFacts {
    const char *name;
    bool embeddedPaletteAllZero;
    int hvaFrames;  // 0: no .hva beside the model
    int hvaSections;
    std::vector<SectionFacts> sections;
};

// Test names and failure messages show the model by name.
void PrintTo(const ModelFacts &facts, std::ostream *out) { *out << facts.name; }

// clang-format off
const std::vector<ModelFacts> kModels = {
    {"3tnk", false, 1, 1, {
        {61, 27, 11, 5954, 2, 0, {-29.8108006f, -13.4883995f, -0.596599579f}, {31.1891994f, 13.5116005f, 10.4034004f}},
    }},
    {"3tnkbarl", false, 1, 1, {
        {61, 27, 15, 122, 2, 0, {-22.0198002f, -12.9006004f, 10.4632492f}, {38.9802017f, 14.0993996f, 25.4632492f}},
    }},
    {"3tnktur", false, 1, 1, {
        {61, 27, 15, 1937, 2, 0, {-22.0198002f, -12.9006004f, 10.4632492f}, {38.9802017f, 14.0993996f, 25.4632492f}},
    }},
    {"art2tur", false, 1, 1, {
        {1, 9, 1, 0, 4, 0, {-0.5f, -4.5f, 0.0f}, {0.5f, 4.5f, 1.0f}},
    }},
    {"cc", true, 1, 1, {
        {69, 39, 17, 33005, 2, 0, {-32.5f, -19.5f, 0.0f}, {36.5f, 19.5f, 17.0f}},
    }},
    {"hind", false, 2, 2, {
        {85, 84, 4, 543, 2, 0, {-44.2870026f, -41.4931984f, 12.2800007f}, {40.8135986f, 42.2803993f, 14.6408997f}},
        {74, 36, 28, 5150, 2, 0, {-41.7869987f, -17.905899f, 1.77999997f}, {37.7083015f, 17.905899f, 28.9860001f}},
    }},
    {"hmec", false, 17, 13, {
        {14, 13, 5, 160, 2, 0, {-6.9885211f, -6.09405994f, -0.744253278f}, {6.61835432f, 6.09405994f, 4.14124584f}},
        {9, 9, 13, 277, 2, 0, {-2.92861557f, -4.26835632f, -9.63818073f}, {5.4945507f, 4.26835537f, 2.38192558f}},
        {10, 4, 12, 293, 2, 0, {-6.80181503f, -1.75374305f, -8.85340691f}, {3.1902492f, 1.75374341f, 2.46337962f}},
        {14, 13, 6, 169, 2, 0, {-6.90725899f, -6.11392689f, -0.729420364f}, {6.73474693f, 6.10952187f, 4.45433426f}},
        {8, 9, 12, 254, 2, 0, {-3.75379729f, -4.2683568f, -8.95816803f}, {4.15651703f, 4.26835537f, 2.68478918f}},
        {8, 4, 13, 266, 2, 0, {-2.39735866f, -1.75374305f, -9.77641392f}, {4.88958836f, 1.75374341f, 2.33402061f}},
        {14, 13, 5, 160, 2, 0, {-7.00190735f, -6.09405899f, -0.698083103f}, {6.60498953f, 6.09406042f, 4.17272949f}},
        {10, 9, 12, 286, 2, 0, {-3.06281567f, -4.26835728f, -9.23493004f}, {6.39435863f, 4.26835537f, 2.45524287f}},
        {10, 4, 12, 273, 2, 0, {-3.22520161f, -1.75374341f, -9.30414009f}, {5.87263775f, 1.75374305f, 2.49417377f}},
        {14, 13, 6, 164, 2, 0, {-7.04027176f, -6.09405899f, -0.738783836f}, {6.5666008f, 6.09406042f, 4.44402122f}},
        {6, 9, 12, 252, 2, 0, {-3.08871603f, -4.26835632f, -9.4578476f}, {2.62457347f, 4.26835537f, 2.49151421f}},
        {10, 4, 12, 254, 2, 0, {-6.0353694f, -1.75374353f, -9.20003319f}, {3.45105052f, 1.75374293f, 2.410321f}},
        {53, 31, 20, 6200, 2, 0, {-26.0457115f, -15.325407f, -9.61439514f}, {26.0457115f, 14.9975052f, 10.3041897f}},
    }},
    {"jeep", false, 1, 1, {
        {32, 14, 13, 2220, 2, 0, {-15.6370068f, -6.86374664f, -6.86747503f}, {15.3762693f, 6.83926153f, 5.33562756f}},
    }},
    {"legs", true, 1, 18, {
        {25, 9, 23, 1516, 4, 0, {-8.74999905f, -3.14999962f, -8.04999924f}, {8.74999905f, 3.14999962f, 8.04999924f}},
        {25, 9, 23, 1516, 4, 0, {-8.74999905f, -3.14999962f, -8.04999924f}, {8.74999905f, 3.14999962f, 8.04999924f}},
        {25, 9, 23, 1516, 4, 0, {-8.74999905f, -3.14999962f, -8.04999924f}, {8.74999905f, 3.14999962f, 8.04999924f}},
        {25, 9, 23, 1516, 4, 0, {-8.74999905f, -3.14999962f, -8.04999924f}, {8.74999905f, 3.14999962f, 8.04999924f}},
        {25, 9, 23, 1516, 4, 0, {-8.74999905f, -3.14999962f, -8.04999924f}, {8.74999905f, 3.14999962f, 8.04999924f}},
        {25, 9, 23, 1516, 4, 0, {-8.74999905f, -3.14999962f, -8.04999924f}, {8.74999905f, 3.14999962f, 8.04999924f}},
        {27, 9, 42, 1632, 4, 0, {-9.44999886f, -3.14999962f, -14.6999989f}, {9.44999886f, 3.14999962f, 14.6999989f}},
        {27, 9, 42, 1632, 4, 0, {-9.44999886f, -3.14999962f, -14.6999989f}, {9.44999886f, 3.14999962f, 14.6999989f}},
        {27, 9, 42, 1632, 4, 0, {-9.44999886f, -3.14999962f, -14.6999989f}, {9.44999886f, 3.14999962f, 14.6999989f}},
        {27, 9, 42, 1632, 4, 0, {-9.44999886f, -3.14999962f, -14.6999989f}, {9.44999886f, 3.14999962f, 14.6999989f}},
        {27, 9, 42, 1632, 4, 0, {-9.44999886f, -3.14999962f, -14.6999989f}, {9.44999886f, 3.14999962f, 14.6999989f}},
        {27, 9, 42, 1632, 4, 0, {-9.44999886f, -3.14999962f, -14.6999989f}, {9.44999886f, 3.14999962f, 14.6999989f}},
        {52, 9, 73, 3642, 4, 0, {-18.1999989f, -3.14999962f, -25.5499973f}, {18.1999989f, 3.14999962f, 25.5499973f}},
        {52, 9, 73, 3642, 4, 0, {-18.1999989f, -3.14999962f, -25.5499973f}, {18.1999989f, 3.14999962f, 25.5499973f}},
        {52, 9, 73, 3642, 4, 0, {-18.1999989f, -3.14999962f, -25.5499973f}, {18.1999989f, 3.14999962f, 25.5499973f}},
        {52, 9, 73, 3642, 4, 0, {-18.1999989f, -3.14999962f, -25.5499973f}, {18.1999989f, 3.14999962f, 25.5499973f}},
        {52, 9, 73, 3642, 4, 0, {-18.1999989f, -3.14999962f, -25.5499973f}, {18.1999989f, 3.14999962f, 25.5499973f}},
        {52, 9, 73, 3642, 4, 0, {-18.1999989f, -3.14999962f, -25.5499973f}, {18.1999989f, 3.14999962f, 25.5499973f}},
    }},
    {"rainbow_dash", true, 6, 16, {
        {10, 9, 10, 63, 2, 0, {-3.0f, -4.5f, -4.0f}, {7.0f, 4.5f, 6.0f}},
        {5, 5, 6, 28, 2, 0, {-2.5f, -2.5f, 0.0f}, {2.5f, 2.5f, 6.0f}},
        {10, 5, 5, 90, 2, 0, {-5.0f, -2.5f, 0.0f}, {5.0f, 2.5f, 5.0f}},
        {10, 5, 5, 32, 2, 0, {-8.0f, -2.5f, -2.5f}, {2.0f, 2.5f, 2.5f}},
        {10, 5, 5, 22, 2, 0, {-5.0f, -2.5f, -2.5f}, {5.0f, 2.5f, 2.5f}},
        {10, 5, 5, 32, 2, 0, {-8.0f, -2.5f, -2.5f}, {2.0f, 2.5f, 2.5f}},
        {10, 5, 5, 22, 2, 0, {-5.0f, -2.5f, -2.5f}, {5.0f, 2.5f, 2.5f}},
        {5, 5, 10, 34, 2, 0, {-2.5f, -2.5f, -8.0f}, {2.5f, 2.5f, 2.0f}},
        {2, 2, 5, 16, 2, 0, {-1.0f, -1.0f, -3.5f}, {1.0f, 1.0f, 1.5f}},
        {2, 2, 5, 16, 2, 0, {-1.0f, -1.0f, -3.5f}, {1.0f, 1.0f, 1.5f}},
        {2, 2, 5, 16, 2, 0, {-1.0f, -1.0f, -3.5f}, {1.0f, 1.0f, 1.5f}},
        {2, 2, 5, 16, 2, 0, {-1.0f, -1.0f, -3.5f}, {1.0f, 1.0f, 1.5f}},
        {2, 2, 5, 16, 2, 0, {-1.0f, -1.0f, -4.0f}, {1.0f, 1.0f, 1.0f}},
        {2, 2, 5, 16, 2, 0, {-1.0f, -1.0f, -4.0f}, {1.0f, 1.0f, 1.0f}},
        {2, 2, 6, 16, 2, 0, {-1.0f, -1.0f, -4.5f}, {1.0f, 1.0f, 1.5f}},
        {2, 2, 6, 16, 2, 0, {-1.0f, -1.0f, -4.5f}, {1.0f, 1.0f, 1.5f}},
    }},
    {"rgb", false, 0, 0, {
        {32, 32, 32, 99, 2, 0, {0.0f, 0.0f, 0.0f}, {32.0f, 32.0f, 32.0f}},
    }},
    {"simple", true, 0, 0, {
        {3, 3, 3, 9, 2, 0, {-1.5f, -1.5f, 0.0f}, {1.5f, 1.5f, 3.0f}},
    }},
    {"subapc", true, 5, 5, {
        {71, 27, 29, 10419, 4, 0, {-35.5f, -13.5f, 0.0f}, {35.5f, 13.5f, 29.0f}},
        {71, 27, 29, 10419, 4, 0, {-35.5f, -13.5f, 0.0f}, {35.5f, 13.5f, 29.0f}},
        {71, 27, 29, 10419, 4, 0, {-35.5f, -13.5f, 0.0f}, {35.5f, 13.5f, 29.0f}},
        {71, 27, 29, 10419, 4, 0, {-35.5f, -13.5f, 0.0f}, {35.5f, 13.5f, 29.0f}},
        {71, 27, 29, 10419, 4, 0, {-35.5f, -13.5f, 0.0f}, {35.5f, 13.5f, 29.0f}},
    }},
    {"truckc", false, 1, 1, {
        {56, 19, 25, 4386, 4, 15, {-23.1715984f, -9.45368385f, -0.103958122f}, {32.3682022f, 9.47122383f, 24.2549934f}},
    }},
    {"ttnkbarl", false, 1, 1, {
        {1, 1, 1, 1, 4, 0, {-0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 1.0f}},
    }},
    {"yaggun", false, 2, 3, {
        {32, 5, 5, 480, 4, 0, {-15.855114f, -2.32782269f, -1.94834518f}, {15.9342804f, 2.38223362f, 2.65904045f}},
        {32, 5, 5, 480, 4, 0, {-15.855114f, -2.37212706f, -1.94834161f}, {15.9342804f, 2.33792925f, 2.65904355f}},
        {31, 27, 18, 4371, 4, 0, {-9.20546341f, -13.3104019f, 22.5949593f}, {21.2479095f, 13.4662724f, 39.6975594f}},
    }},
};
// clang-format on

const fs::path kModelsDir = VOXELFAIR_MODELS_DIR;

#define SKIP_WITHOUT_MODELS()                                                                                          \
    if (!fs::is_directory(kModelsDir / "vxl"))                                                                         \
    GTEST_SKIP() << "shared models folder " << (kModelsDir / "vxl").string() << " is absent"

std::vector<uint8_t> load(const fs::path &path) { return readFileBytes(path.string()); }

VxlModel loadVxl(const std::string &name) {
    const std::vector<uint8_t> bytes = load(kModelsDir / "vxl" / (name + ".vxl"));
    return readVxl(bytes.data(), bytes.size());
}

size_t totalVoxels(const VxlModel &m) {
    return std::accumulate(m.sections.begin(), m.sections.end(), size_t(0),
                           [](size_t n, const VxlSection &s) { return n + s.volume.voxelCount(); });
}

class SharedVxlModel : public ::testing::TestWithParam<ModelFacts> {};

}  // namespace

TEST_P(SharedVxlModel, LoadsWithTheMeasuredFacts) {
    SKIP_WITHOUT_MODELS();
    const ModelFacts &facts = GetParam();
    const VxlModel model = loadVxl(facts.name);
    EXPECT_EQ(model.embeddedPalette.allZero(), facts.embeddedPaletteAllZero);
    EXPECT_EQ(model.remapFirst, 16);
    EXPECT_EQ(model.remapLast, 31);
    ASSERT_EQ(model.sections.size(), facts.sections.size());
    for (size_t s = 0; s < facts.sections.size(); ++s) {
        SCOPED_TRACE("section " + std::to_string(s) + " \"" + model.sections[s].name + "\"");
        const VxlSection &section = model.sections[s];
        const SectionFacts &f = facts.sections[s];
        EXPECT_EQ(section.volume.sizeX, f.sizeX);
        EXPECT_EQ(section.volume.sizeY, f.sizeY);
        EXPECT_EQ(section.volume.sizeZ, f.sizeZ);
        EXPECT_EQ(section.volume.voxelCount(), f.voxels);
        EXPECT_EQ(section.normalType, f.normalType);
        EXPECT_EQ(section.clampedNormals, f.clampedNormals);
        EXPECT_EQ(section.minBounds, f.minBounds);
        EXPECT_EQ(section.maxBounds, f.maxBounds);
        const int maxNormal = section.normalType == 2 ? 35 : 243;
        for (const Voxel &v : section.volume.voxels)
            ASSERT_LE(v.normal, maxNormal);
    }

    const fs::path hvaPath = kModelsDir / "vxl" / (std::string(facts.name) + ".hva");
    ASSERT_EQ(fs::exists(hvaPath), facts.hvaFrames > 0);
    if (facts.hvaFrames > 0) {
        const std::vector<uint8_t> bytes = load(hvaPath);
        const HvaAnimation hva = readHva(bytes.data(), bytes.size());
        EXPECT_EQ(hva.frameCount, facts.hvaFrames);
        EXPECT_EQ(hva.sectionCount(), facts.hvaSections);
        EXPECT_EQ(hva.sectionCount(), int(model.sections.size()));  // sections match by index
        // Every frame places every section somewhere finite.
        for (int frame = 0; frame < hva.frameCount; ++frame)
            for (int s = 0; s < hva.sectionCount(); ++s) {
                const glm::mat4 m = sectionToModel(model.sections[size_t(s)], &hva.matrix(frame, s));
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 4; ++r)
                        ASSERT_TRUE(std::isfinite(m[c][r]));
            }
    }
}

TEST_P(SharedVxlModel, RoundTripsThroughTheWriter) {
    SKIP_WITHOUT_MODELS();
    VxlModel model = loadVxl(GetParam().name);
    const std::vector<uint8_t> bytes = writeVxl(model);
    const VxlModel back = readVxl(bytes.data(), bytes.size());
    // Clamped normals are written clamped, so nothing is clamped on the way back.
    for (VxlSection &s : model.sections)
        s.clampedNormals = 0;
    EXPECT_EQ(fixtures::firstDifference(model, back), "");
}

INSTANTIATE_TEST_SUITE_P(Models, SharedVxlModel, ::testing::ValuesIn(kModels),
                         [](const ::testing::TestParamInfo<ModelFacts> &info) {
                             std::string name = info.param.name;
                             for (char &c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return name;
                         });

TEST(SharedVxlModels, TheTableCoversEveryFile) {
    SKIP_WITHOUT_MODELS();
    std::set<std::string> inTable;
    for (const ModelFacts &m : kModels)
        inTable.insert(m.name);
    for (const fs::directory_entry &e : fs::directory_iterator(kModelsDir / "vxl"))
        if (e.path().extension() == ".vxl") {
            EXPECT_TRUE(inTable.count(e.path().stem().string())) << e.path();
        }
}

TEST(SharedVxlModels, KnownFacts) {
    SKIP_WITHOUT_MODELS();
    EXPECT_GT(loadVxl("truckc").sections[0].clampedNormals, 0u);  // normal index 244 in the file
    EXPECT_TRUE(loadVxl("art2tur").sections[0].volume.empty());
    const VxlModel barrel = loadVxl("ttnkbarl");
    EXPECT_EQ(barrel.sections[0].volume.sizeX * barrel.sections[0].volume.sizeY * barrel.sections[0].volume.sizeZ, 1);
    const VxlModel apc = loadVxl("subapc");
    EXPECT_EQ(apc.sections.size(), 5u);
    EXPECT_NEAR(double(totalVoxels(apc)), 52000.0, 500.0);
    const VxlModel cc = loadVxl("cc");
    EXPECT_EQ(cc.sections.size(), 1u);
    EXPECT_NEAR(double(totalVoxels(cc)), 33000.0, 100.0);
    for (const VxlSection &s : loadVxl("legs").sections) {
        const glm::vec3 sf = s.voxelScale();
        EXPECT_NEAR(sf.x, 0.7f, 1e-5f);
        EXPECT_NEAR(sf.y, 0.7f, 1e-5f);
        EXPECT_NEAR(sf.z, 0.7f, 1e-5f);
    }
    EXPECT_EQ(loadVxl("hmec").sections.size(), 13u);
    const std::vector<uint8_t> hva = load(kModelsDir / "vxl" / "hmec.hva");
    EXPECT_EQ(readHva(hva.data(), hva.size()).frameCount, 17);
}

// Palettes: "" is no external palette (the embedded one, or the default when that is all zeros).
class SharedPalette : public ::testing::TestWithParam<std::string> {};

TEST_P(SharedPalette, HouseColourVoxelsOfEveryModelAreRed) {
    SKIP_WITHOUT_MODELS();
    Palette external = defaultPalette();
    if (!GetParam().empty()) {
        const fs::path path = kModelsDir / "pal" / GetParam();
        const std::vector<uint8_t> bytes = load(path);
        EXPECT_EQ(bytes.size(), 768u);
        external = readPal(bytes.data(), bytes.size());
    }
    // Indices 16..31: a red ramp, brightest first (6-bit 63 widens to 255).
    EXPECT_EQ(external.colours[16], (Rgb{GetParam().empty() ? uint8_t(252) : uint8_t(255), 0, 0}));
    for (int i = 16; i <= 31; ++i) {
        EXPECT_EQ(external.colours[size_t(i)].g, 0) << i;
        EXPECT_EQ(external.colours[size_t(i)].b, 0) << i;
        if (i > 16) {
            EXPECT_LT(external.colours[size_t(i)].r, external.colours[size_t(i - 1)].r) << i;
        }
    }
    size_t houseVoxels = 0;
    for (const ModelFacts &facts : kModels) {
        const VxlModel model = loadVxl(facts.name);
        // Without a chosen palette a non-zero embedded one is used: its house entries are whatever
        // the author's editor held, so only the external and default palettes are checked.
        if (GetParam().empty() && !model.embeddedPalette.allZero())
            continue;
        for (const VxlSection &s : model.sections)
            for (const Voxel &v : s.volume.voxels)
                if (v.colour >= model.remapFirst && v.colour <= model.remapLast) {
                    ++houseVoxels;
                    const Rgb c = external.colours[v.colour];
                    ASSERT_TRUE(c.r > 0 && c.g == 0 && c.b == 0) << facts.name;
                }
    }
    EXPECT_GT(houseVoxels, 0u);
}

INSTANTIATE_TEST_SUITE_P(Palettes, SharedPalette,
                         ::testing::Values("", "ts_unittem.pal", "ra2_unittem.pal", "ra2_unitsno.pal"),
                         [](const ::testing::TestParamInfo<std::string> &info) {
                             std::string name =
                                 info.param.empty() ? "none" : info.param.substr(0, info.param.size() - 4);
                             return name;
                         });
