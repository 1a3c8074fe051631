// Malformed VXL input: every problem is a FormatError that names it and says where it is.
#include "fixtures/vxl_fixtures.h"
#include "formats/format_error.h"
#include "formats/vxl.h"
#include "fixtures/raw_vxl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace voxelfair;
using namespace voxelfair::rawvxl;

namespace {

// The message of the FormatError that reading `bytes` throws ("" if it does not throw).
std::string errorOf(const std::vector<uint8_t> &bytes) {
    try {
        readVxl(bytes.data(), bytes.size());
    } catch (const FormatError &e) {
        return e.what();
    }
    return "";
}

// A valid one-section file (2 x 1 x zSize) whose columns the tests then corrupt.
struct OneSection {
    RawVxl raw;
    RawSection section;

    explicit OneSection(std::vector<RawColumn> columns, uint8_t zSize = 4) {
        section.size[0] = uint8_t(columns.size());
        section.size[2] = zSize;
        raw.addBody(section, columns);
        raw.sections = {section};
    }
    std::vector<uint8_t> bytes() { return raw.bytes(); }
    RawSection &tailer() { return raw.sections[0]; }
    void setSpans(size_t column, int32_t start, int32_t end) {
        patch32(raw.body, size_t(section.spanStartOfs) + 4 * column, uint32_t(start));
        patch32(raw.body, size_t(section.spanEndOfs) + 4 * column, uint32_t(end));
    }
};

OneSection twoColumns() {
    return OneSection(
        {{concat({segment(1, {{1, 2}}), segment(2, {})})}, {segment(0, {{3, 4}, {5, 6}, {7, 8}, {9, 10}})}});
}

std::vector<uint8_t> smallWrittenFile() {
    using namespace voxelfair::fixtures;
    return writeVxl(
        makeModel({makeSection("a", volumeWhere(3, 2, 4, [](int x, int y, int z) { return (x + y + z) % 3 != 0; })),
                   makeSection("b", volumeFromVoxels(1, 2, 2, {{0, 1, 1, {4, 4}}}))}));
}

// Success when reading `bytes` throws a FormatError whose message contains every part.
::testing::AssertionResult errorMentions(const std::vector<uint8_t> &bytes, std::initializer_list<const char *> parts) {
    const std::string message = errorOf(bytes);
    if (message.empty())
        return ::testing::AssertionFailure() << "no FormatError";
    for (const char *part : parts)
        if (message.find(part) == std::string::npos)
            return ::testing::AssertionFailure() << "\"" << message << "\" does not mention \"" << part << "\"";
    return ::testing::AssertionSuccess();
}

}  // namespace

TEST(VxlErrors, TheValidBaseFileReads) {
    EXPECT_EQ(errorOf(twoColumns().bytes()), "");
    EXPECT_EQ(errorOf(smallWrittenFile()), "");
}

TEST(VxlErrors, WrongMagicSaysItIsNotAWestwoodVxl) {
    std::vector<uint8_t> aceOfSpadesLike(4096, 0x40);  // any map bytes
    EXPECT_TRUE(errorMentions(aceOfSpadesLike, {"not a Westwood VXL", "Ace of Spades"}));
    RawVxl raw = twoColumns().raw;
    raw.magic = "Voxel Animatiom";
    EXPECT_TRUE(errorMentions(raw.bytes(), {"not a Westwood VXL"}));
    EXPECT_TRUE(errorMentions(std::vector<uint8_t>{'V', 'o', 'x', 'x'}, {"not a Westwood VXL"}));
}

TEST(VxlErrors, TruncatedHeader) {
    std::vector<uint8_t> bytes = smallWrittenFile();
    bytes.resize(500);
    EXPECT_TRUE(errorMentions(bytes, {"truncated", "802"}));
    EXPECT_TRUE(errorMentions(std::vector<uint8_t>{}, {"truncated"}));
}

TEST(VxlErrors, TruncationAtEveryByteThrows) {
    const std::vector<uint8_t> bytes = smallWrittenFile();
    for (size_t n = 0; n < bytes.size(); ++n) {
        const std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + std::ptrdiff_t(n));
        EXPECT_THROW(readVxl(cut.data(), cut.size()), FormatError) << "cut at " << n;
    }
}

TEST(VxlErrors, CorruptingAnyByteNeverCrashes) {
    // Either a model or a FormatError, whatever the byte: run under the sanitizers in CI.
    const std::vector<uint8_t> bytes = smallWrittenFile();
    for (size_t i = 0; i < bytes.size(); ++i) {
        for (uint8_t value :
             {uint8_t(0), uint8_t(1), uint8_t(0x7F), uint8_t(0x80), uint8_t(0xFF), uint8_t(bytes[i] ^ 0x55)}) {
            std::vector<uint8_t> corrupt = bytes;
            corrupt[i] = value;
            try {
                readVxl(corrupt.data(), corrupt.size());
            } catch (const FormatError &) {
            }
        }
    }
}

TEST(VxlErrors, NoSections) {
    RawVxl raw;
    EXPECT_TRUE(errorMentions(raw.bytes(), {"no sections"}));
}

TEST(VxlErrors, TailerCountDiffersFromSectionCount) {
    RawVxl raw = twoColumns().raw;
    raw.numTailers = 2;
    EXPECT_TRUE(errorMentions(raw.bytes(), {"numTailers 2", "numSections 1"}));
}

