// Every reader on empty input and on the other formats' files (a misnamed file reaches the wrong
// reader): a FormatError saying the file is not of its format, never a crash.
#include "formats/format_error.h"
#include "formats/hva.h"
#include "formats/palette.h"
#include "formats/vox.h"
#include "formats/vxl.h"
#include "hostile_input.h"

#include <cstring>
#include <string>

using namespace voxelfair;
using namespace voxelfair::test;

namespace {

struct NamedReader {
    const char *name;
    Reader read;
    const char *wrongFormat;  // what its message says for another format's file
};

const NamedReader kReaders[] = {
    {"vxl", [](const uint8_t *d, size_t n) { readVxl(d, n); }, "not a Westwood VXL"},
    {"hva", [](const uint8_t *d, size_t n) { readHva(d, n); }, "does not match"},
    {"pal", [](const uint8_t *d, size_t n) { readPal(d, n); }, "not a palette"},
    {"vox", [](const uint8_t *d, size_t n) { readVox(d, n); }, "not a MagicaVoxel file"},
};

// Nothing here is large: any input of these tests fits in this.
constexpr HeapBound kSmallHeap{8, 64 << 10};

}  // namespace

TEST(HostileInput, EmptyInputIsAFormatErrorForEveryReader) {
    for (const NamedReader &r : kReaders) {
        for (const uint8_t *data : {static_cast<const uint8_t *>(nullptr), reinterpret_cast<const uint8_t *>("")}) {
            try {
                r.read(data, 0);
                ADD_FAILURE() << r.name << " accepted an empty file";
            } catch (const FormatError &e) {
                EXPECT_GT(std::strlen(e.what()), 10u) << r.name;
            }
        }
    }
}

TEST(HostileInput, EveryReaderRejectsTheOtherFormats) {
    const char *files[] = {"vxl/jeep.vxl", "vxl/jeep.hva", "pal/ra2_unittem.pal", "vox/robo.vox"};
    size_t tried = 0;
    for (size_t f = 0; f < 4; ++f) {
        const Bytes bytes = loadModel(files[f]);
        if (bytes.empty())
            continue;
        for (size_t r = 0; r < 4; ++r) {
            if (r == f)
                continue;
            const Attempt a = attempt(kReaders[r].read, bytes);
            EXPECT_TRUE(survived(a, kSmallHeap, bytes.size())) << kReaders[r].name << " on " << files[f];
            EXPECT_TRUE(rejectedWith(a, {kReaders[r].wrongFormat})) << kReaders[r].name << " on " << files[f];
            ++tried;
        }
    }
    if (tried == 0)
        GTEST_SKIP() << "shared models folder " << modelsDir().string() << " is absent";
}

TEST(HostileInput, TheMagicFollowedByConstantBytes) {
    // The magic, then all 0x00 or all 0xFF: every count, size and offset at its extreme.
    const std::pair<size_t, std::string> magics[] = {{0, "Voxel Animation"}, {3, "VOX \x96"}};
    for (const auto &[reader, magic] : magics) {
        for (uint8_t fill : {uint8_t(0x00), uint8_t(0xFF)}) {
            for (size_t size : {magic.size(), size_t(20), size_t(802), size_t(922), size_t(4096)}) {
                Bytes b(size, fill);
                std::memcpy(b.data(), magic.data(), magic.size());
                const Attempt a = attempt(kReaders[reader].read, b);
                EXPECT_TRUE(survived(a, kSmallHeap, b.size())) << kReaders[reader].name << ", " << size << " bytes";
                EXPECT_FALSE(a.accepted) << kReaders[reader].name << ", " << size << " bytes";
            }
        }
    }
}
