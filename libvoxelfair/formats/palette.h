// 256-colour palettes: Westwood .pal files, the built-in default, house-colour remapping.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace voxelfair {

struct Rgb {
    uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(Rgb a, Rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
    friend bool operator!=(Rgb a, Rgb b) { return !(a == b); }
};

struct Palette {
    std::array<Rgb, 256> colours{};
    bool allZero() const;
};

// Reads a .pal: either exactly 768 bytes of 6-bit RGB (0..63, widened to 8 bits as
// (v << 2) | (v >> 4) so that 63 becomes 255), or a JASC-PAL text palette (8-bit values).
// Throws FormatError for any other size, a channel above 63 in a binary palette, or bad text.
Palette readPal(const uint8_t *data, size_t size);

// The palette used when a VXL's embedded palette is all zeros and the user chose no .pal file.
// It is generated, not copied from a game (see palette.cpp for the exact rule).
Palette defaultPalette();

// The house-colour range of Westwood palettes (the VXL header's remap bytes, always 16..31).
constexpr int kHouseColourFirst = 16;
constexpr int kHouseColourLast = 31;

// Rebuilds entries first..last as a brightness ramp of `house`, the way the game tools do:
// entry i = round(house * ramp[i - first] / 255) with ramp = 252, 236, ..., 32 (16 steps).
void remapHouseColours(Palette &palette, Rgb house, int first = kHouseColourFirst, int last = kHouseColourLast);

}  // namespace voxelfair
