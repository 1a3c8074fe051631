// Writes small, valid seed inputs for each fuzz target with the test fixtures' writers, so that
// no model file is committed: fuzz_seeds <corpus root> fills <root>/fuzz_vxl, fuzz_hva, ...
#include "fixtures/tdcz_writer.h"
#include "fixtures/vox_writer.h"
#include "fixtures/vxl_fixtures.h"
#include "formats/hva.h"
#include "formats/palette.h"
#include "formats/vxl.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace voxelfair;
using namespace voxelfair::fixtures;
namespace fs = std::filesystem;

namespace {

void save(const fs::path &root, const char *target, const std::string &name, const std::vector<uint8_t> &bytes) {
    fs::create_directories(root / target);
    std::ofstream out(root / target / name, std::ios::binary);
    out.write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
}

void vxlSeeds(const fs::path &root) {
    const auto hollow = [](int x, int y, int z) { return x == 0 || y == 0 || z == 0 || x == 4 || y == 4 || z == 4; };
    save(root, "fuzz_vxl", "hollow_box.vxl", writeVxl(makeModel({makeSection("box", volumeWhere(5, 5, 5, hollow))})));
    save(root, "fuzz_vxl", "two_sections.vxl",
         writeVxl(makeModel(
             {makeSection("hull", volumeWhere(6, 4, 3, [](int x, int y, int z) { return (x + y + z) % 3 != 0; })),
              makeSection("turret", volumeWhere(2, 3, 4, [](int x, int, int z) { return x == 0 || z % 2 == 1; }),
                          VxlNormalType::TiberianSun)})));
    save(root, "fuzz_vxl", "one_voxel.vxl",
         writeVxl(makeModel({makeSection("dot", volumeWhere(1, 1, 1, [](int, int, int) { return true; }))})));
    save(root, "fuzz_vxl", "empty_section.vxl",
         writeVxl(makeModel({makeSection("none", volumeWhere(1, 9, 1, [](int, int, int) { return false; }))})));
}

void hvaSeeds(const fs::path &root) {
    for (int frames : {1, 3}) {
        HvaAnimation a;
        a.frameCount = frames;
        a.sectionNames = {"body", "turret"};
        for (int m = 0; m < 2 * frames; ++m) {
            Matrix3x4 matrix = kIdentity3x4;
            matrix[3] = float(m) * 0.5f;
            matrix[11] = -float(m);
            a.matrices.push_back(matrix);
        }
        save(root, "fuzz_hva", std::to_string(frames) + "_frames.hva", writeHva(a));
    }
}

void palSeeds(const fs::path &root) {
    std::vector<uint8_t> binary;
    for (const Rgb &c : defaultPalette().colours)
        binary.insert(binary.end(), {uint8_t(c.r >> 2), uint8_t(c.g >> 2), uint8_t(c.b >> 2)});
    save(root, "fuzz_pal", "binary.pal", binary);
    for (const char *ending : {"\r\n", "\n"}) {
        std::string text = std::string("JASC-PAL") + ending + "0100" + ending + "16" + ending;
        for (int i = 0; i < 16; ++i)
            text += std::to_string(i * 16) + " " + std::to_string(255 - i) + " 7" + ending;
        save(root, "fuzz_pal", std::string("jasc") + (ending[0] == '\r' ? "_crlf" : "_lf") + ".pal",
             std::vector<uint8_t>(text.begin(), text.end()));
    }
}

void voxSeeds(const fs::path &root) {
    save(root, "fuzz_vox", "one_model.vox", VoxWriter().model(2, 2, 2, {{0, 0, 0, 1}, {1, 1, 1, 2}}).bytes());
    // Every chunk kind the reader interprets: PACK, two models, a graph with rotation,
    // translation, keyframes, names, a hidden flag and a layer, and a palette.
    VoxWriter w;
    w.pack(2).model(3, 2, 4, {{0, 0, 0, 1}, {1, 1, 1, 2}, {2, 1, 3, 9}}).model(1, 2, 1, {{0, 1, 0, 3}});
    w.transform(0, 1, {{}}).group(1, {2, 4});
    w.transform(2, 3, {{{"_r", "105"}, {"_t", "1 -2 3"}, {"_f", "0"}}, {{"_r", "4"}, {"_f", "2"}}}, {{"_name", "a"}}, 1)
        .shape(3, {{0, {}}, {1, {{"_f", "1"}}}});
    w.transform(4, 5, {{{"_t", "0 0 1"}}}, {{"_hidden", "0"}}).shape(5, 1);
    w.layer(1, {{"_hidden", "0"}, {"_name", "layer"}}).palette([](int i) { return uint32_t(i) * 0x01010101u; });
    save(root, "fuzz_vox", "scene_graph.vox", w.bytes(200));
    save(root, "fuzz_vox", "pack_animation.vox",
         VoxWriter()
             .pack(3)
             .model(1, 1, 1, {{0, 0, 0, 1}})
             .model(2, 1, 1, {{1, 0, 0, 2}})
             .model(1, 1, 3, {{0, 0, 2, 3}})
             .bytes());
    save(root, "fuzz_vox", "sponge.vox", VoxWriter().model(9, 9, 9, mengerSponge(2)).bytes());
    // MATL materials of every type (formats/vox_materials.h), one with unreadable values.
    save(root, "fuzz_vox", "materials.vox",
         VoxWriter()
             .model(2, 1, 1, {{0, 0, 0, 1}, {1, 0, 0, 2}})
             .material(1, {{"_type", "_emit"}, {"_emit", "0.5"}, {"_flux", "2"}})
             .material(2, {{"_type", "_glass"}, {"_alpha", "0.7"}, {"_ior", "0.3"}, {"_rough", "0.2"}})
             .material(3, {{"_type", "_metal"}, {"_metal", "1"}, {"_rough", "x"}})
             .material(4, {{"_type", "_blend"}, {"_metal", "0.3"}, {"_trans", "0.5"}, {"_emit", "0.2"}})
             .material(256, {{"_type", "_media"}})
             .bytes(200));
    // Teardown's TDCZ: an unfinished zlib stream of the dense volume (teardown.vox seeds it too).
    Bytes dense(4 * 3 * 5, 0);
    for (size_t i = 0; i < dense.size(); i += 3)
        dense[i] = uint8_t(1 + i % 7);
    save(root, "fuzz_vox", "teardown_tdcz.vox",
         VoxWriter().size(4, 3, 5).chunk("TDCZ", tdczContent(4, 3, 5, dense)).model(1, 1, 1, {{0, 0, 0, 2}}).bytes());
}

// fuzz_extraction's format: sides - 1, placement, then voxel bits (repeated to fill the grid).
void extractionSeeds(const fs::path &root) {
    save(root, "fuzz_extraction", "box", {3, 3, 3, 0, 0xFF});
    save(root, "fuzz_extraction", "checkerboard_slab", {15, 15, 0, 0x3F, 0x55});
    save(root, "fuzz_extraction", "columns_touching_at_edges", {3, 3, 3, 0x40, 0x21, 0x84});
    // A 5^3 shell around a cavity, one byte per 8 voxels.
    std::vector<uint8_t> shell{4, 4, 4, 0xC0};
    std::vector<bool> bits;
    for (int z = 0; z < 5; ++z)
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 5; ++x)
                bits.push_back(!(x == 2 && y == 2 && z == 2));
    for (size_t i = 0; i < bits.size(); i += 8) {
        uint8_t byte = 0;
        for (size_t b = 0; b < 8 && i + b < bits.size(); ++b)
            byte |= uint8_t(bits[i + b]) << b;
        shell.push_back(byte);
    }
    save(root, "fuzz_extraction", "shell_with_cavity", shell);
    std::mt19937 rng(7);
    std::vector<uint8_t> noise{11, 9, 13, 0x12};
    for (int i = 0; i < 200; ++i)
        noise.push_back(uint8_t(rng()));
    save(root, "fuzz_extraction", "noise", noise);
}

}  // namespace

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <corpus root>\n", argv[0]);
        return 2;
    }
    const fs::path root = argv[1];
    vxlSeeds(root);
    hvaSeeds(root);
    palSeeds(root);
    voxSeeds(root);
    extractionSeeds(root);
    return 0;
}
