// Writes the bundled example model: a small Red Alert 2-style tank (hull with tracks, turret,
// cylindrical cannon) as tank.vxl + tank.hva, authored here from code so that no third-party
// model ships with voxelfair.
//
// usage: make_example_tank OUTPUT_FOLDER
#include "formats/hva.h"
#include "formats/vxl.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

using namespace voxelfair;

namespace {

// Palette entries the tank uses (the file embeds this palette).
enum Colour : uint8_t {
    kHouse = 20,  // inside the house-colour range 16..31: recoloured by the importer's choice
    kOlive = 40,  // 40..43: olive drab, light to dark
    kTrack = 56,  // 56..58: track greys
    kBlack = 64,
    kHeadlight = 65,
};

Palette tankPalette() {
    Palette p;
    remapHouseColours(p, Rgb{255, 0, 0});
    const Rgb olive[4] = {{128, 138, 72}, {108, 118, 60}, {90, 98, 50}, {70, 76, 40}};
    for (int i = 0; i < 4; ++i)
        p.colours[kOlive + i] = olive[i];
    const Rgb greys[3] = {{92, 92, 88}, {66, 66, 62}, {44, 44, 42}};
    for (int i = 0; i < 3; ++i)
        p.colours[kTrack + i] = greys[i];
    p.colours[kBlack] = {16, 16, 16};
    p.colours[kHeadlight] = {250, 236, 150};
    return p;
}

using VoxelRule = std::function<int(int x, int y, int z)>;  // palette index, or -1 for empty

VxlSection makeSection(const char *name, int sx, int sy, int sz, glm::vec3 minBounds, const VoxelRule &rule) {
    VoxelVolumeBuilder builder(sx, sy, sz);
    for (int y = 0; y < sy; ++y)
        for (int x = 0; x < sx; ++x)
            for (int z = 0; z < sz; ++z) {
                const int colour = rule(x, y, z);
                if (colour >= 0)
                    builder.add(x, y, z, Voxel{uint8_t(colour), 0});
            }
    VxlSection s;
    s.name = name;
    s.volume = builder.finish();
    s.minBounds = minBounds;
    s.maxBounds = minBounds + glm::vec3(sx, sy, sz);
    s.normalType = uint8_t(VxlNormalType::RedAlert2);
    return s;
}

// Hull: 28 long (x), 16 wide (y), 8 high (z); tracks along both sides, sloped glacis at the front.
int hull(int x, int y, int z) {
    const bool track = y < 4 || y >= 12;
    if (track) {
        // Rounded track ends: cut the lower and upper corners at both ends.
        const int fromEnd = std::min(x, 27 - x);
        if (z > 4)
            return -1;
        if ((z == 0 || z == 4) && fromEnd < 2)
            return -1;
        return kTrack + ((x + z) % 3 == 0 ? 2 : (y == 0 || y == 15 ? 1 : 0));
    }
    // Upper hull between the tracks, with the front sloping down.
    const int top = x > 21 ? 7 - (x - 21) / 2 : 7;
    if (z < 1 || z > top)
        return -1;
    if (x == 27 && z == top && (y == 5 || y == 10))
        return kHeadlight;
    if (z == top && (y == 7 || y == 8))
        return kHouse;  // a house-colour stripe along the deck
    return kOlive + (z >= top ? 0 : z >= top - 2 ? 1 : 2);
}

// Turret: a rounded block 12 x 10 x 6 with a bevelled top.
int turret(int x, int y, int z) {
    const float cx = x + 0.5f - 6.0f, cy = y + 0.5f - 5.0f;
    const float r = std::sqrt(cx * cx * 0.55f + cy * cy);
    if (r > 5.2f - (z >= 4 ? (z - 3) * 0.9f : 0.0f))
        return -1;
    if (z == 5 && std::abs(cx) < 1.0f && std::abs(cy) < 1.0f)
        return kHouse;  // hatch
    return kOlive + (z >= 4 ? 0 : 1);
}

// Cannon: a cylinder of radius 2.4 along x (18 long), with a wider muzzle brake at the end.
int cannon(int x, int y, int z) {
    const float cy = y + 0.5f - 3.5f, cz = z + 0.5f - 3.5f;
    const float r = std::sqrt(cy * cy + cz * cz);
    const bool muzzle = x >= 15;
    if (r > (muzzle ? 3.4f : 2.4f))
        return -1;
    if (x == 17 && r < 1.3f)
        return kBlack;  // the bore
    return muzzle ? kTrack + 1 : kOlive + 2;
}

void writeFile(const std::string &path, const std::vector<uint8_t> &bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
    if (!out)
        throw std::runtime_error("cannot write " + path);
}

}  // namespace

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT_FOLDER\n", argv[0]);
        return 2;
    }
    try {
        VxlModel tank;
        tank.embeddedPalette = tankPalette();
        tank.sections.push_back(makeSection("Hull", 28, 16, 8, {-14, -8, 0}, hull));
        tank.sections.push_back(makeSection("Turret", 12, 10, 6, {-6, -5, 0}, turret));
        tank.sections.push_back(makeSection("Cannon", 18, 7, 7, {0, -3.5f, -3.5f}, cannon));

        // HVA translations are in leptons: 12 per voxel with the usual section scale 1/12.
        HvaAnimation hva;
        hva.frameCount = 1;
        hva.sectionNames = {"Hull", "Turret", "Cannon"};
        const glm::vec3 offsets[3] = {{0, 0, 0}, {-2, 0, 8}, {3, 0, 11}};
        for (const glm::vec3 &t : offsets)
            hva.matrices.push_back(Matrix3x4{1, 0, 0, t.x * 12, 0, 1, 0, t.y * 12, 0, 0, 1, t.z * 12});

        const std::string folder = argv[1];
        writeFile(folder + "/tank.vxl", writeVxl(tank));
        writeFile(folder + "/tank.hva", writeHva(hva));
        return 0;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "make_example_tank: %s\n", e.what());
        return 1;
    }
}
