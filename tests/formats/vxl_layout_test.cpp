// The reader follows the tailer offsets wherever they point: it never assumes the editor's
// contiguous layout or that columns follow each other.
#include "formats/vxl.h"
#include "fixtures/raw_vxl.h"

#include <gtest/gtest.h>

using namespace voxelfair;
using namespace voxelfair::rawvxl;

TEST(VxlLayout, FollowsTailerOffsetsInAnyOrder) {
    // Body: padding, B's data, A's data (column 1 before column 0, with stray bytes that spanEnd
    // covers), A's spanEnd[] before its spanStart[], then B's arrays.
    RawVxl raw;
    RawSection a, b;
    a.name = "A";
    a.size[0] = 2, a.size[1] = 1, a.size[2] = 4;
    b.name = "B";
    b.size[2] = 2;
    b.normalType = 2;
    std::vector<uint8_t> &body = raw.body;
    body = {0xEE, 0xEE, 0xEE, 0xEE, 0xEE};

    const std::vector<uint8_t> bColumn = segment(1, {{7, 8}});
    b.spanDataOfs = int32_t(body.size());
    body.insert(body.end(), bColumn.begin(), bColumn.end());

    const std::vector<uint8_t> aColumn1 = concat({segment(2, {{3, 4}, {5, 6}}), {0xAB, 0xCD}});
    const std::vector<uint8_t> aColumn0 = concat({segment(0, {{1, 2}}), segment(3, {})});
    a.spanDataOfs = int32_t(body.size());
    body.insert(body.end(), aColumn1.begin(), aColumn1.end());
    body.insert(body.end(), aColumn0.begin(), aColumn0.end());
    a.spanEndOfs = int32_t(body.size());
    put32(body, uint32_t(aColumn1.size() + aColumn0.size() - 1));
    put32(body, uint32_t(aColumn1.size() - 1));
    a.spanStartOfs = int32_t(body.size());
    put32(body, uint32_t(aColumn1.size()));
    put32(body, 0);
    b.spanStartOfs = int32_t(body.size());
    put32(body, 0);
    b.spanEndOfs = int32_t(body.size());
    put32(body, uint32_t(bColumn.size() - 1));
    raw.sections = {a, b};

    const VxlModel model = read(raw.bytes());
    ASSERT_EQ(model.sections.size(), 2u);
    const VoxelVolume &va = model.sections[0].volume;
    EXPECT_EQ(model.sections[0].name, "A");
    EXPECT_EQ(va.voxelCount(), 3u);
    ASSERT_TRUE(va.solid(0, 0, 0) && va.solid(1, 0, 2) && va.solid(1, 0, 3));
    EXPECT_EQ(va.find(0, 0, 0)->colour, 1);
    EXPECT_EQ(va.find(0, 0, 0)->normal, 2);
    EXPECT_EQ(va.find(1, 0, 2)->colour, 3);
    EXPECT_EQ(va.find(1, 0, 3)->normal, 6);
    const VoxelVolume &vb = model.sections[1].volume;
    EXPECT_EQ(model.sections[1].normalType, 2);
    EXPECT_EQ(vb.voxelCount(), 1u);
    ASSERT_TRUE(vb.solid(0, 0, 1));
    EXPECT_EQ(vb.find(0, 0, 1)->colour, 7);
}

TEST(VxlLayout, ColumnsMayShareTheirData) {
    RawVxl raw;
    RawSection s;
    s.size[0] = 2;
    s.size[2] = 2;
    raw.addBody(s, {{segment(0, {{9, 1}, {8, 2}})}, {segment(0, {{0, 0}, {0, 0}})}});
    patch32(raw.body, size_t(s.spanStartOfs) + 4, 0);  // column 1 reuses column 0's bytes
    patch32(raw.body, size_t(s.spanEndOfs) + 4, 6);
    raw.sections = {s};
    const VoxelVolume v = read(raw.bytes()).sections[0].volume;
    EXPECT_EQ(v.voxelCount(), 4u);
    EXPECT_EQ(v.find(1, 0, 0)->colour, 9);
    EXPECT_EQ(v.find(1, 0, 1)->colour, 8);
}

TEST(VxlLayout, AcceptsAColumnFilledWithoutADummySegment) {
    RawVxl raw;
    RawSection s;
    s.size[2] = 3;
    raw.addBody(s, {{segment(1, {{4, 5}, {6, 7}})}});  // ends exactly at zSize
    raw.sections = {s};
    const VoxelVolume v = read(raw.bytes()).sections[0].volume;
    EXPECT_EQ(v.voxelCount(), 2u);
    EXPECT_FALSE(v.solid(0, 0, 0));
    EXPECT_TRUE(v.solid(0, 0, 2));
}

TEST(VxlLayout, IgnoresBytesAfterTheTailers) {
    // The reference readers seek to the tailers through bodySize and never look at the end of file.
    RawVxl raw;
    RawSection s;
    raw.addBody(s, {{segment(0, {{1, 1}})}});
    raw.sections = {s};
    std::vector<uint8_t> bytes = raw.bytes();
    bytes.resize(bytes.size() + 7, 0x5A);
    EXPECT_EQ(read(bytes).sections[0].volume.voxelCount(), 1u);
}

TEST(VxlLayout, ReadsNamesOfSixteenCharactersWithoutTerminator) {
    RawVxl raw;
    RawSection s;
    s.name = "ABCDEFGHIJKLMNOP";
    raw.addBody(s, {{}});
    raw.sections = {s};
    EXPECT_EQ(read(raw.bytes()).sections[0].name, "ABCDEFGHIJKLMNOP");
}
