// Hostile .vox input: real files truncated at every byte and with random bits flipped, chunk sizes
// pointing past their parent, absurd sizes and counts in every chunk kind, and scene graphs that
// instance one model many times. Each input is accepted or rejected with a FormatError naming the
// problem, within the heap bound below.
#include "fixtures/vox_writer.h"
#include "formats/vox.h"
#include "hostile_input.h"
#include "scene/vox_scene.h"

#include <chrono>
#include <functional>
#include <random>
#include <string>

using namespace voxelfair;
using namespace voxelfair::fixtures;
using namespace voxelfair::test;

namespace {

void readOnly(const uint8_t *data, size_t size) { readVox(data, size); }

// What the importer does first: read, then place the models of frame 0.
void readAndPlace(const uint8_t *data, size_t size) {
    const VoxFile file = readVox(data, size);
    voxScene(file);
}

// Reading. Per byte: at most ~26 bytes (a 68-byte transform keyframe per 4-byte empty
// dictionary, and stable_sort's buffer for them). Fixed: the models' column indexes, 4 bytes per
// column, which 24-byte SIZE chunks declare: kMaxVoxColumns of them (64 MiB) at most, plus one
// entry per model.
constexpr HeapBound kVoxHeap{32, 4 * (kMaxVoxColumns + kMaxVoxModels) + (1 << 20)};

// Reading and placing: each shape instance costs a VoxInstance and a PlacedVolume (doubled for
// vector growth); a 4-byte child id can add one, doubling groups up to kMaxVoxInstances.
constexpr size_t kInstanceBytes = 2 * (sizeof(VoxInstance) + sizeof(PlacedVolume));
constexpr HeapBound kVoxPlaceHeap{kVoxHeap.perByte, kVoxHeap.fixed + kMaxVoxInstances *kInstanceBytes};

// Each chunk's header offset, id and the end of its parent, in file order.
struct ChunkAt {
    size_t offset;
    std::string id;
    size_t parentEnd;
};

void walkChunks(const Bytes &b, size_t begin, size_t end, std::vector<ChunkAt> &out) {
    for (size_t at = begin; at + 12 <= end;) {
        const size_t content = load32(b, at + 4), children = load32(b, at + 8);
        out.push_back({at, std::string(b.begin() + std::ptrdiff_t(at), b.begin() + std::ptrdiff_t(at + 4)), end});
        walkChunks(b, at + 12 + content, at + 12 + content + children, out);
        at += 12 + content + children;
    }
}

std::vector<ChunkAt> chunksOf(const Bytes &b) {
    std::vector<ChunkAt> chunks;
    walkChunks(b, 8, b.size(), chunks);
    return chunks;
}

// A small file with every chunk kind the reader interprets.
Bytes fixtureFile() {
    VoxWriter w;
    w.pack(2).model(3, 2, 4, {{0, 0, 0, 1}, {1, 1, 1, 2}, {2, 1, 3, 9}}).model(1, 2, 1, {{0, 1, 0, 3}});
    w.transform(0, 1, {{}}).group(1, {2, 4});
    w.transform(2, 3, {{{"_r", "105"}, {"_t", "1 -2 3"}, {"_f", "0"}}, {{"_f", "2"}}}, {{"_name", "a"}}, 1)
        .shape(3, {{0, {}}, {1, {{"_f", "1"}}}});
    w.transform(4, 5, {{{"_t", "0 0 1"}}}, {{"_hidden", "0"}}).shape(5, 1);
    w.layer(1, {{"_hidden", "0"}, {"_name", "layer"}}).palette([](int i) { return uint32_t(i) * 0x01010101u; });
    return w.bytes(200);
}

// Node 0 is a transform over group 1; groups 1 .. levels each list the next node twice, and node
// levels + 1 shows model 0: 2^levels instances from a few hundred bytes.
Bytes doublingGraph(int levels, const std::vector<VoxVoxel> &model) {
    VoxWriter w;
    w.model(8, 8, 8, model);
    w.transform(0, 1, {{}});
    for (int i = 1; i <= levels; ++i)
        w.group(i, {i + 1, i + 1});
    w.shape(levels + 1, 0);
    return w.bytes();
}

std::vector<VoxVoxel> cube(int side) {
    std::vector<VoxVoxel> voxels;
    for (int z = 0; z < side; ++z)
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                voxels.push_back({uint8_t(x), uint8_t(y), uint8_t(z), 1});
    return voxels;
}

}  // namespace

TEST(HostileVox, RealFileTruncatedAtEveryByte) {
    VOXELFAIR_LOAD_MODEL_OR_SKIP(robo, "vox/robo.vox");
    sweepTruncations(readOnly, robo, kVoxHeap, {"truncated", "run past the end of the file"}, "robo.vox prefixes");
}

