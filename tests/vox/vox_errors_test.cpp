// Broken .vox files: each gives a FormatError saying what and where; no prefix or corrupted byte of
// a valid file crashes the reader.
#include "fixtures/vox_writer.h"
#include "vox_expect_error.h"
#include "formats/format_error.h"
#include "formats/vox.h"
#include "scene/vox_scene.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

using namespace voxelfair;
using namespace voxelfair::test;
using namespace voxelfair::fixtures;

namespace {

// A valid file with one 1x1x1 model, then `graph` (root nTRN 0 -> nGRP 1 -> ...).
Bytes withGraph(const std::function<void(VoxWriter &)> &graph) {
    VoxWriter w;
    w.model(1, 1, 1, {{0, 0, 0, 1}});
    graph(w);
    return w.bytes();
}

Bytes withFrame(const VoxDict &frame) {
    return withGraph([&](VoxWriter &w) { w.transform(0, 1, {{}}).group(1, {2}).transform(2, 3, {frame}).shape(3, 0); });
}

Bytes header(int version) { return VoxContent().raw({'V', 'O', 'X', ' '}).i32(version).bytes(); }

}  // namespace

TEST(VoxErrors, WrongMagic) {
    expectVoxError({'V', 'X', 'L', ' ', 150, 0, 0, 0}, {"not a MagicaVoxel file"});
    expectVoxError({'V', 'O', 'X'}, {"truncated", "8-byte header"});
    expectVoxError({}, {"truncated"});
}

TEST(VoxErrors, UnsupportedVersion) {
    expectVoxError(VoxWriter().model(1, 1, 1, {}).bytes(151), {"unsupported version 151"});
}

TEST(VoxErrors, FirstChunkIsNotMain) {
    Bytes b = header(150);
    const Bytes size = voxChunk("SIZE", VoxContent().i32(1).i32(1).i32(1).bytes());
    b.insert(b.end(), size.begin(), size.end());
    expectVoxError(b, {"chunk 'SIZE' at byte 8", "must be 'MAIN'"});
}

TEST(VoxErrors, MainPastTheEndOfTheFile) {
    Bytes b = VoxWriter().model(1, 1, 1, {{0, 0, 0, 1}}).bytes();
    b.resize(b.size() - 1);
    expectVoxError(b, {"chunk 'MAIN' at byte 8", "run past the end of the file"});
    expectVoxError(header(150), {"truncated", "chunk header at byte 8"});
}

TEST(VoxErrors, ChunkPastItsParent) {
    // A chunk claiming 100 content bytes inside a MAIN that holds 12 + 4.
    Bytes content = VoxContent().raw({'A', 'B', 'C', 'D'}).i32(100).i32(0).i32(0).bytes();
    Bytes b = header(150);
    const Bytes main = voxChunk("MAIN", {}, content);
    b.insert(b.end(), main.begin(), main.end());
    b.resize(b.size() + 200, 0);  // the file is long enough: only MAIN's extent is exceeded
    expectVoxError(b, {"chunk 'ABCD' at byte 20", "run past the end of chunk 'MAIN'"});
    // Negative sizes read as huge.
    expectVoxError(VoxWriter().chunk("XYZI", {}).bytes(), {"XYZI chunk without a SIZE"});
    Bytes negative = VoxWriter().model(1, 1, 1, {}).bytes();
    negative[20 + 4] = 0xff, negative[20 + 5] = 0xff, negative[20 + 6] = 0xff, negative[20 + 7] = 0xff;
    expectVoxError(negative, {"chunk 'SIZE' at byte 20", "4294967295 content"});
}

TEST(VoxErrors, VoxelCountPastTheChunk) {
    expectVoxError(
        VoxWriter().size(2, 2, 2).chunk("XYZI", VoxContent().i32(10).raw({0, 0, 0, 1, 1, 1, 1, 1}).bytes()).bytes(),
        {"chunk 'XYZI' at byte 44", "voxel count 10 needs at least 40 bytes but only 8 remain"});
    expectVoxError(VoxWriter().size(2, 2, 2).chunk("XYZI", VoxContent().i32(-1).bytes()).bytes(),
                   {"voxel count is negative"});
}

TEST(VoxErrors, VoxelOutsideTheModel) {
    expectVoxError(VoxWriter().model(2, 3, 4, {{0, 0, 0, 1}, {1, 3, 0, 1}}).bytes(),
                   {"chunk 'XYZI'", "model 0: voxel 1 at (1, 3, 0) lies outside the model's size 2 x 3 x 4"});
}

