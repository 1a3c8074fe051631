// The .vox reader on files written from code: chunks, models, palettes, versions.
#include "fixtures/vox_writer.h"
#include "formats/vox.h"

#include <gtest/gtest.h>

using namespace voxelfair;
using namespace voxelfair::fixtures;

namespace {

VoxFile read(const Bytes &bytes) { return readVox(bytes.data(), bytes.size()); }

}  // namespace

TEST(VoxReader, ReadsOneModel) {
    const VoxFile file = read(VoxWriter().model(2, 3, 4, {{1, 2, 3, 7}}).bytes());
    EXPECT_EQ(file.version, 150);
    ASSERT_EQ(file.models.size(), 1u);
    const VoxelVolume &m = file.models[0];
    EXPECT_EQ(m.sizeX, 2);
    EXPECT_EQ(m.sizeY, 3);
    EXPECT_EQ(m.sizeZ, 4);
    EXPECT_EQ(m.voxelCount(), 1u);
    ASSERT_NE(m.find(1, 2, 3), nullptr);
    EXPECT_EQ(m.find(1, 2, 3)->colour, 7);
    EXPECT_EQ(m.find(1, 2, 3)->normal, 0);
    EXPECT_TRUE(file.nodes.empty());
    EXPECT_EQ(file.root, -1);
    EXPECT_EQ(file.frameCount, 1);
}

TEST(VoxReader, ModelIdsFollowFileOrder) {
    const VoxFile file =
        read(VoxWriter().model(1, 1, 1, {{0, 0, 0, 1}}).model(5, 1, 1, {}).model(2, 2, 2, {{1, 1, 1, 3}}).bytes());
    ASSERT_EQ(file.models.size(), 3u);
    EXPECT_EQ(file.models[0].sizeX, 1);
    EXPECT_EQ(file.models[1].sizeX, 5);
    EXPECT_TRUE(file.models[1].empty());  // an XYZI of no voxels is an empty model, still model 1
    EXPECT_EQ(file.models[2].find(1, 1, 1)->colour, 3);
}

TEST(VoxReader, SortsVoxelsAndLetsTheLastDuplicateWin) {
    // Any order in the file; (1,0,2) twice (the later colour wins); colour 0 means empty.
    const VoxFile file =
        read(VoxWriter()
                 .model(3, 2, 4, {{2, 1, 3, 1}, {1, 0, 2, 5}, {0, 0, 0, 2}, {1, 0, 2, 6}, {1, 0, 1, 4}, {2, 1, 0, 0}})
                 .bytes());
    const VoxelVolume &m = file.models[0];
    EXPECT_EQ(m.voxelCount(), 4u);
    EXPECT_EQ(m.find(2, 1, 3)->colour, 1);
    EXPECT_EQ(m.find(1, 0, 2)->colour, 6);
    EXPECT_EQ(m.find(0, 0, 0)->colour, 2);
    EXPECT_EQ(m.find(1, 0, 1)->colour, 4);
    EXPECT_EQ(m.find(2, 1, 0), nullptr);
    EXPECT_EQ(m.runs.size(), 3u);  // (1,0,1..2) is one run
}

TEST(VoxReader, LaterZeroColourEmptiesAVoxel) {
    const VoxFile file = read(VoxWriter().model(2, 2, 2, {{1, 1, 1, 9}, {1, 1, 1, 0}}).bytes());
    EXPECT_TRUE(file.models[0].empty());
}

TEST(VoxReader, PaletteEntryCMinusOneColoursIndexC) {
    // File entry i = (i, 255 - i, 7, 100 + i % 100): colour index c gets entry c - 1.
    const VoxFile file =
        read(VoxWriter()
                 .model(1, 1, 1, {{0, 0, 0, 1}})
                 .palette([](int i) {
                     return uint32_t(i) | uint32_t(255 - i) << 8 | 7u << 16 | uint32_t(100 + i % 100) << 24;
                 })
                 .bytes());
    EXPECT_FALSE(file.defaultPalette);
    EXPECT_EQ(file.palette.colours[1], (Rgb{0, 255, 7}));
    EXPECT_EQ(file.palette.colours[2], (Rgb{1, 254, 7}));
    EXPECT_EQ(file.palette.colours[255], (Rgb{254, 1, 7}));
    EXPECT_EQ(file.alpha[1], 100);
    EXPECT_EQ(file.alpha[255], 100 + 254 % 100);
    EXPECT_EQ(file.palette.colours[0], (Rgb{0, 0, 0}));
    EXPECT_EQ(file.alpha[0], 0);
}

TEST(VoxReader, MissingPaletteUsesTheSpecDefault) {
    const VoxFile file = read(VoxWriter().model(1, 1, 1, {{0, 0, 0, 1}}).bytes());
    EXPECT_TRUE(file.defaultPalette);
    // Values from vox-spec-base.txt §8 (0xAABBGGRR): entry c for colour index c.
    EXPECT_EQ(file.palette.colours[1], (Rgb{0xff, 0xff, 0xff}));    // 0xffffffff
    EXPECT_EQ(file.palette.colours[2], (Rgb{0xff, 0xff, 0xcc}));    // 0xffccffff
    EXPECT_EQ(file.palette.colours[7], (Rgb{0xff, 0xcc, 0xff}));    // 0xffffccff
    EXPECT_EQ(file.palette.colours[37], (Rgb{0xcc, 0xff, 0xff}));   // 0xffffffcc
    EXPECT_EQ(file.palette.colours[215], (Rgb{0x00, 0x00, 0x33}));  // 0xff330000
    EXPECT_EQ(file.palette.colours[216], (Rgb{0xee, 0x00, 0x00}));  // 0xff0000ee
    EXPECT_EQ(file.palette.colours[255], (Rgb{0x11, 0x11, 0x11}));  // 0xff111111
    EXPECT_EQ(file.alpha[1], 0xff);
    EXPECT_EQ(voxDefaultPalette().colours[2], file.palette.colours[2]);
}