TEST(HostileVox, RandomBitFlips) {
    SweepRecord record;
    // Every other variant flips bits in chunk headers only (ids and sizes), the rest anywhere.
    const auto sweep = [&](const Bytes &base, uint32_t seed, int variants) {
        BitFlipSweep flips{seed, variants, 8, {}};
        for (const ChunkAt &c : chunksOf(base))
            flips.focus.push_back({c.offset, c.offset + 12});
        sweepBitFlips(readAndPlace, base, flips, kVoxPlaceHeap, record);
    };
    sweep(fixtureFile(), 31, 3000);
    const Bytes robo = loadModel("vox/robo.vox"), ontop = loadModel("vox/8ontop.vox");
    if (!robo.empty())
        sweep(robo, 32, 2000);
    if (!ontop.empty())
        sweep(ontop, 33, 500);
    record.print("bit-flipped .vox files");
    EXPECT_GT(record.accepted, 0u);
    EXPECT_LT(record.accepted, record.inputs);
}

TEST(HostileVox, ChunkSizesPastTheirParent) {
    VOXELFAIR_LOAD_MODEL_OR_SKIP(robo, "vox/robo.vox");
    const std::vector<ChunkAt> chunks = chunksOf(robo);
    ASSERT_GT(chunks.size(), 10u);
    for (const ChunkAt &c : chunks) {
        const size_t content = load32(robo, c.offset + 4), children = load32(robo, c.offset + 8);
        const size_t room = c.parentEnd - (c.offset + 12);  // content + children may not exceed it
        const std::pair<size_t, uint32_t> patches[] = {
            {4, uint32_t(room - children + 1)}, {8, uint32_t(room - content + 1)}, {4, 0xFFFFFFFFu}, {8, 0x80000000u}};
        for (const auto &[field, value] : patches) {
            Bytes b = robo;
            patch32(b, c.offset + field, value);
            const Attempt a = attempt(readOnly, b);
            const std::string where = "chunk '" + c.id + "' at byte " + std::to_string(c.offset);
            EXPECT_TRUE(survived(a, kVoxHeap, b.size()));
            EXPECT_TRUE(rejectedWith(a, {where.c_str(), "run past the end of"}));
        }
    }
}

TEST(HostileVox, AbsurdCountsInEveryChunkKind) {
    const int32_t huge = 0x7FFFFFFF;
    struct Case {
        Bytes bytes;
        const char *expected;
    };
    const auto node = [](const char *id, const VoxContent &c) {
        return VoxWriter().model(1, 1, 1, {}).chunk(id, c.bytes()).bytes();
    };
    const Case cases[] = {
        {VoxWriter().size(4, 4, 4).chunk("XYZI", VoxContent().i32(huge).bytes()).bytes(), "voxel count 2147483647"},
        {node("nTRN", VoxContent().i32(0).i32(huge)), "node attribute count 2147483647"},
        {node("nTRN", VoxContent().i32(0).i32(1).i32(huge).i32(0)), "dictionary key 2147483647"},
        {node("nTRN", VoxContent().i32(0).i32(0).i32(1).i32(-1).i32(-1).i32(0x40000000)), "frame count 1073741824"},
        {node("nTRN", VoxContent().i32(0).i32(0).i32(1).i32(-1).i32(-1).i32(1).i32(huge)), "frame attribute count"},
        {node("nGRP", VoxContent().i32(0).i32(0).i32(huge)), "child count 2147483647"},
        {node("nSHP", VoxContent().i32(0).i32(0).i32(huge)), "model count 2147483647"},
        {node("nSHP", VoxContent().i32(0).i32(0).i32(1).i32(0).i32(huge)), "model attribute count"},
        {node("LAYR", VoxContent().i32(0).i32(huge)), "layer attribute count"},
        {node("MATL", VoxContent().i32(1).i32(huge)), "material property count 2147483647"},
        {node("MATL", VoxContent().i32(1).i32(1).i32(huge).i32(0)), "dictionary key 2147483647"},
        {node("RGBA", VoxContent().i32(1)), "RGBA palette (255 used entries)"},
        {VoxWriter().model(huge, 1, 1, {}).bytes(), "size 2147483647 x 1 x 1"},
        {VoxWriter().model(-1, -1, -1, {}).bytes(), "size -1 x -1 x -1"},
    };
    for (const Case &c : cases) {
        const Attempt a = attempt(readOnly, c.bytes);
        EXPECT_TRUE(survived(a, kVoxHeap, c.bytes.size()));
        EXPECT_TRUE(rejectedWith(a, {c.expected}));
    }
}

TEST(HostileVox, LargestModelSizesStayWithinTheColumnLimit) {
    // Four empty 2048^3 models: 2^24 columns, the limit, from 184 bytes; a fifth is refused.
    VoxWriter w;
    for (int i = 0; i < 4; ++i)
        w.model(kMaxVolumeSide, kMaxVolumeSide, kMaxVolumeSide, {});
    const Bytes four = w.bytes();
    const Attempt a = attempt(readOnly, four);
    EXPECT_TRUE(a.accepted) << a.error;
    EXPECT_TRUE(survived(a, kVoxHeap, four.size()));
    EXPECT_GE(a.peakBytes, 4 * kMaxVoxColumns);
    const Bytes five = w.model(kMaxVolumeSide, 1, 1, {}).bytes();
    EXPECT_TRUE(rejectedWith(attempt(readOnly, five), {"over the limit of 16777216"}));
}

