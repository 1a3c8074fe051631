// Hostile .hva input: a real file truncated at every byte and with random bits flipped, and frame
// and section counts whose products overflow. HVA has no offsets: its size must match its counts.
#include "formats/hva.h"
#include "hostile_input.h"

#include <random>
#include <string>

using namespace voxelfair;
using namespace voxelfair::test;

namespace {

void readOnly(const uint8_t *data, size_t size) { readHva(data, size); }

// Names (a 32-byte string per 16 bytes) and matrices (48 bytes each), both sized by the file.
constexpr HeapBound kHvaHeap{4, 16 << 10};

// Two sections, three frames, as the writer lays them out.
Bytes fixtureFile() {
    HvaAnimation a;
    a.frameCount = 3;
    a.sectionNames = {"body", "a very long section name"};
    for (int m = 0; m < 6; ++m) {
        Matrix3x4 matrix = kIdentity3x4;
        matrix[3] = float(m);
        a.matrices.push_back(matrix);
    }
    return writeHva(a);
}

}  // namespace

TEST(HostileHva, RealFileTruncatedAtEveryByte) {
    VOXELFAIR_LOAD_MODEL_OR_SKIP(hmec, "vxl/hmec.hva");  // 13 sections, 17 frames
    sweepTruncations(readOnly, hmec, kHvaHeap, {"truncated", "does not match"}, "hmec.hva prefixes");
}

TEST(HostileHva, RandomBitFlips) {
    SweepRecord record;
    // Every other variant flips only the section and frame counts; the rest mostly matrix floats.
    const auto sweep = [&](const Bytes &base, uint32_t seed, int variants) {
        sweepBitFlips(readOnly, base, {seed, variants, 8, {{16, 24}}}, kHvaHeap, record,
                      {"does not match", "no frames", "no sections", "not a finite number"});
    };
    sweep(fixtureFile(), 11, 2000);
    const Bytes hmec = loadModel("vxl/hmec.hva");
    if (!hmec.empty())
        sweep(hmec, 12, 3000);
    record.print("bit-flipped .hva files");
    EXPECT_GT(record.accepted, 0u);
    EXPECT_LT(record.accepted, record.inputs);
}

TEST(HostileHva, CountsWhoseProductsOverflow) {
    const Bytes base = fixtureFile();
    // Pairs whose size formula 24 + 16 s + 48 f s wraps in 32 or 64 bits, or nearly matches.
    const std::pair<uint32_t, uint32_t> counts[] = {
        {0xFFFFFFFFu, 0xFFFFFFFFu}, {0x80000000u, 2},           {1, 0x80000000u}, {0x55555556u, 3},
        {3, 0x0AAAAAABu},           {0x10000000u, 0x10000000u}, {4, 2},           {3, 3}};
    for (const auto &[frames, sections] : counts) {
        Bytes b = base;
        patch32(b, 16, frames);
        patch32(b, 20, sections);
        const Attempt a = attempt(readOnly, b);
        EXPECT_TRUE(survived(a, kHvaHeap, b.size()));
        const std::string expected = std::to_string(frames) + " frames x " + std::to_string(sections) + " sections";
        EXPECT_TRUE(rejectedWith(a, {"does not match", expected.c_str()}));
    }
}
