// Hostile .vxl input: a real file truncated at every byte and with random bits flipped, tailer and
// column offsets pointing outside the file, absurd counts and sizes, and span data shared so that
// a small file would decode to many voxels. Each input is accepted or rejected with a FormatError
// naming the problem, within the heap bound below.
#include "fixtures/vxl_fixtures.h"
#include "fixtures/raw_vxl.h"  // hand-assembled VXL bytes
#include "formats/vxl.h"
#include "hostile_input.h"

#include <cstdint>
#include <limits>
#include <random>
#include <string>

using namespace voxelfair;
using namespace voxelfair::test;

namespace {

void readOnly(const uint8_t *data, size_t size) { readVxl(data, size); }

// Everything a VXL decodes to is paid for by bytes present (readVxl caps columns at one per 8
// bytes and voxels at one per 2), so there is no fixed part beyond small strings and vectors.
// The densest case, runs of one voxel, costs 4.5 bytes per byte (DenseStructuresStayWithinTheBound).
constexpr HeapBound kVxlHeap{8, 16 << 10};

constexpr size_t kHeaderBytes = 802, kSectionHeaderBytes = 28, kTailerBytes = 92;

// Where the parts of a well-formed file are, read from its header and tailers.
struct Layout {
    size_t sections = 0, bodyBegin = 0, bodySize = 0;
    size_t tailer(size_t s) const { return bodyBegin + bodySize + kTailerBytes * s; }
};

Layout layoutOf(const Bytes &bytes) {
    Layout l;
    l.sections = load32(bytes, 20);
    l.bodySize = load32(bytes, 28);
    l.bodyBegin = kHeaderBytes + kSectionHeaderBytes * l.sections;
    return l;
}

// A written two-section model, so that the sweeps run without the shared models too.
Bytes fixtureFile() {
    using namespace voxelfair::fixtures;
    return writeVxl(
        makeModel({makeSection("hull", volumeWhere(9, 7, 5, [](int x, int y, int z) { return (x * y + z) % 4 != 1; })),
                   makeSection("turret", volumeWhere(3, 4, 6, [](int x, int, int z) { return x != 1 || z % 2 == 0; }),
                               VxlNormalType::TiberianSun)}));
}

// Every other variant flips bits of the headers and tailers only, where the offsets, counts and
// sizes are; flips in the span data mostly change colours.
void sweepVxlBitFlips(const Bytes &base, uint32_t seed, int variants, SweepRecord &record) {
    const Layout l = layoutOf(base);
    sweepBitFlips(readOnly, base, {seed, variants, 8, {{0, l.bodyBegin}, {l.tailer(0), base.size()}}}, kVxlHeap,
                  record);
}

// The body of a section whose 255 x 255 columns all read the same span data: `column`, or
// nothing (every column empty) when it is empty.
rawvxl::RawVxl sharedSpans(const Bytes &column, size_t sections) {
    using namespace voxelfair::rawvxl;
    constexpr size_t kColumns = 255 * 255;
    RawVxl raw;
    const uint32_t start = column.empty() ? uint32_t(-1) : 0;
    const uint32_t end = column.empty() ? uint32_t(-1) : uint32_t(column.size() - 1);
    for (size_t c = 0; c < kColumns; ++c)
        put32(raw.body, start);
    for (size_t c = 0; c < kColumns; ++c)
        put32(raw.body, end);
    raw.body.insert(raw.body.end(), column.begin(), column.end());
    RawSection s;
    s.size[0] = s.size[1] = s.size[2] = 255;
    s.spanStartOfs = 0;
    s.spanEndOfs = int32_t(4 * kColumns);
    s.spanDataOfs = int32_t(8 * kColumns);
    raw.sections.assign(sections, s);
    return raw;
}

}  // namespace

TEST(HostileVxl, RealFileTruncatedAtEveryByte) {
    VOXELFAIR_LOAD_MODEL_OR_SKIP(jeep, "vxl/jeep.vxl");
    // Cut inside the section headers, the section count is what no longer fits.
    sweepTruncations(readOnly, jeep, kVxlHeap, {"truncated", "cannot fit in a file of"}, "jeep.vxl prefixes");
}