TEST(HostileVox, InstancingCannotMultiplyVoxels) {
    // 2^20 instances (the limit) of a 64-voxel model would show 2^26 voxels from 900 bytes.
    const Bytes many = doublingGraph(20, cube(4));
    const Attempt a = attempt(readOnly, many);
    EXPECT_TRUE(survived(a, kVoxHeap, many.size()));
    EXPECT_TRUE(rejectedWith(a, {"shape instances show more than 16777216 voxels"}));
    // 2^12 instances of it (2^18 voxels) are a valid scene.
    const Bytes fewer = doublingGraph(12, cube(4));
    const Attempt b = attempt(readAndPlace, fewer);
    EXPECT_TRUE(b.accepted) << b.error;
    EXPECT_TRUE(survived(b, kVoxPlaceHeap, fewer.size()));
}

TEST(HostileVox, TheInstanceLimitBoundsTheScene) {
    // 2^20 one-voxel instances from 776 bytes: accepted, and placing them stays within the bound
    // (a million instances: linear work, not a hang).
    const Bytes b = doublingGraph(20, cube(1));
    const Attempt a = attempt(readAndPlace, b);
    EXPECT_TRUE(a.accepted) << a.error;
    EXPECT_TRUE(survived(a, kVoxPlaceHeap, b.size(), 60.0));
    std::printf("[ hostile  ] 2^20 instances: %zu bytes of file, %zu bytes of heap to place them\n", b.size(),
                a.peakBytes);
}

TEST(HostileVox, DenseStructuresStayWithinTheBound) {
    // The chunk contents that cost the most heap per byte, each filling about 1 MB.
    constexpr int kItems = 1 << 18;
    const auto withGraph = [](const std::function<void(VoxWriter &)> &graph) {
        VoxWriter w;
        w.model(1, 1, 1, {{0, 0, 0, 1}});
        graph(w);
        return w.bytes();
    };
    std::vector<std::pair<std::string, Bytes>> cases;
    cases.emplace_back("transform keyframes",
                       withGraph([](VoxWriter &w) { w.transform(0, 1, std::vector<VoxDict>(kItems)).shape(1, 0); }));
    cases.emplace_back("empty dictionary entries",
                       withGraph([](VoxWriter &w) { w.transform(0, 1, {{}}, VoxDict(kItems / 2)).shape(1, 0); }));
    cases.emplace_back(
        "group children", withGraph([](VoxWriter &w) {
            w.transform(0, 1, {{}}).group(1, std::vector<int>(kItems, 2)).transform(2, 3, {{}}).shape(3, 0);
        }));
    cases.emplace_back("shape keyframes", withGraph([](VoxWriter &w) {
                           w.transform(0, 1, {{}}).shape(1, std::vector<std::pair<int, VoxDict>>(kItems / 2, {0, {}}));
                       }));
    cases.emplace_back("nodes", withGraph([](VoxWriter &w) {
                           std::vector<int> children;
                           for (int i = 0; i < kItems / 16; ++i)
                               children.push_back(2 + i);
                           w.transform(0, 1, {{}}).group(1, children);
                           for (int child : children)
                               w.group(child, {});
                       }));
    cases.emplace_back("layers", withGraph([](VoxWriter &w) {
                           for (int i = 0; i < kItems / 8; ++i)
                               w.layer(i, {});
                       }));
    std::vector<VoxVoxel> voxels;
    for (int i = 0; i < kItems; ++i)
        voxels.push_back({uint8_t(i % 256), uint8_t(i / 256 % 256), uint8_t(2 * (i / 65536)), 1});
    cases.emplace_back("scattered voxels", VoxWriter().model(256, 256, 8, voxels).bytes());
    for (const auto &[name, bytes] : cases) {
        const Attempt read = attempt(readOnly, bytes), placed = attempt(readAndPlace, bytes);
        EXPECT_TRUE(read.accepted && placed.accepted) << name << ": " << read.error << placed.error;
        EXPECT_TRUE(survived(read, HeapBound{kVoxHeap.perByte, 1 << 20}, bytes.size())) << name;
        EXPECT_TRUE(survived(placed, kVoxPlaceHeap, bytes.size())) << name;
        std::printf("[ hostile  ] %s: %.1f bytes of heap per byte to read, %.1f to read and place\n", name.c_str(),
                    double(read.peakBytes) / bytes.size(), double(placed.peakBytes) / bytes.size());
    }
}

TEST(HostileVox, MeshingManyInstancesIsLinear) {
    // 2^16 one-voxel instances. Appending each part's surface to the whole once cost time
    // quadratic in the part count: this test took minutes that way, and the 2^20 limit hours.
    const Bytes b = doublingGraph(16, cube(1));
    const VoxFile file = readVox(b.data(), b.size());
    const VoxelScene scene = voxScene(file);
    const auto start = std::chrono::steady_clock::now();
    const SceneSurface surface = extractSceneSurface(scene);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(surface.quadCount(), 6u << 16);
    EXPECT_LT(seconds, 10.0);
}
