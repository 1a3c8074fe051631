// The VXL reader (readVxl, formats/vxl.h): header, section headers and tailers, then each
// section's span columns into a VoxelVolume, every offset and count checked against the file.
#include "formats/vxl.h"

#include "formats/byte_reader.h"
#include "formats/vxl_layout.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace voxelfair {

namespace {

using namespace vxl;

// What a file may decode to. Without sharing, each column takes 8 bytes of span arrays and each
// voxel 2 bytes of span data, so a file of n bytes holds fewer than n / 8 columns and n / 2
// voxels. Sharing is legal (all is addressed by offsets) but no known writer does it (none of
// 263 real files surveyed does); unchecked, each 120-byte section re-reading another's span arrays and data
// would add 65025 columns and 16.6 million voxels. The caps keep memory and time proportional to
// the file.
struct DecodeBudget {
    explicit DecodeBudget(size_t fileSize) : fileSize(fileSize), columns(fileSize / 8), voxels(fileSize / 2) {}
    size_t fileSize;
    uint64_t columns, voxels;  // left
};

// The tailer fields that locate and size a section's body.
struct SpanLayout {
    int32_t startOfs = 0, endOfs = 0, dataOfs = 0;
    int sizeX = 0, sizeY = 0, sizeZ = 0;
};

std::string sectionLabel(size_t index, const std::string &name) {
    return "section " + std::to_string(index) + " (\"" + name + "\")";
}

float finiteFloat(const ByteReader &in, uint64_t offset, const std::string &where, const char *field) {
    const float v = in.f32(offset, field);
    if (!std::isfinite(v))
        throw FormatError(where + ": " + field + " is not a finite number (byte offset " + std::to_string(offset) +
                          ")");
    return v;
}

void checkMagic(const uint8_t *data, size_t size) {
    // A file shorter than the magic but matching it so far is a truncated VXL, not another format.
    if (size > 0 && std::memcmp(data, kMagic, std::min(size, kMagicLength)) != 0)
        throw FormatError(
            "not a Westwood VXL: the file does not start with \"Voxel Animation\" (Ace of Spades maps also use "
            "the .vxl extension but are a different format)");
}

// Parses columns of one section into its volume; errors name the section and the column.
class ColumnReader {
public:
    ColumnReader(const std::string &where, int sizeX, int sizeY, int sizeZ, uint8_t normalType, DecodeBudget &budget)
        : where_(where), budget_(budget), sizeZ_(sizeZ),
          maxNormal_(normalType == uint8_t(VxlNormalType::TiberianSun) ? kTiberianSunNormalCount - 1
                                                                       : kRedAlert2NormalCount - 1),
          builder_(sizeX, sizeY, sizeZ) {}

    // Column (x, y) with the given span offsets, relative to the span data at `dataBegin`; the
    // column's bytes must lie before `bodyEnd`.
    void read(const ByteReader &in, int x, int y, int32_t start, int32_t end, uint64_t dataBegin, uint64_t bodyEnd) {
        if (start == kEmptyColumn && end == kEmptyColumn)
            return;
        const auto spans = [&] { return "spanStart " + std::to_string(start) + ", spanEnd " + std::to_string(end); };
        if (start == kEmptyColumn || end == kEmptyColumn)
            throw error(x, y, spans() + ": an empty column has both equal to -1");
        if (start < 0 || end < 0)
            throw error(x, y, spans() + ": negative span offset");
        if (end < start)
            throw error(x, y, spans() + ": spanEnd before spanStart");
        // spanEnd is the column's last byte (inclusive).
        const uint64_t first = dataBegin + uint64_t(start);
        const uint64_t limit = dataBegin + uint64_t(end) + 1;
        if (limit > bodyEnd)
            throw error(x, y,
                        spans() + ": column data at bytes [" + std::to_string(first) + ", " + std::to_string(limit) +
                            ") runs past the end of the body (byte " + std::to_string(bodyEnd) + ")");
        const size_t length = size_t(limit - first);
        const uint8_t *column = in.bytes(first, length, "column data");

        // Segments (skip, count, count x (colour, normal), count again) until the column is full;
        // a writer's trailing dummy segment (skip to the top, count 0) needs no special case.
        size_t pos = 0;
        int z = 0;
        while (z < sizeZ_) {
            const auto at = [&] { return " at byte offset " + std::to_string(first + pos); };
            if (length - pos < 2)
                throw error(x, y, "segment" + at() + " runs past spanEnd (" + spans() + ")");
            const int skip = column[pos];
            const int count = column[pos + 1];
            if (z + skip + count > sizeZ_)
                throw error(x, y,
                            "run of " + std::to_string(count) + " voxels after skipping " + std::to_string(skip) +
                                " from z = " + std::to_string(z) + at() + " runs past the column height " +
                                std::to_string(sizeZ_));
            if (length - pos < 3 + 2 * size_t(count))
                throw error(x, y,
                            "run of " + std::to_string(count) + " voxels" + at() + " runs past spanEnd (" + spans() +
                                ")");
            const uint8_t repeated = column[pos + 2 + 2 * size_t(count)];
            if (repeated != count)
                throw error(x, y,
                            "run" + at() + " has count " + std::to_string(count) + " but its repeated count is " +
                                std::to_string(repeated));
            if (uint64_t(count) > budget_.voxels)
                throw error(x, y,
                            "the sections hold more than " + std::to_string(budget_.fileSize / 2) +
                                " voxels, one per two bytes of the file: columns share their span data beyond what "
                                "the reader accepts");
            budget_.voxels -= uint64_t(count);
            z += skip;
            const uint8_t *voxel = column + pos + 2;
            for (int k = 0; k < count; ++k, ++z, voxel += 2) {
                uint8_t normal = voxel[1];
                if (normal > maxNormal_) {
                    normal = maxNormal_;  // the editor's rule: clamp to the table's last entry
                    ++clampedNormals_;
                }
                builder_.add(x, y, z, Voxel{voxel[0], normal});  // in order: columns ascend, z ascends
            }
            pos += 3 + 2 * size_t(count);
        }
    }

