#include "formats/palette.h"

#include "formats/format_error.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace voxelfair {

namespace {

constexpr size_t kBinaryPaletteBytes = 768;

// Brightness ramp of the house-colour entries, brightest first (Westwood VXL §6 in doc/formats/westwood.md, after OS SHP Builder).
constexpr uint8_t kHouseRamp[16] = {252, 236, 220, 208, 192, 176, 164, 148, 132, 120, 104, 88, 76, 60, 44, 32};

// 6-bit to 8-bit so that 0 -> 0 and 63 -> 255 (a plain << 2 would top out at 252).
uint8_t widen6(uint8_t v) { return uint8_t((v << 2) | (v >> 4)); }

Palette readBinaryPal(const uint8_t *data) {
    Palette palette;
    for (size_t i = 0; i < kBinaryPaletteBytes; ++i) {
        if (data[i] > 63)
            throw FormatError("binary palette byte " + std::to_string(i) + " (entry " + std::to_string(i / 3) +
                              ") is " + std::to_string(data[i]) + ", above the 6-bit maximum 63");
    }
    for (size_t i = 0; i < 256; ++i)
        palette.colours[i] = Rgb{widen6(data[3 * i]), widen6(data[3 * i + 1]), widen6(data[3 * i + 2])};
    return palette;
}

// Splits text into at most `maxLines` lines without their "\r\n" or "\n" ending; the rest is
// not looked at. (A string per line of a long file of newlines would cost 32 bytes per byte.)
std::vector<std::string> splitLines(const uint8_t *data, size_t size, size_t maxLines) {
    std::vector<std::string> lines;
    std::string line;
    for (size_t i = 0; i < size && lines.size() < maxLines; ++i) {
        const char c = char(data[i]);
        if (c == '\n') {
            if (!line.empty() && line.back() == '\r')
                line.pop_back();
            lines.push_back(std::move(line));
            line.clear();
        } else {
            line.push_back(c);
        }
    }
    if (!line.empty() && line.back() == '\r')
        line.pop_back();
    if (!line.empty() && lines.size() < maxLines)
        lines.push_back(std::move(line));
    return lines;
}

// A line of the file for a message, cut short: a corrupt file may hold one long line.
std::string quoted(const std::string &text) {
    return "\"" + (text.size() <= 32 ? text : text.substr(0, 32) + "...") + "\"";
}

// Parses whitespace-separated decimal integers in [0, maxValue]; false on anything else.
bool parseInts(const std::string &line, std::vector<int> &out, int maxValue) {
    out.clear();
    size_t i = 0;
    for (;;) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        if (i == line.size())
            return true;
        if (line[i] < '0' || line[i] > '9')
            return false;
        long value = 0;
        while (i < line.size() && line[i] >= '0' && line[i] <= '9') {
            value = value * 10 + (line[i++] - '0');
            if (value > maxValue)
                return false;
        }
        if (i < line.size() && line[i] != ' ' && line[i] != '\t')
            return false;
        out.push_back(int(value));
    }
}

// JASC-PAL: "JASC-PAL", "0100", the colour count (1..256), then one "r g b" line per colour
// (8 bits per channel). Entries past the count stay black.
Palette readJascPal(const uint8_t *data, size_t size) {
    const std::vector<std::string> lines = splitLines(data, size, 3 + 256);
    if (lines.size() < 3 || lines[0] != "JASC-PAL" || lines[1] != "0100")
        throw FormatError("JASC-PAL palette: expected \"JASC-PAL\" then the version \"0100\" on lines 1 and 2");
    std::vector<int> values;
    if (!parseInts(lines[2], values, 256) || values.size() != 1 || values[0] < 1)
        throw FormatError("JASC-PAL palette: line 3 must hold the colour count (1 to 256), got " + quoted(lines[2]));
    const size_t count = size_t(values[0]);
    if (lines.size() < 3 + count)
        throw FormatError("JASC-PAL palette: " + std::to_string(count) + " colours announced but only " +
                          std::to_string(lines.size() - 3) + " lines follow");
    Palette palette;
    for (size_t i = 0; i < count; ++i) {
        const std::string &line = lines[3 + i];
        if (!parseInts(line, values, 255) || values.size() != 3)
            throw FormatError("JASC-PAL palette: line " + std::to_string(4 + i) +
                              " must be three values 0..255 (\"r g b\"), got " + quoted(line));
        palette.colours[i] = Rgb{uint8_t(values[0]), uint8_t(values[1]), uint8_t(values[2])};
    }
    return palette;
}

}  // namespace

bool Palette::allZero() const {
    return std::all_of(colours.begin(), colours.end(), [](Rgb c) { return c == Rgb{}; });
}

Palette readPal(const uint8_t *data, size_t size) {
    static const char kJasc[] = "JASC-PAL";
    const size_t jascLength = sizeof kJasc - 1;
    // Checked before the size: a text palette may happen to be 768 bytes long.
    if (size >= jascLength && std::memcmp(data, kJasc, jascLength) == 0)
        return readJascPal(data, size);
    if (size == kBinaryPaletteBytes)
        return readBinaryPal(data);
    throw FormatError("not a palette: " + std::to_string(size) +
                      " bytes, expected 768 bytes of 6-bit RGB or a JASC-PAL text file");
}

void remapHouseColours(Palette &palette, Rgb house, int first, int last) {
    first = std::max(first, 0);
    last = std::min(last, 255);
    // round(c * ramp / 255) in integers; the ramp's last step repeats past 16 entries.
    const auto shade = [](uint8_t c, int ramp) { return uint8_t((c * ramp + 127) / 255); };
    for (int i = first; i <= last; ++i) {
        const int ramp = kHouseRamp[std::min(i - first, 15)];
        palette.colours[size_t(i)] = Rgb{shade(house.r, ramp), shade(house.g, ramp), shade(house.b, ramp)};
    }
}

// The default palette is generated by one rule, so that no game data ships with the project:
// entries 16r .. 16r+15 form ramp r (r = 0..15), the house-colour brightness ramp
// (252, 236, ..., 32 out of 255, brightest first) applied to the ramp's base colour below, exactly
// as remapHouseColours does; then entry 0 is set to black. Ramp 1 (16..31) is therefore the red
// house colour, as in the game palettes, and the other ramps cover what unit art mostly uses:
// greys, greens, browns, sand, metal blues, warning yellows and oranges, skin, glass and lights.
Palette defaultPalette() {
    static constexpr Rgb kRampBase[16] = {
        {255, 255, 255},  //  0 neutral grey (entry 0 black)
        {255, 0, 0},      //  1 house colour (red)
        {200, 215, 130},  //  2 olive drab
        {120, 210, 100},  //  3 foliage green
        {225, 170, 115},  //  4 brown
        {245, 220, 165},  //  5 sand
        {235, 120, 70},   //  6 rust
        {180, 200, 225},  //  7 steel blue-grey
        {100, 150, 255},  //  8 blue
        {255, 230, 90},   //  9 yellow
        {255, 160, 50},   // 10 orange
        {235, 225, 205},  // 11 warm grey
        {190, 140, 235},  // 12 purple
        {100, 225, 215},  // 13 teal (glass, energy)
        {255, 205, 175},  // 14 skin
        {255, 250, 215},  // 15 lights (pale yellow)
    };
    Palette palette;
    for (int r = 0; r < 16; ++r)
        remapHouseColours(palette, kRampBase[r], 16 * r, 16 * r + 15);
    palette.colours[0] = Rgb{};
    return palette;
}

}  // namespace voxelfair