TEST(VxlErrors, AbsurdSectionCount) {
    RawVxl raw = twoColumns().raw;
    raw.numSections = raw.numTailers = 0x10000000;
    EXPECT_TRUE(errorMentions(raw.bytes(), {"numSections 268435456", "cannot fit"}));
    raw.numSections = raw.numTailers = 0xFFFFFFFF;
    EXPECT_TRUE(errorMentions(raw.bytes(), {"numSections 4294967295"}));
}

TEST(VxlErrors, BodySizeOutOfRange) {
    RawVxl raw = twoColumns().raw;
    raw.bodySize = int64_t(raw.body.size()) + 1;
    EXPECT_TRUE(errorMentions(raw.bytes(), {"bodySize", "truncated"}));
    raw.bodySize = 0xFFFFFFFF;
    EXPECT_TRUE(errorMentions(raw.bytes(), {"bodySize 4294967295"}));
}

TEST(VxlErrors, SpanArrayOffsetsOutOfRange) {
    for (int32_t bad : {-4, -1, 1 << 20, 33}) {  // 33: the array's last bytes would pass the body end
        OneSection f = twoColumns();
        f.tailer().spanStartOfs = bad;
        EXPECT_TRUE(errorMentions(f.bytes(), {"section 0 (\"raw\")", "spanStartOfs", "outside the body"}));
        f = twoColumns();
        f.tailer().spanEndOfs = bad;
        EXPECT_TRUE(errorMentions(f.bytes(), {"section 0", "spanEndOfs", "outside the body"}));
    }
    for (int32_t bad : {-1, 1 << 20}) {
        OneSection f = twoColumns();
        f.tailer().spanDataOfs = bad;
        EXPECT_TRUE(errorMentions(f.bytes(), {"section 0", "spanDataOfs", "outside the body"}));
    }
}

TEST(VxlErrors, RepeatedCountDiffers) {
    OneSection f({{{0, 1, 5, 5, 2}}, {}});
    EXPECT_TRUE(
        errorMentions(f.bytes(), {"section 0", "column (0, 0)", "repeated count is 2", "count 1", "byte offset 846"}));
}

TEST(VxlErrors, RunPastTheColumnHeight) {
    OneSection f({{}, {segment(1, {{1, 1}, {1, 1}, {1, 1}, {1, 1}})}});  // 1 + 4 > 4
    EXPECT_TRUE(errorMentions(f.bytes(), {"column (1, 0)", "past the column height 4"}));
    OneSection skipOnly({{}, {segment(5, {})}});
    EXPECT_TRUE(errorMentions(skipOnly.bytes(), {"column (1, 0)", "past the column height 4"}));
}

TEST(VxlErrors, OnlyOneOfTheSpansIsMinusOne) {
    OneSection f = twoColumns();
    f.setSpans(1, -1, 9);
    EXPECT_TRUE(errorMentions(f.bytes(), {"column (1, 0)", "spanStart -1, spanEnd 9", "both equal to -1"}));
    f = twoColumns();
    f.setSpans(0, 0, -1);
    EXPECT_TRUE(errorMentions(f.bytes(), {"column (0, 0)", "spanEnd -1", "both equal to -1"}));
}

TEST(VxlErrors, SpanEndBeforeSpanStart) {
    OneSection f = twoColumns();
    f.setSpans(1, 10, 9);
    EXPECT_TRUE(errorMentions(f.bytes(), {"column (1, 0)", "spanEnd before spanStart"}));
}

TEST(VxlErrors, NegativeSpanOffset) {
    OneSection f = twoColumns();
    f.setSpans(0, -8, 3);
    EXPECT_TRUE(errorMentions(f.bytes(), {"column (0, 0)", "negative span offset"}));
}

TEST(VxlErrors, ColumnDataRunsPastSpanEnd) {
    OneSection f = twoColumns();
    f.setSpans(0, 0, 3);  // cuts the first segment (5 bytes)
    EXPECT_TRUE(errorMentions(f.bytes(), {"column (0, 0)", "past spanEnd"}));
    // A column whose segments stop before the top: the next segment header is not there.
    OneSection short_({{segment(0, {{1, 1}})}, {}});
    EXPECT_TRUE(errorMentions(short_.bytes(), {"column (0, 0)", "segment at byte offset", "past spanEnd"}));
}

TEST(VxlErrors, ColumnDataRunsPastTheBody) {
    OneSection f = twoColumns();
    f.setSpans(1, 10, 1000);
    EXPECT_TRUE(errorMentions(f.bytes(), {"column (1, 0)", "past the end of the body"}));
}

TEST(VxlErrors, ZeroSizes) {
    for (int axis = 0; axis < 3; ++axis) {
        OneSection f = twoColumns();
        f.tailer().size[axis] = 0;
        EXPECT_TRUE(errorMentions(f.bytes(), {"section 0", "zero size"}));
    }
}

TEST(VxlErrors, NonFiniteTailerValues) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    OneSection f = twoColumns();
    f.tailer().scale = nan;
    EXPECT_TRUE(errorMentions(f.bytes(), {"section 0", "scale is not a finite number"}));
    f = twoColumns();
    f.tailer().transform[7] = inf;
    EXPECT_TRUE(errorMentions(f.bytes(), {"section 0", "transform entry is not a finite number"}));
    f = twoColumns();
    f.tailer().minBounds[1] = -inf;
    EXPECT_TRUE(errorMentions(f.bytes(), {"minBounds is not a finite number"}));
    f = twoColumns();
    f.tailer().maxBounds[2] = nan;
    EXPECT_TRUE(errorMentions(f.bytes(), {"maxBounds is not a finite number", "byte offset"}));
}