    size_t clampedNormals() const { return clampedNormals_; }
    VoxelVolume finish() { return builder_.finish(); }

private:
    FormatError error(int x, int y, const std::string &problem) const {
        return FormatError(where_ + ", column (" + std::to_string(x) + ", " + std::to_string(y) + "): " + problem);
    }

    const std::string &where_;
    DecodeBudget &budget_;
    int sizeZ_;
    uint8_t maxNormal_;
    VoxelVolumeBuilder builder_;
    size_t clampedNormals_ = 0;
};

// Reads a section's span arrays and columns from the body [bodyBegin, bodyEnd).
void readSectionVoxels(const ByteReader &in, uint64_t bodyBegin, uint64_t bodyEnd, const SpanLayout &layout,
                       const std::string &where, DecodeBudget &budget, VxlSection &section) {
    const uint64_t bodySize = bodyEnd - bodyBegin;
    const uint64_t columns = uint64_t(layout.sizeX) * uint64_t(layout.sizeY);
    const auto spanArray = [&](int32_t ofs, const char *name) {
        if (ofs < 0 || uint64_t(ofs) > bodySize || 4 * columns > bodySize - uint64_t(ofs))
            throw FormatError(where + ": " + name + " " + std::to_string(ofs) + " puts its " + std::to_string(columns) +
                              " offsets outside the body (bodySize " + std::to_string(bodySize) + ")");
        return in.bytes(bodyBegin + uint64_t(ofs), 4 * columns, name);
    };
    const uint8_t *spanStart = spanArray(layout.startOfs, "spanStartOfs");
    const uint8_t *spanEnd = spanArray(layout.endOfs, "spanEndOfs");
    if (columns > budget.columns)
        throw FormatError(where + ": the sections hold more than " + std::to_string(budget.fileSize / 8) +
                          " columns, one per eight bytes of the file: sections share their span arrays beyond what "
                          "the reader accepts");
    budget.columns -= columns;
    if (layout.dataOfs < 0 || uint64_t(layout.dataOfs) > bodySize)
        throw FormatError(where + ": spanDataOfs " + std::to_string(layout.dataOfs) +
                          " lies outside the body (bodySize " + std::to_string(bodySize) + ")");
    const uint64_t dataBegin = bodyBegin + uint64_t(layout.dataOfs);

    // Every column is read from its own spanStart: columns need not follow each other.
    ColumnReader reader(where, layout.sizeX, layout.sizeY, layout.sizeZ, section.normalType, budget);
    for (int y = 0; y < layout.sizeY; ++y)
        for (int x = 0; x < layout.sizeX; ++x) {
            const size_t i = 4 * (size_t(y) * size_t(layout.sizeX) + size_t(x));
            reader.read(in, x, y, int32_t(ByteReader::load32(spanStart + i)), int32_t(ByteReader::load32(spanEnd + i)),
                        dataBegin, bodyEnd);
        }
    section.clampedNormals = reader.clampedNormals();
    section.volume = reader.finish();
}

}  // namespace

