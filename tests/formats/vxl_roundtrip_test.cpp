// writeVxl -> readVxl gives back the same model, and the writer uses the editor's layout.
#include "fixtures/vxl_fixtures.h"
#include "formats/format_error.h"
#include "formats/vxl.h"
#include "fixtures/raw_vxl.h"

#include <gtest/gtest.h>

using namespace voxelfair;
using namespace voxelfair::fixtures;

namespace {

VxlModel roundTrip(const VxlModel &model) {
    const std::vector<uint8_t> bytes = writeVxl(model);
    return readVxl(bytes.data(), bytes.size());
}

void expectRoundTrip(const VxlModel &model) {
    const VxlModel back = roundTrip(model);
    EXPECT_EQ(firstDifference(model, back), "");
}

}  // namespace

TEST(VxlRoundTrip, SingleVoxel) {
    VxlModel model = makeModel({makeSection("one", volumeFromVoxels(3, 4, 5, {{1, 2, 3, {200, 17}}}))});
    const VxlModel back = roundTrip(model);
    EXPECT_EQ(firstDifference(model, back), "");
    ASSERT_EQ(back.sections[0].volume.voxelCount(), 1u);
    const Voxel *v = back.sections[0].volume.find(1, 2, 3);
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(v->colour, 200);
    EXPECT_EQ(v->normal, 17);
}

TEST(VxlRoundTrip, OneByOneByOne) {
    expectRoundTrip(makeModel({makeSection("dot", volumeFromVoxels(1, 1, 1, {{0, 0, 0, {5, 6}}}))}));
}

TEST(VxlRoundTrip, FullBox) {
    VxlModel model = makeModel({makeSection("box", volumeWhere(7, 5, 9, [](int, int, int) { return true; }))});
    EXPECT_EQ(model.sections[0].volume.voxelCount(), 7u * 5u * 9u);
    expectRoundTrip(model);
}

TEST(VxlRoundTrip, ColumnsWithGaps) {
    // Runs starting at the bottom, in the middle and ending at the top, and empty columns.
    auto solid = [](int x, int y, int z) { return (x + y) % 3 != 0 && ((z + x) % 4 != 1) && z != 5; };
    VxlModel model = makeModel({makeSection("gaps", volumeWhere(6, 4, 11, solid))});
    const VxlModel back = roundTrip(model);
    EXPECT_EQ(firstDifference(model, back), "");
    EXPECT_EQ(solidVoxels(back.sections[0].volume), solidVoxels(model.sections[0].volume));
}

TEST(VxlRoundTrip, ColumnsOf255Voxels) {
    // The tallest column the format can hold: full, gaps at both ends, single voxels at the extremes.
    VxlModel model = makeModel({makeSection("tall", volumeWhere(4, 1, 255, [](int x, int, int z) {
                                                switch (x) {
                                                case 0: return true;
                                                case 1: return z > 0 && z < 254;
                                                case 2: return z == 0 || z == 254;
                                                default: return z % 2 == 1;
                                                }
                                            }))});
    expectRoundTrip(model);
}

TEST(VxlRoundTrip, EmptySection) {
    VxlModel model = makeModel({makeSection("empty", volumeFromVoxels(1, 9, 1, {}))});
    const VxlModel back = roundTrip(model);
    EXPECT_EQ(firstDifference(model, back), "");
    EXPECT_TRUE(back.sections[0].volume.empty());
    EXPECT_EQ(back.sections[0].volume.sizeY, 9);
}

TEST(VxlRoundTrip, MultipleSectionsWithBothNormalTypes) {
    auto ts = [](int x, int y, int z) { return patternVoxel(x, y, z, kTiberianSunNormalCount); };
    VxlSection body = makeSection("BODY",
                                  volumeWhere(
                                      8, 6, 5, [](int x, int y, int z) { return x + y + z < 10; }, ts),
                                  VxlNormalType::TiberianSun);
    VxlSection turret = makeSection("TURRET", volumeWhere(5, 5, 3, [](int x, int y, int) { return x != y; }));
    VxlSection empty = makeSection("NOTHING", volumeFromVoxels(2, 2, 2, {}));
    VxlSection barrel = makeSection("A fifteen chars", volumeFromVoxels(1, 1, 1, {{0, 0, 0, {1, 243}}}));
    turret.scale = 0.0555556f;
    turret.transform = {0, -1, 0, 1.5f, 1, 0, 0, -2.25f, 0, 0, 1, 7.0f};
    turret.minBounds = {-1.75f, -2.5f, 3.0f};
    turret.maxBounds = {2.0f, 1.25f, 4.5f};
    VxlModel model = makeModel({body, turret, empty, barrel});
    model.remapFirst = 10;
    model.remapLast = 40;
    expectRoundTrip(model);
}

