// Whole-file reading for the parsers, which all work on byte arrays.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace voxelfair {

// Largest model file read (256 MiB): far above any real VXL (< 2 MiB) or VOX (< 100 MiB) file,
// low enough that a wrong path (a device, a huge file) cannot exhaust memory.
constexpr size_t kMaxModelFileBytes = size_t(256) << 20;

// Reads the file at `path`; throws FormatError("<path>: <reason>") when it cannot be opened or
// read, or is larger than `maxBytes`.
std::vector<uint8_t> readFileBytes(const std::string &path, size_t maxBytes = kMaxModelFileBytes);

}  // namespace voxelfair