TEST(VoxErrors, BadModelSize) {
    expectVoxError(VoxWriter().model(0, 1, 1, {}).bytes(), {"chunk 'SIZE' at byte 20", "size 0 x 1 x 1", "1..2048"});
    expectVoxError(VoxWriter().model(1, kMaxVolumeSide + 1, 1, {}).bytes(), {"size 1 x 2049 x 1"});
    expectVoxError(VoxWriter().model(1, 1, -5, {}).bytes(), {"size 1 x 1 x -5"});
    expectVoxError(VoxWriter().chunk("SIZE", VoxContent().i32(1).i32(1).bytes()).bytes(), {"truncated: model size"});
}

TEST(VoxErrors, SizeWithoutVoxels) {
    expectVoxError(VoxWriter().size(1, 1, 1).bytes(),
                   {"model 0: chunk 'SIZE' at byte 20 has no XYZI (or TDCZ) chunk after it"});
    expectVoxError(VoxWriter().size(1, 1, 1).size(1, 1, 1).xyzi({}).bytes(),
                   {"has no XYZI", "chunk 'SIZE' at byte 44 follows it"});
    expectVoxError(VoxWriter().size(1, 1, 1).chunk("RGBA", Bytes(1024, 0)).bytes(),
                   {"has no XYZI (or TDCZ) chunk after it", "found 'RGBA' instead"});
}

TEST(VoxErrors, NoModel) {
    expectVoxError(VoxWriter().bytes(), {"holds no model"});
    expectVoxError(VoxWriter().chunk("RGBA", Bytes(1024, 0)).bytes(), {"holds no model"});
}

TEST(VoxErrors, TooManyColumns) {
    VoxWriter w;
    for (int i = 0; i < 5; ++i)
        w.model(kMaxVolumeSide, kMaxVolumeSide, 1, {});
    expectVoxError(w.bytes(), {"model 4 (2048 x 2048 x 1)", "over the limit of 16777216"});
}

TEST(VoxErrors, TooManyModels) {
    VoxWriter w;
    for (int i = 0; i <= kMaxVoxModels; ++i)
        w.model(1, 1, 1, {});
    expectVoxError(w.bytes(), {"more than 65536 models"});
}

TEST(VoxErrors, ShortPalette) {
    expectVoxError(VoxWriter().model(1, 1, 1, {}).chunk("RGBA", Bytes(1016, 0)).bytes(),
                   {"chunk 'RGBA'", "RGBA palette (255 used entries)"});
}

TEST(VoxErrors, ShapeShowsAMissingModel) {
    expectVoxError(
        withGraph([](VoxWriter &w) { w.transform(0, 1, {{}}).group(1, {2}).transform(2, 3, {{}}).shape(3, 3); }),
        {"node 3 (chunk 'nSHP' at byte", "shows model 3 but the file has 1 models"});
    expectVoxError(withGraph([](VoxWriter &w) { w.transform(0, 1, {{}}).shape(1, -1); }), {"shows model -1"});
}

TEST(VoxErrors, BadRotation) {
    for (const char *r : {"3", "5", "15", "128", "x", "-1", "4 ", ""})
        expectVoxError(withFrame({{"_r", r}}),
                       {"chunk 'nTRN' at byte", "node 2 frame 0: rotation _r \"" + std::string(r) + "\""});
    expectVoxError(withFrame({{"_r", "5"}}), {"is not a valid rotation (rows 0 and 1 use columns 1 and 1)"});
}

TEST(VoxErrors, BadTranslation) {
    for (const char *t : {"1 2 x", "1 2", "1 2 3 4", "", "1.5 0 0", "99999999999 0 0"})
        expectVoxError(withFrame({{"_t", t}}),
                       {"node 2 frame 0: translation _t \"" + std::string(t) + "\" is not three integers"});
}

TEST(VoxErrors, BadFrameIndex) {
    expectVoxError(withFrame({{"_f", "-1"}}), {"frame index _f \"-1\""});
    expectVoxError(withGraph([](VoxWriter &w) {
                       w.transform(0, 1, {{}}).shape(1, {{0, {{"_f", "one"}}}});
                   }),
                   {"node 1 model entry 0: frame index _f \"one\""});
}

TEST(VoxErrors, MissingChildNode) {
    expectVoxError(withGraph([](VoxWriter &w) {
                       w.transform(0, 1, {{}}).group(1, {2, 9}).transform(2, 3, {{}}).shape(3, 0);
                   }),
                   {"node 1 (chunk 'nGRP' at byte", "refers to child node 9, which the file does not define"});
}

TEST(VoxErrors, CycleInTheGraph) {
    expectVoxError(withGraph([](VoxWriter &w) { w.transform(0, 1, {{}}).group(1, {2}).transform(2, 1, {{}}); }),
                   {"the scene graph has a cycle", "node 1 (chunk 'nGRP'"});
    expectVoxError(withGraph([](VoxWriter &w) { w.transform(0, 0, {{}}); }), {"cycle"});
}