TEST(HostileVxl, RandomBitFlips) {
    SweepRecord record;
    sweepVxlBitFlips(fixtureFile(), 1, 2000, record);
    const Bytes jeep = loadModel("vxl/jeep.vxl");
    const Bytes subapc = loadModel("vxl/subapc.vxl");  // five sections
    if (!jeep.empty())
        sweepVxlBitFlips(jeep, 2, 3000, record);
    if (!subapc.empty())
        sweepVxlBitFlips(subapc, 3, 500, record);
    record.print("bit-flipped .vxl files");
    EXPECT_GT(record.accepted, 0u);
    EXPECT_LT(record.accepted, record.inputs);
}

TEST(HostileVxl, TailerOffsetsOutsideTheBody) {
    VOXELFAIR_LOAD_MODEL_OR_SKIP(jeep, "vxl/jeep.vxl");
    const Layout l = layoutOf(jeep);
    const uint32_t bad[] = {uint32_t(-1), 0x80000000u, 0x7FFFFFFFu, uint32_t(l.bodySize + 1), uint32_t(jeep.size())};
    const char *fields[] = {"spanStartOfs", "spanEndOfs", "spanDataOfs"};
    for (size_t s = 0; s < l.sections; ++s) {
        for (size_t f = 0; f < 3; ++f) {
            for (uint32_t value : bad) {
                Bytes b = jeep;
                patch32(b, l.tailer(s) + 4 * f, value);
                const Attempt a = attempt(readOnly, b);
                const std::string where = "section " + std::to_string(s) + " (";
                EXPECT_TRUE(survived(a, kVxlHeap, b.size()));
                EXPECT_TRUE(rejectedWith(a, {where.c_str(), fields[f], "outside the body"}))
                    << fields[f] << " = " << int32_t(value);
            }
        }
    }
}

TEST(HostileVxl, ColumnSpansOutsideTheBody) {
    VOXELFAIR_LOAD_MODEL_OR_SKIP(jeep, "vxl/jeep.vxl");
    const Layout l = layoutOf(jeep);
    const size_t t = l.tailer(0);
    const size_t startArray = l.bodyBegin + load32(jeep, t), endArray = l.bodyBegin + load32(jeep, t + 4);
    const size_t columns = size_t(jeep[t + 88]) * jeep[t + 89];
    const int32_t bad[] = {int32_t(l.bodySize), std::numeric_limits<int32_t>::max(), -2,
                           std::numeric_limits<int32_t>::min()};
    size_t tried = 0;
    for (size_t c = 0; c < columns; c += 7) {
        if (load32(jeep, startArray + 4 * c) == uint32_t(-1))
            continue;  // empty columns have no data to misplace
        for (int32_t value : bad) {
            for (size_t array : {startArray, endArray}) {
                Bytes b = jeep;
                patch32(b, array + 4 * c, uint32_t(value));
                const Attempt a = attempt(readOnly, b);
                EXPECT_TRUE(survived(a, kVxlHeap, b.size()));
                EXPECT_TRUE(rejectedWith(a, {"section 0", "column ("})) << "column " << c << " = " << value;
                ++tried;
            }
        }
    }
    EXPECT_GT(tried, 100u);
}

TEST(HostileVxl, AbsurdHeaderCounts) {
    VOXELFAIR_LOAD_MODEL_OR_SKIP(jeep, "vxl/jeep.vxl");
    const Layout l = layoutOf(jeep);
    // numSections (with numTailers alike) just past what the file holds, and far past it.
    for (uint32_t count : {uint32_t(jeep.size() / 120), 0x80000000u, 0xFFFFFFFFu}) {
        Bytes b = jeep;
        patch32(b, 20, count);
        patch32(b, 24, count);
        const Attempt a = attempt(readOnly, b);
        EXPECT_TRUE(survived(a, kVxlHeap, b.size()));
        EXPECT_TRUE(rejectedWithAnyOf(a, {"numSections", "bodySize"})) << count;
    }
    for (uint32_t bodySize : {uint32_t(l.bodySize + 1), uint32_t(jeep.size()), 0xFFFFFFFFu}) {
        Bytes b = jeep;
        patch32(b, 28, bodySize);
        const Attempt a = attempt(readOnly, b);
        EXPECT_TRUE(survived(a, kVxlHeap, b.size()));
        EXPECT_TRUE(rejectedWith(a, {"bodySize", "truncated"})) << bodySize;
    }
}

