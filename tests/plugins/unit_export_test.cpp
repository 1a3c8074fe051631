// Whole units and glTF export through the real meshlabserver: NAME.vxl brings NAMEtur.vxl and
// NAMEbarl.vxl (face counts add up, VOXELFAIR_UNIT=0 gives the body alone, a broken turret is a
// clear message and the body still imports); `-o model.glb` writes files Khronos' validator
// passes with 0 errors and 0 warnings, with one node per part, pivots, and animations.
#include "meshlab_run.h"
#include "ply_reader.h"

#include "fixtures/vox_writer.h"
#include "fixtures/vxl_fixtures.h"
#include "formats/file_bytes.h"
#include "formats/hva.h"
#include "formats/vxl.h"
#include "scene/unit_scene.h"
#include "fixtures/glb_reader.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

using namespace voxelfair;
namespace fs = std::filesystem;

namespace {

const std::string kModels = std::string(VOXELFAIR_MODELS_DIR) + "/vxl";
const std::string kVoxModels = std::string(VOXELFAIR_MODELS_DIR) + "/vox";

size_t importedFaces(const std::string &model, const std::map<std::string, std::string> &env,
                     std::string *log = nullptr) {
    const std::string dir = makeTempDir();
    const MeshlabRun run = runMeshlabServer({"-i", model, "-o", dir + "/out.ply", "-m", "fq", "sa"}, env);
    if (log)
        *log = run.output;
    const size_t faces = fs::exists(dir + "/out.ply") ? readAsciiPly(dir + "/out.ply").triangles.size() : 0;
    fs::remove_all(dir);
    return faces;
}

// Khronos' validator over the files: the summary lines; fails the test unless 0 errors, 0 warnings.
void expectValid(const std::vector<std::string> &glbs) {
    std::string command = "node '" + std::string(VOXELFAIR_SOURCE_DIR) + "/tools/gltf_validate.js'";
    for (const std::string &g : glbs)
        command += " '" + g + "'";
    command += " 2>&1";
    FILE *pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string output;
    char buffer[4096];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe))
        output.append(buffer, n);
    const int status = pclose(pipe);
    EXPECT_EQ(status, 0) << output;
    for (const std::string &g : glbs)
        EXPECT_NE(output.find(g + ": 0 errors, 0 warnings"), std::string::npos) << output;
}

tinygltf::Model loadGlb(const std::string &path) {
    fixtures::GlbRead r = fixtures::readGlbFile(path);
    EXPECT_TRUE(r.ok) << path << ": " << r.error;
    return std::move(r.model);
}

const tinygltf::Node *findNode(const tinygltf::Model &model, const std::string &name) {
    for (const tinygltf::Node &n : model.nodes)
        if (n.name == name)
            return &n;
    return nullptr;
}

void writeFile(const std::string &path, const std::vector<uint8_t> &bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
}

// A unit written from code: a body box, a turret box, a barrel rod, each with a one-frame .hva
// placing it at a random height (fixed seed).
std::string writeUnit(const std::string &dir, const std::string &stem, std::mt19937 &rng) {
    using namespace voxelfair::fixtures;
    std::uniform_int_distribution<int> side(3, 9);
    const auto box = [&](int x, int y, int z) { return volumeWhere(x, y, z, [](int, int, int) { return true; }); };
    const std::pair<std::string, VoxelVolume> parts[3] = {
        {"", box(side(rng) + 6, side(rng), side(rng))}, {"tur", box(side(rng), side(rng), 3)}, {"barl", box(8, 1, 1)}};
    for (const auto &[suffix, volume] : parts) {
        VxlSection section = makeSection("s" + suffix, volume);
        section.maxBounds = glm::vec3(volume.sizeX, volume.sizeY, volume.sizeZ);
        writeFile(dir + "/" + stem + suffix + ".vxl", writeVxl(makeModel({section})));
        HvaAnimation hva;
        hva.frameCount = 1;
        hva.sectionNames = {"s" + suffix};
        Matrix3x4 m = kIdentity3x4;
        m[11] = float(12 * (suffix.empty() ? 0 : 6 + int(rng() % 4)));  // z, in leptons (Det 1/12)
        hva.matrices = {m};
        writeFile(dir + "/" + stem + suffix + ".hva", writeHva(hva));
    }
    return dir + "/" + stem + ".vxl";
}

}  // namespace

