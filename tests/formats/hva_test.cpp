#include "formats/format_error.h"
#include "formats/hva.h"
#include "fixtures/raw_vxl.h"

#include <gtest/gtest.h>

#include <limits>

using namespace voxelfair;

namespace {

HvaAnimation sampleAnimation() {
    HvaAnimation a;
    a.frameCount = 3;
    a.sectionNames = {"BODY", "TURRET"};
    for (int f = 0; f < 3; ++f)
        for (int s = 0; s < 2; ++s) {
            Matrix3x4 m = kIdentity3x4;
            m[3] = float(f) * 1.5f;
            m[7] = float(s) - 0.25f;
            m[11] = -float(f * s);
            a.matrices.push_back(m);
        }
    return a;
}

HvaAnimation read(const std::vector<uint8_t> &bytes) { return readHva(bytes.data(), bytes.size()); }

std::string errorOf(const std::vector<uint8_t> &bytes) {
    try {
        read(bytes);
    } catch (const FormatError &e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(Hva, RoundTrip) {
    const HvaAnimation a = sampleAnimation();
    const std::vector<uint8_t> bytes = writeHva(a);
    EXPECT_EQ(bytes.size(), 24u + 16u * 2 + 48u * 3 * 2);
    const HvaAnimation b = read(bytes);
    EXPECT_EQ(b.frameCount, 3);
    EXPECT_EQ(b.sectionNames, a.sectionNames);
    EXPECT_EQ(b.matrices, a.matrices);
    // Section-fastest order: frame 2, section 1 is the last matrix.
    EXPECT_EQ(b.matrix(2, 1)[3], 3.0f);
    EXPECT_EQ(b.matrix(2, 1)[11], -2.0f);
    EXPECT_EQ(b.matrix(1, 0)[7], -0.25f);
}

TEST(Hva, RejectsAnySizeButTheExactOne) {
    const std::vector<uint8_t> bytes = writeHva(sampleAnimation());
    for (size_t n = 0; n < bytes.size(); ++n) {
        const std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + std::ptrdiff_t(n));
        EXPECT_THROW(readHva(cut.data(), cut.size()), FormatError) << "cut at " << n;
    }
    std::vector<uint8_t> longer = bytes;
    longer.push_back(0);
    EXPECT_NE(errorOf(longer).find("does not match 3 frames x 2 sections"), std::string::npos) << errorOf(longer);
}

TEST(Hva, RejectsZeroFramesOrSections) {
    std::vector<uint8_t> bytes = writeHva(sampleAnimation());
    rawvxl::patch32(bytes, 16, 0);
    EXPECT_NE(errorOf(bytes).find("no frames"), std::string::npos);
    bytes = writeHva(sampleAnimation());
    rawvxl::patch32(bytes, 20, 0);
    EXPECT_NE(errorOf(bytes).find("no sections"), std::string::npos);
}

TEST(Hva, RejectsHugeCountsWithoutOverflow) {
    std::vector<uint8_t> bytes = writeHva(sampleAnimation());
    rawvxl::patch32(bytes, 16, 0xFFFFFFFF);
    rawvxl::patch32(bytes, 20, 0xFFFFFFFF);
    EXPECT_NE(errorOf(bytes).find("does not match"), std::string::npos);
    // A product computed in 32 bits would wrap around to a small, plausible size.
    bytes = writeHva(sampleAnimation());
    rawvxl::patch32(bytes, 16, 0x80000001);
    EXPECT_NE(errorOf(bytes).find("does not match"), std::string::npos);
}

TEST(Hva, RejectsNonFiniteMatrixEntries) {
    std::vector<uint8_t> bytes = writeHva(sampleAnimation());
    const size_t frame1Section0Entry5 = 24 + 16 * 2 + 48 * 2 + 4 * 5;
    rawvxl::patchFloat(bytes, frame1Section0Entry5, std::numeric_limits<float>::quiet_NaN());
    const std::string message = errorOf(bytes);
    EXPECT_NE(message.find("frame 1, section 0: matrix entry 5 is not a finite number"), std::string::npos) << message;
}

TEST(Hva, WriterRejectsInconsistentAnimations) {
    HvaAnimation a = sampleAnimation();
    a.matrices.pop_back();
    EXPECT_THROW(writeHva(a), FormatError);
    EXPECT_THROW(writeHva(HvaAnimation{}), FormatError);
}
