// A minimal PNG encoder for the report's pictures and test images: 8-bit RGB or RGBA, no
// interlacing, every row filtered with "Up" (rendered images are mostly flat, so the vertical
// difference is mostly zero and deflates well), compressed with zlib.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace voxelfair::render {

// `pixels` holds height rows of width * channels bytes, top row first. channels is 3 (RGB) or 4
// (RGBA). Returns the whole file, or an empty vector for bad arguments.
std::vector<uint8_t> encodePng(const uint8_t *pixels, int width, int height, int channels);

// Encodes and writes `path`. Returns false (and says why in *error when given) on failure.
bool writePng(const std::string &path, const uint8_t *pixels, int width, int height, int channels,
              std::string *error = nullptr);

}  // namespace voxelfair::render
