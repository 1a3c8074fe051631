// Fuzzes the palette reader (binary and JASC-PAL) and the house-colour remap the VXL importer
// applies to it, with the colour and range taken from the input too.
#include "formats/format_error.h"
#include "formats/palette.h"
#include "checks/surface_checks.h"

#include <cstring>

using namespace voxelfair;
using namespace voxelfair::fuzz;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    Palette palette;
    try {
        palette = readPal(data, size);
    } catch (const FormatError &) {
        return 0;
    }
    if (size == 768 && std::memcmp(data, "JASC-PAL", 8) != 0) {
        // Binary: 6-bit channels widened so that 0 and 63 map to 0 and 255.
        for (size_t i = 0; i < 256; ++i) {
            const Rgb c = palette.colours[i];
            check(c.r >> 2 == data[3 * i] && c.g >> 2 == data[3 * i + 1] && c.b >> 2 == data[3 * i + 2],
                  "a binary channel does not widen its 6-bit value");
        }
    }
    // VXL headers give the remap range as two bytes; any order and any values must be safe.
    if (size >= 5)
        remapHouseColours(palette, Rgb{data[0], data[1], data[2]}, int8_t(data[3]), data[4]);
    return 0;
}