TEST(VoxErrors, DuplicateNodeIdOrNoRoot) {
    expectVoxError(withGraph([](VoxWriter &w) { w.transform(0, 1, {{}}).shape(1, 0).shape(1, 0); }),
                   {"node id 1 is used twice"});
    expectVoxError(withGraph([](VoxWriter &w) { w.transform(5, 1, {{}}).shape(1, 0); }),
                   {"no root (no node with id 0)"});
}

TEST(VoxErrors, GraphTooDeep) {
    expectVoxError(withGraph([](VoxWriter &w) {
                       for (int i = 0; i < 300; ++i)
                           w.group(i, {i + 1});
                       w.shape(300, 0);
                   }),
                   {"the scene graph is 301 levels deep, over the limit of 256"});
}

TEST(VoxErrors, GraphExpandsToTooManyInstances) {
    // Each group lists the next one twice: 2^21 paths from 22 nodes.
    expectVoxError(withGraph([](VoxWriter &w) {
                       for (int i = 0; i < 21; ++i)
                           w.group(i, {i + 1, i + 1});
                       w.shape(21, 0);
                   }),
                   {"expands to more than 1048576 shape instances"});
}

TEST(VoxErrors, NodeFieldsPastTheChunk) {
    expectVoxError(VoxWriter().model(1, 1, 1, {}).chunk("nTRN", VoxContent().i32(0).i32(1000).bytes()).bytes(),
                   {"chunk 'nTRN'", "node attribute count 1000 needs at least 8000 bytes"});
    expectVoxError(
        VoxWriter().model(1, 1, 1, {}).chunk("nGRP", VoxContent().i32(0).i32(1).i32(50).str("k").bytes()).bytes(),
        {"chunk 'nGRP'", "dictionary key 50 needs at least 50 bytes but only 5 remain"});
    expectVoxError(
        VoxWriter().model(1, 1, 1, {}).chunk("nGRP", VoxContent().i32(0).i32(0).i32(3).i32(1).bytes()).bytes(),
        {"child count 3 needs at least 12 bytes but only 4 remain"});
    expectVoxError(withGraph([](VoxWriter &w) { w.transform(0, 1, {}); }), {"node 0 has no frames"});
    expectVoxError(
        withGraph([](VoxWriter &w) { w.transform(0, 1, {{}}).shape(1, std::vector<std::pair<int, VoxDict>>{}); }),
        {"node 1 shows no model"});
}

TEST(VoxErrors, FrameOutOfRange) {
    const Bytes b = VoxWriter().model(1, 1, 1, {}).bytes();
    const VoxFile file = readVox(b.data(), b.size());
    EXPECT_THROW(voxScene(file, {1}), FormatError);
}

// A small file with every kind of chunk, for the two sweeps below.
Bytes sweepFixture() {
    VoxWriter w;
    w.pack(2).model(2, 2, 2, {{0, 0, 0, 1}, {1, 1, 1, 2}}).model(1, 2, 1, {{0, 1, 0, 3}});
    w.transform(0, 1, {{}}).group(1, {2, 4});
    w.transform(2, 3, {{{"_r", "105"}, {"_t", "1 -2 3"}, {"_f", "0"}}}, {{"_name", "a"}}, 1)
        .shape(3, {{0, {}}, {1, {{"_f", "1"}}}});
    w.transform(4, 5, {{{"_t", "0 0 1"}}}).shape(5, 1);
    w.layer(1, {{"_hidden", "0"}}).palette([](int i) { return uint32_t(i) * 0x01010101u; });
    return w.bytes();
}

TEST(VoxErrors, EveryTruncationIsAFormatError) {
    const Bytes full = sweepFixture();
    ASSERT_NO_THROW(readVox(full.data(), full.size()));
    for (size_t n = 0; n < full.size(); ++n) {
        const Bytes prefix(full.begin(), full.begin() + std::ptrdiff_t(n));
        EXPECT_THROW(readVox(prefix.data(), prefix.size()), FormatError) << "prefix of " << n << " bytes";
    }
}

TEST(VoxErrors, CorruptBytesNeverCrash) {
    // Each byte replaced by values that break sizes, counts, ids and strings: the reader either
    // accepts the file or throws FormatError, and the scene of an accepted file can be built.
    const Bytes full = sweepFixture();
    for (size_t i = 0; i < full.size(); ++i) {
        for (uint8_t value : {uint8_t(0x00), uint8_t(0x01), uint8_t(0x7f), uint8_t(0x80), uint8_t(0xff)}) {
            Bytes b = full;
            b[i] = value;
            try {
                const VoxFile file = readVox(b.data(), b.size());
                for (int f = 0; f < std::min(file.frameCount, 4); ++f)
                    voxScene(file, {f});
            } catch (const FormatError &) {
            }
        }
    }
}
