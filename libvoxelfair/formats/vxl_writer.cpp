// The VXL writer (writeVxl, formats/vxl.h): sections in the editor's contiguous layout, for the
// tests' fixtures and the bundled example.
#include "formats/vxl.h"

#include "formats/byte_writer.h"
#include "formats/format_error.h"
#include "formats/vxl_layout.h"

#include <limits>

namespace voxelfair {

namespace {

using namespace vxl;

void checkWritable(const VxlSection &section, size_t index) {
    const VoxelVolume &v = section.volume;
    const auto side = [](int n) { return n >= 1 && n <= kMaxSide; };
    if (!side(v.sizeX) || !side(v.sizeY) || !side(v.sizeZ))
        throw FormatError("cannot write VXL section " + std::to_string(index) + ": size " + std::to_string(v.sizeX) +
                          "x" + std::to_string(v.sizeY) + "x" + std::to_string(v.sizeZ) + " is outside 1..255");
    if (v.columnFirstRun.size() != size_t(v.sizeX) * size_t(v.sizeY) + 1)
        throw FormatError("cannot write VXL section " + std::to_string(index) + ": malformed volume (column index)");
}

// Appends one section body in the editor's contiguous layout (spanStart[], spanEnd[], data) and
// returns its three offsets relative to the body start.
std::array<int32_t, 3> writeSectionBody(const VoxelVolume &volume, ByteWriter &body) {
    const size_t columns = size_t(volume.sizeX) * size_t(volume.sizeY);
    const size_t startOfs = body.size();
    const size_t endOfs = startOfs + 4 * columns;
    const size_t dataOfs = endOfs + 4 * columns;
    body.bytes().resize(dataOfs);
    for (size_t c = 0; c < columns; ++c) {
        const uint32_t firstRun = volume.columnFirstRun[c];
        const uint32_t lastRun = volume.columnFirstRun[c + 1];
        if (firstRun == lastRun) {
            body.patchI32(startOfs + 4 * c, kEmptyColumn);
            body.patchI32(endOfs + 4 * c, kEmptyColumn);
            continue;
        }
        body.patchI32(startOfs + 4 * c, int32_t(body.size() - dataOfs));
        int z = 0;
        for (uint32_t r = firstRun; r < lastRun; ++r) {
            const VoxelRun &run = volume.runs[r];
            const int count = run.zEnd - run.zBegin;
            body.u8(uint8_t(run.zBegin - z));
            body.u8(uint8_t(count));
            for (int k = 0; k < count; ++k) {
                const Voxel &voxel = volume.voxels[run.firstVoxel + uint32_t(k)];
                body.u8(voxel.colour);
                body.u8(voxel.normal);
            }
            body.u8(uint8_t(count));
            z = run.zEnd;
        }
        // The editor's dummy segment: skip the empty top so that the column reaches zSize.
        if (z < volume.sizeZ) {
            body.u8(uint8_t(volume.sizeZ - z));
            body.u8(0);
            body.u8(0);
        }
        body.patchI32(endOfs + 4 * c, int32_t(body.size() - dataOfs - 1));  // last byte, inclusive
    }
    return {int32_t(startOfs), int32_t(endOfs), int32_t(dataOfs)};
}

}  // namespace

std::vector<uint8_t> writeVxl(const VxlModel &model) {
    if (model.sections.empty())
        throw FormatError("cannot write VXL: the model has no sections");
    for (size_t s = 0; s < model.sections.size(); ++s)
        checkWritable(model.sections[s], s);

    ByteWriter body;
    std::vector<std::array<int32_t, 3>> offsets;
    offsets.reserve(model.sections.size());
    for (const VxlSection &section : model.sections) {
        offsets.push_back(writeSectionBody(section.volume, body));
        if (body.size() > size_t(std::numeric_limits<int32_t>::max()))
            throw FormatError("cannot write VXL: the body exceeds the format's 2 GiB offsets");
    }

    const uint32_t sectionCount = uint32_t(model.sections.size());
    ByteWriter out;
    out.bytes().reserve(kHeaderBytes + (kSectionHeaderBytes + kTailerBytes) * sectionCount + body.size());
    out.text(kMagic, kNameBytes);
    out.u32(1);  // numPalettes
    out.u32(sectionCount);
    out.u32(sectionCount);  // numTailers
    out.u32(uint32_t(body.size()));
    out.u8(model.remapFirst);
    out.u8(model.remapLast);
    for (const Rgb &c : model.embeddedPalette.colours) {
        out.u8(c.r);
        out.u8(c.g);
        out.u8(c.b);
    }
    for (uint32_t s = 0; s < sectionCount; ++s) {
        out.text(model.sections[s].name, kNameBytes);  // at most 15 characters, as the editor writes
        out.u32(s);                                    // number
        out.u32(1);                                    // unknown1, as the editor writes
        out.u32(2);                                    // unknown2, as the editor writes
    }
    out.bytes().insert(out.bytes().end(), body.bytes().begin(), body.bytes().end());
    for (uint32_t s = 0; s < sectionCount; ++s) {
        const VxlSection &section = model.sections[s];
        for (int32_t ofs : offsets[s])
            out.i32(ofs);
        out.f32(section.scale);
        for (float v : section.transform)
            out.f32(v);
        for (int a = 0; a < 3; ++a)
            out.f32(section.minBounds[a]);
        for (int a = 0; a < 3; ++a)
            out.f32(section.maxBounds[a]);
        out.u8(uint8_t(section.volume.sizeX));
        out.u8(uint8_t(section.volume.sizeY));
        out.u8(uint8_t(section.volume.sizeZ));
        out.u8(section.normalType);
    }
    return std::move(out.bytes());
}

}  // namespace voxelfair
