#include "formats/format_error.h"
#include "formats/palette.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <tuple>

using namespace voxelfair;

namespace {

Palette readText(const std::string &text) {
    return readPal(reinterpret_cast<const uint8_t *>(text.data()), text.size());
}

std::string errorOf(const std::vector<uint8_t> &bytes) {
    try {
        readPal(bytes.data(), bytes.size());
    } catch (const FormatError &e) {
        return e.what();
    }
    return "";
}

int brightness(Rgb c) { return c.r + c.g + c.b; }

}  // namespace

TEST(Palette, WidensSixBitChannels) {
    std::vector<uint8_t> bytes(768, 0);
    bytes[3 * 5 + 0] = 63;
    bytes[3 * 5 + 1] = 32;
    bytes[3 * 5 + 2] = 1;
    const Palette p = readPal(bytes.data(), bytes.size());
    EXPECT_EQ(p.colours[5], (Rgb{255, 130, 4}));
    EXPECT_EQ(p.colours[0], (Rgb{0, 0, 0}));
    EXPECT_TRUE(Palette{}.allZero());
    EXPECT_FALSE(p.allZero());
}

TEST(Palette, RejectsChannelsAboveSixBits) {
    std::vector<uint8_t> bytes(768, 10);
    bytes[3 * 200 + 2] = 64;
    const std::string message = errorOf(bytes);
    EXPECT_NE(message.find("entry 200"), std::string::npos) << message;
    EXPECT_NE(message.find("above the 6-bit maximum 63"), std::string::npos) << message;
}

TEST(Palette, RejectsOtherSizes) {
    EXPECT_NE(errorOf(std::vector<uint8_t>(767, 0)).find("767 bytes"), std::string::npos);
    EXPECT_NE(errorOf(std::vector<uint8_t>(769, 0)).find("not a palette"), std::string::npos);
    EXPECT_THROW(readPal(nullptr, 0), FormatError);
}

TEST(Palette, ReadsJascText) {
    const Palette p = readText("JASC-PAL\r\n0100\r\n3\r\n255 0 10\r\n1 2 3\r\n0 128 255\r\n");
    EXPECT_EQ(p.colours[0], (Rgb{255, 0, 10}));
    EXPECT_EQ(p.colours[1], (Rgb{1, 2, 3}));
    EXPECT_EQ(p.colours[2], (Rgb{0, 128, 255}));
    EXPECT_EQ(p.colours[3], (Rgb{}));  // past the count: black

    std::string full = "JASC-PAL\n0100\n256\n";
    for (int i = 0; i < 256; ++i)
        full += std::to_string(i) + " " + std::to_string(255 - i) + " 7\n";
    const Palette q = readText(full);
    EXPECT_EQ(q.colours[255], (Rgb{255, 0, 7}));
    EXPECT_EQ(q.colours[100], (Rgb{100, 155, 7}));
}

TEST(Palette, RejectsBadJascText) {
    EXPECT_THROW(readText("JASC-PAL\n0200\n1\n1 2 3\n"), FormatError);    // version
    EXPECT_THROW(readText("JASC-PAL\n0100\n257\n"), FormatError);         // count
    EXPECT_THROW(readText("JASC-PAL\n0100\n0\n"), FormatError);           // count
    EXPECT_THROW(readText("JASC-PAL\n0100\n2\n1 2 3\n"), FormatError);    // missing line
    EXPECT_THROW(readText("JASC-PAL\n0100\n1\n1 2 256\n"), FormatError);  // 8-bit range
    EXPECT_THROW(readText("JASC-PAL\n0100\n1\n1 2\n"), FormatError);      // two values
    EXPECT_THROW(readText("JASC-PAL\n0100\n1\n1 -2 3\n"), FormatError);   // sign
    EXPECT_THROW(readText("JASC-PAL\n0100\n1\n1 2 3 4\n"), FormatError);  // four values
    EXPECT_THROW(readText("JASC-PAL\n0100\n1\n99999999999 2 3\n"), FormatError);
    try {
        readText("JASC-PAL\n0100\n2\n1 2 3\nx y z\n");
        FAIL() << "no FormatError";
    } catch (const FormatError &e) {
        EXPECT_NE(std::string(e.what()).find("line 5"), std::string::npos) << e.what();
    }
}

TEST(Palette, RemapsHouseColoursWithTheToolsRamp) {
    Palette p = defaultPalette();
    const Palette before = p;
    remapHouseColours(p, Rgb{255, 100, 0});
    EXPECT_EQ(p.colours[16], (Rgb{252, 99, 0}));   // round(100 * 252 / 255) = round(98.8)
    EXPECT_EQ(p.colours[17], (Rgb{236, 93, 0}));   // round(92.5) = 93
    EXPECT_EQ(p.colours[31], (Rgb{32, 13, 0}));    // round(12.5) = 13
    EXPECT_EQ(p.colours[15], before.colours[15]);  // outside the range: untouched
    EXPECT_EQ(p.colours[32], before.colours[32]);
    Palette q;
    remapHouseColours(q, Rgb{255, 255, 255}, 250, 300);  // clamped to the table, ramp continues
    EXPECT_EQ(q.colours[250], (Rgb{252, 252, 252}));
    EXPECT_EQ(q.colours[255], (Rgb{176, 176, 176}));
}

TEST(Palette, DefaultPaletteFollowsItsRule) {
    const Palette p = defaultPalette();
    EXPECT_EQ(p.colours[0], (Rgb{0, 0, 0}));
    Palette red = p;
    remapHouseColours(red, Rgb{255, 0, 0});
    for (int i = kHouseColourFirst; i <= kHouseColourLast; ++i)
        EXPECT_EQ(p.colours[size_t(i)], red.colours[size_t(i)]) << i;
    // 16 ramps, each darkening from its first entry to its last.
    for (int ramp = 0; ramp < 16; ++ramp)
        for (int k = std::max(1, 16 * ramp); k < 16 * ramp + 15; ++k)
            EXPECT_GT(brightness(p.colours[size_t(k)]), brightness(p.colours[size_t(k + 1)])) << "entry " << k;
    // Entries 1..15 are neutral greys.
    for (int k = 1; k < 16; ++k)
        EXPECT_TRUE(p.colours[size_t(k)].r == p.colours[size_t(k)].g &&
                    p.colours[size_t(k)].g == p.colours[size_t(k)].b);
    std::set<std::tuple<int, int, int>> distinct;
    for (Rgb c : p.colours)
        distinct.emplace(c.r, c.g, c.b);
    EXPECT_GT(distinct.size(), 240u);  // the ramps are told apart
}
