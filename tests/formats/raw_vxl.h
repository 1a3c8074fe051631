// Hand-assembled VXL bytes for the reader's tests: every header and tailer field can be set to
// any value, including inconsistent ones that writeVxl would never produce.
#pragma once

#include "formats/vxl.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace voxelfair::rawvxl {

inline void put32(std::vector<uint8_t> &out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}
inline void putFloat(std::vector<uint8_t> &out, float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    put32(out, bits);
}
inline void patch32(std::vector<uint8_t> &bytes, size_t offset, uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes[offset + size_t(i)] = uint8_t(v >> (8 * i));
}
inline void patchFloat(std::vector<uint8_t> &bytes, size_t offset, float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    patch32(bytes, offset, bits);
}

// One column's span bytes and where they go: `data` is appended to the section's span data.
struct RawColumn {
    std::vector<uint8_t> data;  // empty: an empty column (spanStart = spanEnd = -1)
};

struct RawSection {
    std::string name = "raw";
    int32_t spanStartOfs = 0, spanEndOfs = 0, spanDataOfs = 0;
    float scale = 1.0f / 12.0f;
    Matrix3x4 transform = kIdentity3x4;
    float minBounds[3] = {0, 0, 0};
    float maxBounds[3] = {1, 1, 1};
    uint8_t size[3] = {1, 1, 1};
    uint8_t normalType = 4;
};

struct RawVxl {
    std::string magic = "Voxel Animation";
    std::vector<RawSection> sections;
    std::vector<uint8_t> body;
    // Header counts; negative means "take the true value".
    int64_t numSections = -1, numTailers = -1, bodySize = -1;

    // Appends a contiguous section body for `columns` (x fastest) and points `section` at it.
    void addBody(RawSection &section, const std::vector<RawColumn> &columns) {
        section.spanStartOfs = int32_t(body.size());
        section.spanEndOfs = section.spanStartOfs + int32_t(4 * columns.size());
        section.spanDataOfs = section.spanEndOfs + int32_t(4 * columns.size());
        std::vector<uint8_t> starts, ends, data;
        for (const RawColumn &c : columns) {
            const bool empty = c.data.empty();
            put32(starts, empty ? uint32_t(-1) : uint32_t(data.size()));
            data.insert(data.end(), c.data.begin(), c.data.end());
            put32(ends, empty ? uint32_t(-1) : uint32_t(data.size() - 1));
        }
        body.insert(body.end(), starts.begin(), starts.end());
        body.insert(body.end(), ends.begin(), ends.end());
        body.insert(body.end(), data.begin(), data.end());
    }

    size_t bodyBegin() const { return 802 + 28 * sections.size(); }

    std::vector<uint8_t> bytes() const {
        std::vector<uint8_t> out(16, 0);
        std::memcpy(out.data(), magic.data(), std::min<size_t>(magic.size(), 16));
        put32(out, 1);
        put32(out, uint32_t(numSections >= 0 ? numSections : int64_t(sections.size())));
        put32(out, uint32_t(numTailers >= 0 ? numTailers : int64_t(sections.size())));
        put32(out, uint32_t(bodySize >= 0 ? bodySize : int64_t(body.size())));
        out.push_back(16);
        out.push_back(31);
        out.resize(802, 0);
        for (size_t s = 0; s < sections.size(); ++s) {
            std::vector<uint8_t> name(16, 0);
            std::memcpy(name.data(), sections[s].name.data(), std::min<size_t>(sections[s].name.size(), 16));
            out.insert(out.end(), name.begin(), name.end());
            put32(out, uint32_t(s));
            put32(out, 1);
            put32(out, 2);
        }
        out.insert(out.end(), body.begin(), body.end());
        for (const RawSection &s : sections) {
            put32(out, uint32_t(s.spanStartOfs));
            put32(out, uint32_t(s.spanEndOfs));
            put32(out, uint32_t(s.spanDataOfs));
            putFloat(out, s.scale);
            for (float v : s.transform) putFloat(out, v);
            for (float v : s.minBounds) putFloat(out, v);
            for (float v : s.maxBounds) putFloat(out, v);
            out.insert(out.end(), s.size, s.size + 3);
            out.push_back(s.normalType);
        }
        return out;
    }
};

// Segment bytes: skip, count, the voxels' (colour, normal) pairs, count again.
inline std::vector<uint8_t> segment(uint8_t skip, std::vector<std::pair<uint8_t, uint8_t>> voxels) {
    std::vector<uint8_t> out{skip, uint8_t(voxels.size())};
    for (auto [colour, normal] : voxels) {
        out.push_back(colour);
        out.push_back(normal);
    }
    out.push_back(uint8_t(voxels.size()));
    return out;
}

inline std::vector<uint8_t> concat(std::initializer_list<std::vector<uint8_t>> parts) {
    std::vector<uint8_t> out;
    for (const auto &p : parts) out.insert(out.end(), p.begin(), p.end());
    return out;
}

inline VxlModel read(const std::vector<uint8_t> &bytes) { return readVxl(bytes.data(), bytes.size()); }

}  // namespace voxelfair::rawvxl
