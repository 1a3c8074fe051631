// Hostile .pal input: a real binary palette truncated at every byte and with random bits flipped,
// bit-flipped JASC-PAL text, and JASC-PAL files with absurd counts, huge lines or endless lines.
#include "formats/palette.h"
#include "hostile_input.h"

#include <random>
#include <string>

using namespace voxelfair;
using namespace voxelfair::test;

namespace {

void readOnly(const uint8_t *data, size_t size) { readPal(data, size); }

// A palette is 256 colours whatever the input: only the first lines of a text palette are kept
// (and one line at most as long as the file, grown by doubling).
constexpr HeapBound kPalHeap{4, 64 << 10};

Bytes text(const std::string &s) { return Bytes(s.begin(), s.end()); }

Bytes jascFile() {
    std::string s = "JASC-PAL\r\n0100\r\n256\r\n";
    for (int i = 0; i < 256; ++i)
        s += std::to_string(i) + " " + std::to_string(255 - i) + " " + std::to_string(i * 7 % 256) + "\r\n";
    return text(s);
}

}  // namespace

TEST(HostilePal, RealFileTruncatedAtEveryByte) {
    VOXELFAIR_LOAD_MODEL_OR_SKIP(pal, "pal/ra2_unittem.pal");
    for (size_t n = 0; n < pal.size(); ++n) {
        const Bytes cut(pal.begin(), pal.begin() + std::ptrdiff_t(n));
        const Attempt a = attempt(readOnly, cut);
        ASSERT_TRUE(survived(a, kPalHeap, n)) << "cut at " << n;
        ASSERT_TRUE(rejectedWith(a, {"not a palette", std::to_string(n).c_str()})) << "cut at " << n;
    }
}

TEST(HostilePal, RandomBitFlips) {
    SweepRecord record;
    const auto sweep = [&](const Bytes &base, uint32_t seed, int variants, const char *expected) {
        sweepBitFlips(readOnly, base, {seed, variants, 4, {}}, kPalHeap, record, {expected, "not a palette"});
    };
    const Bytes pal = loadModel("pal/ts_unittem.pal");
    if (!pal.empty())
        sweep(pal, 21, 2000, "above the 6-bit maximum");
    sweep(jascFile(), 22, 3000, "JASC-PAL palette");
    record.print("bit-flipped .pal files");
    EXPECT_GT(record.accepted, 0u);
    EXPECT_LT(record.accepted, record.inputs);
}

TEST(HostilePal, AbsurdJascCounts) {
    for (const char *count : {"257", "0", "99999999999999999999", "-1", "1 2", "256"}) {
        const Bytes b = text(std::string("JASC-PAL\n0100\n") + count + "\n1 2 3\n");
        const Attempt a = attempt(readOnly, b);
        EXPECT_TRUE(survived(a, kPalHeap, b.size()));
        EXPECT_TRUE(rejectedWithAnyOf(a, {"line 3 must hold the colour count", "256 colours announced but only 1"}))
            << count;
    }
}

TEST(HostilePal, EndlessLinesCostNothing) {
    // 8 MB of empty lines after a valid palette: only the lines the palette needs are kept.
    Bytes b = jascFile();
    b.resize(b.size() + (8 << 20), '\n');
    const Attempt a = attempt(readOnly, b);
    EXPECT_TRUE(a.accepted) << a.error;
    EXPECT_LT(a.peakBytes, size_t(1) << 20);
    EXPECT_TRUE(survived(a, kPalHeap, b.size()));
}

TEST(HostilePal, AHugeLineIsNotQuotedWhole) {
    std::string line(4 << 20, '7');
    const Bytes b = text("JASC-PAL\n0100\n1\n" + line + "\n");
    const Attempt a = attempt(readOnly, b);
    EXPECT_TRUE(survived(a, kPalHeap, b.size()));
    EXPECT_TRUE(rejectedWith(a, {"line 4 must be three values", "777..."}));
}
