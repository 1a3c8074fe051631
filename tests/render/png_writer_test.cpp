#include "render/png_writer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <zlib.h>

using namespace voxelfair::render;

namespace {

uint32_t readU32(const uint8_t *p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

struct Chunk {
    std::string type;
    std::vector<uint8_t> data;
};

// Splits a PNG into chunks, checking the signature and every CRC.
std::vector<Chunk> parseChunks(const std::vector<uint8_t> &png) {
    static const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    EXPECT_GE(png.size(), 8u);
    EXPECT_TRUE(std::equal(signature, signature + 8, png.begin()));
    std::vector<Chunk> chunks;
    size_t at = 8;
    while (at + 12 <= png.size()) {
        const uint32_t length = readU32(&png[at]);
        EXPECT_LE(at + 12 + length, png.size());
        Chunk c;
        c.type.assign(png.begin() + long(at + 4), png.begin() + long(at + 8));
        c.data.assign(png.begin() + long(at + 8), png.begin() + long(at + 8 + length));
        EXPECT_EQ(readU32(&png[at + 8 + length]), uint32_t(crc32(0L, &png[at + 4], uInt(4 + length)))) << c.type;
        chunks.push_back(std::move(c));
        at += 12 + length;
    }
    EXPECT_EQ(at, png.size());
    return chunks;
}

// Decodes what encodePng writes (one IDAT, 8-bit, filter types 0-2) back to pixels.
std::vector<uint8_t> decode(const std::vector<uint8_t> &png, int width, int height, int channels) {
    const std::vector<Chunk> chunks = parseChunks(png);
    EXPECT_EQ(chunks.size(), 3u);
    if (chunks.size() != 3)
        return {};
    EXPECT_EQ(chunks[0].type, "IHDR");
    EXPECT_EQ(readU32(&chunks[0].data[0]), uint32_t(width));
    EXPECT_EQ(readU32(&chunks[0].data[4]), uint32_t(height));
    EXPECT_EQ(chunks[0].data[8], 8);
    EXPECT_EQ(chunks[0].data[9], channels == 4 ? 6 : 2);
    EXPECT_EQ(chunks[1].type, "IDAT");
    EXPECT_EQ(chunks[2].type, "IEND");
    const size_t rowBytes = size_t(width) * size_t(channels);
    std::vector<uint8_t> raw((rowBytes + 1) * size_t(height));
    uLongf rawSize = uLongf(raw.size());
    EXPECT_EQ(uncompress(raw.data(), &rawSize, chunks[1].data.data(), uLong(chunks[1].data.size())), Z_OK);
    EXPECT_EQ(rawSize, raw.size());
    std::vector<uint8_t> pixels(rowBytes * size_t(height));
    for (int y = 0; y < height; ++y) {
        const uint8_t filter = raw[size_t(y) * (rowBytes + 1)];
        EXPECT_LE(filter, 2);
        for (size_t i = 0; i < rowBytes; ++i) {
            const uint8_t v = raw[size_t(y) * (rowBytes + 1) + 1 + i];
            const uint8_t left = i >= size_t(channels) ? pixels[size_t(y) * rowBytes + i - size_t(channels)] : 0;
            const uint8_t up = y > 0 ? pixels[size_t(y - 1) * rowBytes + i] : 0;
            pixels[size_t(y) * rowBytes + i] = uint8_t(v + (filter == 1 ? left : filter == 2 ? up : 0));
        }
    }
    return pixels;
}

TEST(PngWriter, RgbRoundTrips) {
    const int width = 5, height = 3;
    std::vector<uint8_t> pixels;
    for (int i = 0; i < width * height * 3; ++i)
        pixels.push_back(uint8_t(i * 37 + 11));
    const std::vector<uint8_t> png = encodePng(pixels.data(), width, height, 3);
    EXPECT_EQ(decode(png, width, height, 3), pixels);
}

TEST(PngWriter, RgbaRoundTrips) {
    const int width = 2, height = 4;
    std::vector<uint8_t> pixels;
    for (int i = 0; i < width * height * 4; ++i)
        pixels.push_back(uint8_t(255 - i * 9));
    EXPECT_EQ(decode(encodePng(pixels.data(), width, height, 4), width, height, 4), pixels);
}

TEST(PngWriter, RejectsBadArguments) {
    const uint8_t pixel[4] = {};
    EXPECT_TRUE(encodePng(nullptr, 1, 1, 3).empty());
    EXPECT_TRUE(encodePng(pixel, 0, 1, 3).empty());
    EXPECT_TRUE(encodePng(pixel, 1, 1, 2).empty());
    std::string error;
    EXPECT_FALSE(writePng("/nonexistent-folder/x.png", pixel, 1, 1, 3, &error));
    EXPECT_NE(error.find("/nonexistent-folder/x.png"), std::string::npos);
}

TEST(PngWriter, WritesTheFile) {
    const uint8_t pixels[2 * 2 * 3] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    const std::string path = (std::filesystem::temp_directory_path() / "voxelfair_png_writer_test.png").string();
    ASSERT_TRUE(writePng(path, pixels, 2, 2, 3));
    std::ifstream in(path, std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(bytes, encodePng(pixels, 2, 2, 3));
    std::remove(path.c_str());
}

}  // namespace