TEST(Units, SharedTankImportsAsBodyTurretAndBarrel) {
    if (!fs::is_directory(kModels))
        GTEST_SKIP() << "the shared models are absent: " << kModels;
    std::string log;
    const size_t unit = importedFaces(kModels + "/3tnk.vxl", {}, &log);
    const size_t body = importedFaces(kModels + "/3tnk.vxl", {{"VOXELFAIR_UNIT", "0"}});
    const size_t turret = importedFaces(kModels + "/3tnktur.vxl", {});
    const size_t barrel = importedFaces(kModels + "/3tnkbarl.vxl", {});
    EXPECT_GT(body, 0u);
    EXPECT_GT(turret, 0u);
    EXPECT_GT(barrel, 0u);
    EXPECT_EQ(unit, body + turret + barrel);
    EXPECT_NE(log.find("unit of 3 files: 3tnk.vxl (+ .hva), 3tnktur.vxl (+ .hva), 3tnkbarl.vxl (+ .hva)"),
              std::string::npos)
        << log;
}

TEST(Units, GeneratedUnitsAddUpAndTheirGlbHasOneNodePerPart) {
    std::mt19937 rng(1212);
    for (int trial = 0; trial < 3; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const std::string dir = makeTempDir();
        const std::string body = writeUnit(dir, "unit" + std::to_string(trial), rng);
        const size_t whole = importedFaces(body, {});
        const size_t alone = importedFaces(body, {{"VOXELFAIR_UNIT", "0"}});
        const size_t turret = importedFaces(dir + "/unit" + std::to_string(trial) + "tur.vxl", {});
        const size_t barrel = importedFaces(dir + "/unit" + std::to_string(trial) + "barl.vxl", {});
        EXPECT_EQ(whole, alone + turret + barrel);

        // The .glb: body, turret and barrel nodes, the barrel under the turret, the turret offset
        // along the unit's front (+Z in glTF): 120 leptons * Det 1/12 = 10 voxels = 1 m.
        const std::string glb = dir + "/unit.glb";
        const MeshlabRun run = runMeshlabServer({"-i", body, "-o", glb}, {{"VOXELFAIR_TURRET_OFFSET", "120"}});
        ASSERT_TRUE(fs::exists(glb)) << run.output;
        expectValid({glb});
        const tinygltf::Model model = loadGlb(glb);
        const tinygltf::Node *b = findNode(model, "body"), *t = findNode(model, "turret"),
                             *r = findNode(model, "barrel");
        ASSERT_TRUE(b && t && r);
        ASSERT_EQ(t->translation.size(), 3u);
        EXPECT_NEAR(t->translation[2], 1.0, 1e-5);
        EXPECT_EQ(t->children.size(), 2u);  // its section and the barrel
        fs::remove_all(dir);
    }
}

TEST(Units, BrokenOrMissingTurretLeavesTheBody) {
    std::mt19937 rng(7);
    const std::string dir = makeTempDir();
    const std::string body = writeUnit(dir, "tank", rng);
    const size_t alone = importedFaces(body, {{"VOXELFAIR_UNIT", "0"}});
    const size_t barrel = importedFaces(dir + "/tankbarl.vxl", {});
    writeFile(dir + "/tanktur.vxl", {'V', 'o', 'x', 'e', 'l', 0, 1, 2});  // not a VXL
    std::string log;
    EXPECT_EQ(importedFaces(body, {}, &log), alone + barrel);
    EXPECT_NE(log.find(fs::canonical(dir + "/tanktur.vxl").string() + ": "), std::string::npos) << log;
    EXPECT_NE(log.find("the turret is left out, the rest of the unit imports"), std::string::npos) << log;
    fs::remove(dir + "/tanktur.vxl");
    fs::remove(dir + "/tanktur.hva");
    EXPECT_EQ(importedFaces(body, {}, &log), alone + barrel);
    EXPECT_NE(log.find("unit of 2 files"), std::string::npos) << log;
    fs::remove_all(dir);
}

