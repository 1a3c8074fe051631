#include "formats/hva.h"

#include "formats/byte_reader.h"
#include "formats/byte_writer.h"

#include <cmath>

namespace voxelfair {

namespace {

constexpr size_t kHeaderBytes = 24;  // name[16], numFrames, numSections
constexpr size_t kNameBytes = 16;
constexpr size_t kMatrixBytes = 48;

}  // namespace

HvaAnimation readHva(const uint8_t *data, size_t size) {
    const ByteReader in(data, size);
    in.require(0, kHeaderBytes, "the 24-byte HVA header");
    const uint32_t frames = in.u32(16, "numFrames");
    const uint32_t sections = in.u32(20, "numSections");
    if (frames == 0)
        throw FormatError("HVA declares no frames (numFrames is 0)");
    if (sections == 0)
        throw FormatError("HVA declares no sections (numSections is 0)");
    // The exact size is checked in steps so that no product can overflow.
    const uint64_t namesEnd = kHeaderBytes + kNameBytes * uint64_t(sections);
    const bool fits = namesEnd <= size && uint64_t(frames) <= (size - namesEnd) / (kMatrixBytes * sections);
    const uint64_t expected = fits ? namesEnd + kMatrixBytes * uint64_t(frames) * sections : 0;
    if (!fits || expected != size)
        throw FormatError("HVA size " + std::to_string(size) + " bytes does not match " + std::to_string(frames) +
                          " frames x " + std::to_string(sections) + " sections, which need exactly " +
                          "24 + 16 * sections + 48 * frames * sections bytes");

    HvaAnimation animation;
    animation.frameCount = int(frames);
    animation.sectionNames.reserve(sections);
    for (uint32_t s = 0; s < sections; ++s)
        animation.sectionNames.push_back(in.text(kHeaderBytes + kNameBytes * s, kNameBytes, "HVA section name"));
    const size_t matrixCount = size_t(frames) * sections;
    animation.matrices.resize(matrixCount);
    for (size_t m = 0; m < matrixCount; ++m) {
        for (size_t k = 0; k < 12; ++k) {
            const uint64_t offset = namesEnd + kMatrixBytes * m + 4 * k;
            const float v = in.f32(offset, "HVA matrix");
            if (!std::isfinite(v))
                throw FormatError("HVA frame " + std::to_string(m / sections) + ", section " +
                                  std::to_string(m % sections) + ": matrix entry " + std::to_string(k) +
                                  " is not a finite number (byte offset " + std::to_string(offset) + ")");
            animation.matrices[m][k] = v;
        }
    }
    return animation;
}

std::vector<uint8_t> writeHva(const HvaAnimation &animation) {
    const size_t sections = animation.sectionNames.size();
    if (animation.frameCount < 1 || sections == 0)
        throw FormatError("cannot write HVA: it needs at least one frame and one section");
    if (animation.matrices.size() != size_t(animation.frameCount) * sections)
        throw FormatError("cannot write HVA: " + std::to_string(animation.matrices.size()) + " matrices for " +
                          std::to_string(animation.frameCount) + " frames x " + std::to_string(sections) + " sections");
    ByteWriter out;
    out.bytes().reserve(kHeaderBytes + kNameBytes * sections + kMatrixBytes * animation.matrices.size());
    out.text("", kNameBytes);  // the file-name field the game ignores
    out.u32(uint32_t(animation.frameCount));
    out.u32(uint32_t(sections));
    for (const std::string &name : animation.sectionNames)
        out.text(name, kNameBytes);
    for (const Matrix3x4 &matrix : animation.matrices)
        for (float v : matrix)
            out.f32(v);
    return std::move(out.bytes());
}

}  // namespace voxelfair