TEST(VxlRoundTrip, WriterUsesTheEditorsContiguousLayout) {
    // Column (0,0): voxels at z = 1, 2 then empty to the top; column (1,0): empty.
    VxlModel model = makeModel({makeSection("s", volumeFromVoxels(2, 1, 5, {{0, 0, 1, {9, 8}}, {0, 0, 2, {7, 6}}}))});
    const std::vector<uint8_t> bytes = writeVxl(model);
    const size_t body = 802 + 28;
    const std::vector<uint8_t> expectedBody = {
        0,    0,    0,    0,              // spanStart[0]
        0xFF, 0xFF, 0xFF, 0xFF,           // spanStart[1] = -1
        9,    0,    0,    0,              // spanEnd[0]: last byte of the column
        0xFF, 0xFF, 0xFF, 0xFF,           // spanEnd[1] = -1
        1,    2,    9,    8,    7, 6, 2,  // skip 1, two voxels, count again
        2,    0,    0,                    // the dummy segment up to zSize
    };
    ASSERT_EQ(bytes.size(), body + expectedBody.size() + 92);
    EXPECT_EQ(std::vector<uint8_t>(bytes.begin() + body, bytes.begin() + body + expectedBody.size()), expectedBody);
    EXPECT_EQ(std::string(reinterpret_cast<const char *>(bytes.data()), 16), std::string("Voxel Animation\0", 16));
    EXPECT_EQ(bytes[28], expectedBody.size());  // bodySize
    EXPECT_EQ(bytes[32], 16);                   // remap range
    EXPECT_EQ(bytes[33], 31);
    const size_t tailer = body + expectedBody.size();
    EXPECT_EQ(bytes[tailer + 4], 8);   // spanEndOfs
    EXPECT_EQ(bytes[tailer + 8], 16);  // spanDataOfs
    EXPECT_EQ(bytes[tailer + 88], 2);
    EXPECT_EQ(bytes[tailer + 90], 5);
}

TEST(VxlRoundTrip, WriterRejectsUnwritableModels) {
    EXPECT_THROW(writeVxl(VxlModel{}), FormatError);
    EXPECT_THROW(writeVxl(makeModel({makeSection("big", volumeFromVoxels(256, 1, 1, {}))})), FormatError);
    VxlModel unbuilt;
    unbuilt.sections.resize(1);  // a default VoxelVolume has size 0
    EXPECT_THROW(writeVxl(unbuilt), FormatError);
}

TEST(VxlReader, ClampsNormalsPastTheTable) {
    VxlSection ra2 =
        makeSection("ra2", volumeFromVoxels(1, 1, 4, {{0, 0, 0, {1, 243}}, {0, 0, 1, {1, 244}}, {0, 0, 3, {1, 255}}}));
    VxlSection ts = makeSection("ts", volumeFromVoxels(1, 1, 2, {{0, 0, 0, {1, 35}}, {0, 0, 1, {1, 36}}}),
                                VxlNormalType::TiberianSun);
    VxlSection other = makeSection("type3", volumeFromVoxels(1, 1, 2, {{0, 0, 0, {1, 100}}, {0, 0, 1, {1, 250}}}));
    other.normalType = 3;  // unknown types are read as Red Alert 2
    const VxlModel back = roundTrip(makeModel({ra2, ts, other}));

    const VoxelVolume &a = back.sections[0].volume;
    EXPECT_EQ(a.find(0, 0, 0)->normal, 243);
    EXPECT_EQ(a.find(0, 0, 1)->normal, 243);
    EXPECT_EQ(a.find(0, 0, 3)->normal, 243);
    EXPECT_EQ(back.sections[0].clampedNormals, 2u);

    EXPECT_EQ(back.sections[1].volume.find(0, 0, 0)->normal, 35);
    EXPECT_EQ(back.sections[1].volume.find(0, 0, 1)->normal, 35);
    EXPECT_EQ(back.sections[1].clampedNormals, 1u);

    EXPECT_EQ(back.sections[2].normalType, 3);
    EXPECT_EQ(back.sections[2].volume.find(0, 0, 0)->normal, 100);
    EXPECT_EQ(back.sections[2].volume.find(0, 0, 1)->normal, 243);
    EXPECT_EQ(back.sections[2].clampedNormals, 1u);
}

TEST(VxlReader, ReadsZeroScaleAsOne) {
    VxlSection s = makeSection("s", volumeFromVoxels(1, 1, 1, {{0, 0, 0, {}}}));
    s.scale = 0.0f;
    EXPECT_EQ(roundTrip(makeModel({s})).sections[0].scale, 1.0f);
}

TEST(VxlReader, KeepsAnAllZeroEmbeddedPalette) {
    VxlModel model = makeModel({makeSection("s", volumeFromVoxels(1, 1, 1, {{0, 0, 0, {}}}))});
    model.embeddedPalette = Palette{};
    EXPECT_TRUE(roundTrip(model).embeddedPalette.allZero());
}
