// Teardown's compressed TDCZ models: a generated family of sizes and fill densities (fixed seeds)
// reads back voxel for voxel like the same model stored as XYZI, whether the zlib stream is left
// unfinished (as Teardown writes it) or finished; corrupt, short or oversized streams are clear
// errors naming the chunk.
#include "fixtures/tdcz_writer.h"
#include "fixtures/vox_writer.h"
#include "vox_expect_error.h"
#include "formats/format_error.h"
#include "formats/vox.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

using namespace voxelfair;
using namespace voxelfair::test;
using namespace voxelfair::fixtures;

namespace {

struct DenseModel {
    int x, y, z;
    Bytes dense;
    std::vector<VoxVoxel> sparse;
};

DenseModel randomModel(std::mt19937 &rng) {
    DenseModel m;
    std::uniform_int_distribution<int> side(1, 40);
    m.x = side(rng), m.y = side(rng), m.z = side(rng);
    const double fill = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    std::bernoulli_distribution solid(fill);
    std::uniform_int_distribution<int> colour(1, 255);
    m.dense.assign(size_t(m.x) * m.y * m.z, 0);
    for (int z = 0; z < m.z; ++z)
        for (int y = 0; y < m.y; ++y)
            for (int x = 0; x < m.x; ++x)
                if (solid(rng)) {
                    const uint8_t c = uint8_t(colour(rng));
                    m.dense[size_t(x) + size_t(m.x) * (y + size_t(m.y) * z)] = c;
                    m.sparse.push_back({uint8_t(x), uint8_t(y), uint8_t(z), c});
                }
    return m;
}

Bytes tdczFile(const DenseModel &m, bool finish) {
    return VoxWriter().size(m.x, m.y, m.z).chunk("TDCZ", tdczContent(m.x, m.y, m.z, m.dense, finish)).bytes();
}

}  // namespace

TEST(VoxTdcz, GeneratedModelsReadLikeTheirXyziTwins) {
    std::mt19937 rng(12);
    for (int trial = 0; trial < 40; ++trial) {
        const DenseModel m = randomModel(rng);
        SCOPED_TRACE("trial " + std::to_string(trial) + ": " + std::to_string(m.x) + "x" + std::to_string(m.y) + "x" +
                     std::to_string(m.z));
        const Bytes xyzi = VoxWriter().model(m.x, m.y, m.z, m.sparse).bytes();
        const VoxFile expected = readVox(xyzi.data(), xyzi.size());
        for (bool finish : {false, true}) {
            const Bytes bytes = tdczFile(m, finish);
            const VoxFile file = readVox(bytes.data(), bytes.size());
            ASSERT_EQ(file.models.size(), 1u);
            const VoxelVolume &a = file.models[0], &b = expected.models[0];
            EXPECT_EQ(a.voxelCount(), m.sparse.size());
            EXPECT_EQ(a.sizeX, m.x);
            EXPECT_EQ(a.sizeZ, m.z);
            for (const VoxVoxel &v : m.sparse) {
                const Voxel *found = a.find(v.x, v.y, v.z);
                ASSERT_NE(found, nullptr);
                EXPECT_EQ(found->colour, b.find(v.x, v.y, v.z)->colour);
            }
        }
    }
}

TEST(VoxTdcz, MixesWithXyziModelsInFileOrder) {
    std::mt19937 rng(7);
    const DenseModel m = randomModel(rng);
    const Bytes bytes = VoxWriter()
                            .model(1, 1, 1, {{0, 0, 0, 9}})
                            .size(m.x, m.y, m.z)
                            .chunk("TDCZ", tdczContent(m.x, m.y, m.z, m.dense))
                            .model(2, 1, 1, {{1, 0, 0, 4}})
                            .bytes();
    const VoxFile file = readVox(bytes.data(), bytes.size());
    ASSERT_EQ(file.models.size(), 3u);
    EXPECT_EQ(file.models[1].voxelCount(), m.sparse.size());
    EXPECT_EQ(file.models[2].find(1, 0, 0)->colour, 4);
}

TEST(VoxTdcz, CorruptOrShortStreamsAreClearErrors) {
    std::mt19937 rng(3);
    DenseModel m = randomModel(rng);
    while (m.dense.size() < 200)
        m = randomModel(rng);
    const Bytes good = tdczContent(m.x, m.y, m.z, m.dense);

    Bytes badHeader = good;
    badHeader[12] ^= 0xff;  // the zlib header's first byte
    expectVoxError(VoxWriter().size(m.x, m.y, m.z).chunk("TDCZ", badHeader).bytes(),
                   {"chunk 'TDCZ' at byte 44", "model 0: corrupt zlib data"});

    Bytes badBlock = good;
    badBlock[14] = 0xff;  // the first deflate block: type 3 is reserved
    expectVoxError(VoxWriter().size(m.x, m.y, m.z).chunk("TDCZ", badBlock).bytes(), {"corrupt zlib data"});

    Bytes shortStream(good.begin(), good.begin() + 12 + 2);  // the zlib header alone
    expectVoxError(VoxWriter().size(m.x, m.y, m.z).chunk("TDCZ", shortStream).bytes(),
                   {"compressed voxels end after 0 of the " + std::to_string(m.dense.size()) + " bytes"});

    // A finished stream of fewer voxels than the size asks for.
    const Bytes fewer = tdczContent(m.x, m.y, m.z, Bytes(m.dense.begin(), m.dense.end() - 1), true);
    expectVoxError(VoxWriter().size(m.x, m.y, m.z).chunk("TDCZ", fewer).bytes(),
                   {"end after " + std::to_string(m.dense.size() - 1)});
}

TEST(VoxTdcz, SizesAndLimitsAreChecked) {
    const Bytes one = tdczContent(1, 1, 1, {5});
    expectVoxError(VoxWriter().size(2, 1, 1).chunk("TDCZ", one).bytes(),
                   {"compressed voxels' size 1 x 1 x 1 differs from the SIZE chunk's 2 x 1 x 1"});
    expectVoxError(VoxWriter().chunk("TDCZ", one).bytes(), {"a TDCZ chunk without a SIZE chunk before it"});
    expectVoxError(VoxWriter().size(1, 1, 1).chunk("TDCZ", {1, 0, 0, 0}).bytes(), {"truncated: TDCZ model size"});
    // 256^3 voxels claimed from a dozen bytes: refused before anything is allocated.
    VoxContent big;
    big.i32(256).i32(256).i32(256).raw({0x78, 0x9c, 0, 0, 0, 0, 0, 0, 0, 0});
    expectVoxError(VoxWriter().size(256, 256, 256).chunk("TDCZ", big.bytes()).bytes(),
                   {"10 compressed bytes cannot hold the 16777216 voxels"});
    VoxContent huge;
    huge.i32(2048).i32(2048).i32(64);
    expectVoxError(VoxWriter().size(2048, 2048, 64).chunk("TDCZ", huge.bytes()).bytes(), {"over the limit of"});
}