TEST(GlbExport, EverySharedModelIsValidWithItsNodesAndAnimations) {
    if (!fs::is_directory(kModels))
        GTEST_SKIP() << "the shared models are absent: " << kModels;
    const std::string dir = makeTempDir();
    std::vector<std::string> glbs;
    for (const std::string &folder : {kModels, kVoxModels})
        for (const auto &entry : fs::directory_iterator(folder)) {
            const std::string ext = entry.path().extension().string();
            if (ext != ".vxl" && ext != ".vox")
                continue;
            const std::string glb = dir + "/" + entry.path().stem().string() + ".glb";
            const MeshlabRun run = runMeshlabServer({"-i", entry.path().string(), "-o", glb});
            if (run.output.find("there are no voxels to import") != std::string::npos)
                continue;  // art2tur
            EXPECT_TRUE(fs::exists(glb)) << run.output;
            if (fs::exists(glb))
                glbs.push_back(glb);
        }
    ASSERT_GT(glbs.size(), 15u);
    expectValid(glbs);
    // hmec's 17-frame .hva becomes an animation of its 13 sections (legs.hva has one frame: its
    // 18 sections are poses, exported as 18 nodes); robo's named shapes become named nodes.
    const tinygltf::Model hmec = loadGlb(dir + "/hmec.glb");
    ASSERT_EQ(hmec.animations.size(), 1u);
    EXPECT_EQ(hmec.accessors[size_t(hmec.animations[0].samplers[0].input)].count, 17u);
    EXPECT_EQ(hmec.animations[0].channels.size(), 3u * 13u);
    EXPECT_EQ(loadGlb(dir + "/legs.glb").nodes.size(), 19u);
    const tinygltf::Model robo = loadGlb(dir + "/robo.glb");
    EXPECT_NE(findNode(robo, "Head_Upper"), nullptr);
    EXPECT_EQ(robo.nodes.size(), 3u);
    fs::remove_all(dir);
}

TEST(GlbExport, KeyframedVoxScenesBecomeValidAnimations) {
    // MagicaVoxel transform keyframes, written from code (no shared .vox is animated): two named
    // shapes, one moving over 4 frames, one turning; the .glb animates both nodes.
    using namespace voxelfair::fixtures;
    std::vector<VoxDict> moves, turns;
    for (int f = 0; f < 4; ++f) {
        moves.push_back({{"_f", std::to_string(f)}, {"_t", std::to_string(3 * f) + " 0 " + std::to_string(f)}});
        turns.push_back({{"_f", std::to_string(f)}, {"_r", f % 2 ? "17" : "4"}, {"_t", "0 20 0"}});
    }
    std::vector<VoxVoxel> block;
    for (uint8_t x = 0; x < 4; ++x)
        for (uint8_t z = 0; z < 3; ++z)
            block.push_back({x, 0, z, uint8_t(1 + x)});
    const Bytes bytes = VoxWriter()
                            .model(4, 1, 3, block)
                            .transform(0, 1, {{}})
                            .group(1, {2, 4})
                            .transform(2, 3, moves, {{"_name", "mover"}})
                            .shape(3, 0)
                            .transform(4, 5, turns, {{"_name", "turner"}})
                            .shape(5, 0)
                            .bytes();
    const std::string dir = makeTempDir();
    writeFile(dir + "/keys.vox", bytes);
    const MeshlabRun run = runMeshlabServer({"-i", dir + "/keys.vox", "-o", dir + "/keys.glb"});
    ASSERT_TRUE(fs::exists(dir + "/keys.glb")) << run.output;
    expectValid({dir + "/keys.glb"});
    const tinygltf::Model model = loadGlb(dir + "/keys.glb");
    ASSERT_EQ(model.animations.size(), 1u);
    EXPECT_EQ(model.animations[0].channels.size(), 6u);  // 2 nodes x translation, rotation, scale
    EXPECT_EQ(model.accessors[size_t(model.animations[0].samplers[0].input)].count, 4u);
    EXPECT_NE(findNode(model, "mover"), nullptr);
    EXPECT_NE(findNode(model, "turner"), nullptr);
    fs::remove_all(dir);
}