TEST(HostileVxl, LargestSizesInEveryTailer) {
    VOXELFAIR_LOAD_MODEL_OR_SKIP(jeep, "vxl/jeep.vxl");
    const Layout l = layoutOf(jeep);
    for (size_t s = 0; s < l.sections; ++s) {
        Bytes b = jeep;
        b[l.tailer(s) + 88] = b[l.tailer(s) + 89] = b[l.tailer(s) + 90] = 255;
        const Attempt a = attempt(readOnly, b);
        EXPECT_TRUE(survived(a, kVxlHeap, b.size()));
        // 255 x 255 columns need 260100-byte span arrays, far more than the body holds.
        EXPECT_TRUE(rejectedWith(a, {"65025 offsets outside the body"}));
    }
}

TEST(HostileVxl, SharedSpanDataCannotMultiplyVoxels) {
    // One full 255-voxel column read by all 65025 columns: 16.6 million voxels from 521 KB.
    const Bytes column = rawvxl::segment(0, std::vector<std::pair<uint8_t, uint8_t>>(255, {5, 1}));
    for (size_t sections : {1, 8}) {
        const Bytes b = sharedSpans(column, sections).bytes();
        const Attempt a = attempt(readOnly, b);
        EXPECT_TRUE(survived(a, kVxlHeap, b.size())) << sections << " sections";
        EXPECT_TRUE(rejectedWith(a, {"voxels, one per two bytes of the file", "share their span data"}));
    }
}

TEST(HostileVxl, SharedSpanArraysCannotMultiplyColumns) {
    // 255 x 255 empty columns per 120-byte section: a 260 KB column index each, without the cap.
    const Bytes b = sharedSpans({}, 2000).bytes();
    const Attempt a = attempt(readOnly, b);
    EXPECT_TRUE(survived(a, kVxlHeap, b.size()));
    EXPECT_TRUE(rejectedWith(a, {"columns, one per eight bytes of the file", "share their span arrays"}));
    // One such section is a valid (empty) model.
    const Bytes one = sharedSpans({}, 1).bytes();
    const Attempt single = attempt(readOnly, one);
    EXPECT_TRUE(survived(single, kVxlHeap, one.size()));
    EXPECT_TRUE(single.accepted) << single.error;
}

TEST(HostileVxl, DenseStructuresStayWithinTheBound) {
    using namespace voxelfair::fixtures;
    std::vector<std::pair<std::string, Bytes>> cases;
    // Runs of one voxel each (5 bytes of span data for a 10-byte run and voxel); 1-column
    // sections (120 bytes of header and tailer each); 255 x 255 columns of one voxel.
    cases.emplace_back("one-voxel runs",
                       writeVxl(makeModel({makeSection(
                           "runs", volumeWhere(200, 200, 255, [](int, int, int z) { return z % 2 == 0; }))})));
    std::vector<VxlSection> sections(8000, makeSection("s", volumeWhere(1, 1, 1, [](int, int, int) { return true; })));
    cases.emplace_back("many sections", writeVxl(makeModel(sections)));
    cases.emplace_back(
        "many columns",
        writeVxl(makeModel({makeSection("columns", volumeWhere(255, 255, 1, [](int, int, int) { return true; }))})));
    for (const auto &[name, bytes] : cases) {
        const Attempt a = attempt(readOnly, bytes);
        EXPECT_TRUE(a.accepted) << name << ": " << a.error;
        EXPECT_TRUE(survived(a, kVxlHeap, bytes.size())) << name;
        std::printf("[ hostile  ] %s: %.1f bytes of heap per byte\n", name.c_str(), double(a.peakBytes) / bytes.size());
    }
}