VxlModel readVxl(const uint8_t *data, size_t size) {
    checkMagic(data, size);
    const ByteReader in(data, size);
    in.require(0, kHeaderBytes, "the 802-byte header");

    const uint32_t sectionCount = in.u32(20, "numSections");
    const uint32_t tailerCount = in.u32(24, "numTailers");
    const uint32_t bodySize = in.u32(28, "bodySize");
    if (sectionCount == 0)
        throw FormatError("the header declares no sections (numSections is 0)");
    if (tailerCount != sectionCount)
        throw FormatError("numTailers " + std::to_string(tailerCount) + " differs from numSections " +
                          std::to_string(sectionCount));
    // Bound the count by the file before allocating anything per section.
    const uint64_t perSection = kSectionHeaderBytes + kTailerBytes;
    if (kHeaderBytes + perSection * sectionCount > size)
        throw FormatError("numSections " + std::to_string(sectionCount) + " cannot fit in a file of " +
                          std::to_string(size) + " bytes (each section takes " + std::to_string(perSection) +
                          " bytes of header and tailer)");
    const uint64_t bodyBegin = kHeaderBytes + kSectionHeaderBytes * uint64_t(sectionCount);
    const uint64_t bodyEnd = bodyBegin + bodySize;
    const uint64_t tailersEnd = bodyEnd + kTailerBytes * uint64_t(sectionCount);
    // Bytes after the tailers are ignored, as the reference readers (which seek there) do.
    if (tailersEnd > size)
        throw FormatError("truncated file or bad bodySize: bodySize " + std::to_string(bodySize) +
                          " puts the section tailers at bytes [" + std::to_string(bodyEnd) + ", " +
                          std::to_string(tailersEnd) + ") but the file has " + std::to_string(size) + " bytes");

    VxlModel model;
    model.remapFirst = in.u8(32, "startPaletteRemap");
    model.remapLast = in.u8(33, "endPaletteRemap");
    const uint8_t *embedded = in.bytes(kPaletteOffset, 768, "embedded palette");
    for (size_t i = 0; i < 256; ++i)
        model.embeddedPalette.colours[i] = Rgb{embedded[3 * i], embedded[3 * i + 1], embedded[3 * i + 2]};

    model.sections.resize(sectionCount);
    DecodeBudget budget(size);
    for (size_t s = 0; s < sectionCount; ++s) {
        VxlSection &section = model.sections[s];
        section.name = in.text(kHeaderBytes + kSectionHeaderBytes * s, kNameBytes, "section name");
        const std::string where = sectionLabel(s, section.name);

        const uint64_t t = bodyEnd + kTailerBytes * s;
        SpanLayout layout;
        layout.startOfs = in.i32(t, "spanStartOfs");
        layout.endOfs = in.i32(t + 4, "spanEndOfs");
        layout.dataOfs = in.i32(t + 8, "spanDataOfs");
        section.scale = finiteFloat(in, t + 12, where, "scale");
        if (section.scale == 0.0f)
            section.scale = 1.0f;  // the editor's rule
        for (size_t k = 0; k < 12; ++k)
            section.transform[k] = finiteFloat(in, t + 16 + 4 * k, where, "transform entry");
        for (int a = 0; a < 3; ++a) {
            section.minBounds[a] = finiteFloat(in, t + 64 + 4 * uint64_t(a), where, "minBounds");
            section.maxBounds[a] = finiteFloat(in, t + 76 + 4 * uint64_t(a), where, "maxBounds");
        }
        layout.sizeX = in.u8(t + 88, "xSize");
        layout.sizeY = in.u8(t + 89, "ySize");
        layout.sizeZ = in.u8(t + 90, "zSize");
        section.normalType = in.u8(t + 91, "normalType");
        if (layout.sizeX == 0 || layout.sizeY == 0 || layout.sizeZ == 0)
            throw FormatError(where + ": zero size " + std::to_string(layout.sizeX) + "x" +
                              std::to_string(layout.sizeY) + "x" + std::to_string(layout.sizeZ) +
                              " (tailer at byte offset " + std::to_string(t) + ")");

        readSectionVoxels(in, bodyBegin, bodyEnd, layout, where, budget, section);
    }
    return model;
}

}  // namespace voxelfair