TEST(VoxReader, SkipsUnknownChunksWithTheirChildren) {
    const Bytes child = voxChunk("ZZZZ", {1, 2, 3});
    const VoxFile file = read(VoxWriter()
                                  .chunk("ABCD", {9, 9, 9, 9, 9}, child)
                                  .model(1, 1, 1, {{0, 0, 0, 4}})
                                  .chunk("MATL", VoxContent().i32(1).dict({{"_type", "_metal"}}).bytes())
                                  .chunk("rOBJ", VoxContent().dict({{"_type", "_setting"}}).bytes())
                                  .chunk("IMAP", Bytes(256, 0))
                                  .chunk("NOTE", VoxContent().i32(1).str("red").bytes())
                                  .chunk("\x01\x02\x03\x04", {}, child)
                                  .model(1, 1, 1, {{0, 0, 0, 5}})
                                  .bytes());
    ASSERT_EQ(file.models.size(), 2u);
    EXPECT_EQ(file.models[1].find(0, 0, 0)->colour, 5);
}

TEST(VoxReader, AcceptsVersion200) {
    const VoxFile file = read(VoxWriter().model(1, 1, 1, {{0, 0, 0, 1}}).bytes(200));
    EXPECT_EQ(file.version, 200);
    EXPECT_EQ(file.models.size(), 1u);
}

TEST(VoxReader, AcceptsPackAndCountsItsModelsAsFrames) {
    const VoxFile file =
        read(VoxWriter().pack(3).model(1, 1, 1, {{0, 0, 0, 1}}).model(1, 1, 1, {}).model(1, 1, 1, {}).bytes());
    EXPECT_TRUE(file.packed);
    EXPECT_EQ(file.models.size(), 3u);
    EXPECT_EQ(file.frameCount, 3);
}

TEST(VoxReader, KeepsTheSceneGraph) {
    const VoxFile file = read(
        VoxWriter()
            .model(1, 1, 1, {{0, 0, 0, 1}})
            .transform(0, 1, {{}})
            .group(1, {2})
            .transform(2, 3, {{{"_t", "1 2 3"}, {"_f", "4"}}, {{"_r", "17"}}}, {{"_name", "arm"}, {"_hidden", "0"}}, 5)
            .shape(3, {{0, {{"_f", "2"}}}})
            .layer(5, {{"_name", "layer five"}, {"_hidden", "1"}})
            .bytes());
    ASSERT_EQ(file.nodes.size(), 4u);
    ASSERT_EQ(file.root, 0);
    const VoxNode &arm = file.nodes[2];
    EXPECT_EQ(arm.kind, VoxNodeKind::Transform);
    EXPECT_EQ(arm.id, 2);
    EXPECT_EQ(arm.name, "arm");
    EXPECT_FALSE(arm.hidden);
    EXPECT_EQ(arm.layer, 5);
    ASSERT_EQ(arm.children, std::vector<int>{3});
    ASSERT_EQ(arm.transformKeys.size(), 2u);  // sorted by frame
    EXPECT_EQ(arm.transformKeys[0].frame, 0);
    EXPECT_EQ(arm.transformKeys[1].frame, 4);
    EXPECT_EQ(arm.transformKeys[1].transform[3], glm::vec4(1, 2, 3, 1));
    // _r 17: row 0 -> column 1 negated, row 1 -> column 0, row 2 -> column 2 (glm is [column][row]).
    EXPECT_EQ(arm.transformKeys[0].transform[1][0], -1.0f);
    EXPECT_EQ(arm.transformKeys[0].transform[0][1], 1.0f);
    EXPECT_EQ(arm.transformKeys[0].transform[2][2], 1.0f);
    EXPECT_EQ(file.nodes[1].kind, VoxNodeKind::Group);
    EXPECT_EQ(file.nodes[3].kind, VoxNodeKind::Shape);
    EXPECT_EQ(file.nodes[3].shapeKeys[0].frame, 2);
    ASSERT_EQ(file.layers.size(), 1u);
    EXPECT_EQ(file.layers[0].id, 5);
    EXPECT_EQ(file.layers[0].name, "layer five");
    EXPECT_TRUE(file.layers[0].hidden);
    EXPECT_EQ(file.frameCount, 5);  // the largest _f is 4
}

TEST(VoxReader, NodesMayComeBeforeTheModelsAndInAnyOrder) {
    const VoxFile file = read(VoxWriter()
                                  .shape(3, 0)
                                  .transform(2, 3, {{}})
                                  .group(1, {2})
                                  .transform(0, 1, {{}})
                                  .model(1, 1, 1, {{0, 0, 0, 1}})
                                  .bytes());
    EXPECT_EQ(file.root, 3);
    EXPECT_EQ(file.nodes[size_t(file.root)].id, 0);
}
