#include "render/png_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <zlib.h>

namespace voxelfair::render {

namespace {

void putU32(std::vector<uint8_t> &out, uint32_t v) {
    out.push_back(uint8_t(v >> 24));
    out.push_back(uint8_t(v >> 16));
    out.push_back(uint8_t(v >> 8));
    out.push_back(uint8_t(v));
}

// Length, type, data, then the CRC of type and data (PNG spec 5.3).
void putChunk(std::vector<uint8_t> &out, const char type[4], const uint8_t *data, size_t size) {
    putU32(out, uint32_t(size));
    const size_t typeAt = out.size();
    out.insert(out.end(), type, type + 4);
    if (size > 0)
        out.insert(out.end(), data, data + size);
    const uLong crc = crc32(0L, out.data() + typeAt, uInt(4 + size));
    putU32(out, uint32_t(crc));
}

}  // namespace

std::vector<uint8_t> encodePng(const uint8_t *pixels, int width, int height, int channels) {
    if (!pixels || width <= 0 || height <= 0 || (channels != 3 && channels != 4))
        return {};
    const size_t rowBytes = size_t(width) * size_t(channels);

    // Filtered scanlines: a filter byte (2 = Up: each byte minus the one above) then the row.
    std::vector<uint8_t> raw((rowBytes + 1) * size_t(height));
    for (int y = 0; y < height; ++y) {
        uint8_t *dst = &raw[size_t(y) * (rowBytes + 1)];
        const uint8_t *row = pixels + size_t(y) * rowBytes;
        const uint8_t *above = y > 0 ? row - rowBytes : nullptr;
        dst[0] = 2;
        for (size_t i = 0; i < rowBytes; ++i)
            dst[1 + i] = uint8_t(row[i] - (above ? above[i] : 0));
    }
    uLongf packedSize = compressBound(uLong(raw.size()));
    std::vector<uint8_t> packed(packedSize);
    if (compress2(packed.data(), &packedSize, raw.data(), uLong(raw.size()), 6) != Z_OK)
        return {};

    std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<uint8_t> header;
    putU32(header, uint32_t(width));
    putU32(header, uint32_t(height));
    header.push_back(8);                      // bit depth
    header.push_back(channels == 4 ? 6 : 2);  // colour type: RGBA or RGB
    header.push_back(0);                      // deflate
    header.push_back(0);                      // adaptive filtering
    header.push_back(0);                      // no interlace
    putChunk(out, "IHDR", header.data(), header.size());
    putChunk(out, "IDAT", packed.data(), packedSize);
    putChunk(out, "IEND", nullptr, 0);
    return out;
}

bool writePng(const std::string &path, const uint8_t *pixels, int width, int height, int channels, std::string *error) {
    const std::vector<uint8_t> bytes = encodePng(pixels, width, height, channels);
    if (bytes.empty()) {
        if (error)
            *error = "cannot encode a " + std::to_string(width) + "x" + std::to_string(height) + "x" +
                     std::to_string(channels) + " image";
        return false;
    }
    FILE *file = std::fopen(path.c_str(), "wb");
    if (!file) {
        if (error)
            *error = path + ": " + std::strerror(errno);
        return false;
    }
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    const bool closed = std::fclose(file) == 0;
    if ((!ok || !closed) && error)
        *error = path + ": write failed";
    return ok && closed;
}

}  // namespace voxelfair::render
