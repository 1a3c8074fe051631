// The part descriptions exporters get: a VOX scene's instances as nodes at their model pivots,
// with one transform per frame when the scene's keyframes move them; a unit's files and sections
// as a node tree whose section pivots sit at the HVA frames.
#include "export/export_scene.h"
#include "fixtures/vox_writer.h"
#include "fixtures/vxl_fixtures.h"
#include "formats/vox.h"
#include "scene/unit_scene.h"
#include "scene/vox_export_nodes.h"
#include "scene/vox_scene.h"

#include <gtest/gtest.h>

#include <random>

using namespace voxelfair;
using namespace voxelfair::fixtures;

TEST(VoxExportNodes, KeyframedTransformsBecomeFramesAtTheModelPivot) {
    std::mt19937 rng(4);
    for (int trial = 0; trial < 10; ++trial) {
        const int frames = 2 + int(rng() % 5), sx = 1 + int(rng() % 9), sy = 1 + int(rng() % 9);
        std::vector<VoxDict> keys;
        std::vector<glm::vec3> moves;
        for (int f = 0; f < frames; ++f) {
            const glm::vec3 t(int(rng() % 41) - 20, int(rng() % 41) - 20, int(rng() % 41) - 20);
            moves.push_back(t);
            keys.push_back(
                {{"_f", std::to_string(f)},
                 {"_t", std::to_string(int(t.x)) + " " + std::to_string(int(t.y)) + " " + std::to_string(int(t.z))}});
        }
        const Bytes bytes = VoxWriter()
                                .model(sx, sy, 3, {{0, 0, 0, 1}})
                                .transform(0, 1, {{}})
                                .group(1, {2})
                                .transform(2, 3, keys, {{"_name", "mover"}})
                                .shape(3, 0)
                                .bytes();
        const VoxFile file = readVox(bytes.data(), bytes.size());
        const ExportScene scene = voxExportNodes(file, 0);
        EXPECT_EQ(scene.front, ModelFront::MinusY);
        ASSERT_EQ(scene.nodes.size(), 1u);
        EXPECT_EQ(scene.nodes[0].name, "mover");
        ASSERT_EQ(scene.nodes[0].frames.size(), size_t(frames));
        for (int f = 0; f < frames; ++f) {
            // The node's origin is the model's pivot floor(size / 2), which MagicaVoxel puts at _t.
            const VoxInstance instance = voxInstances(file, f)[0];
            const glm::vec3 pivot(instance.toModel * glm::vec4(sx / 2, sy / 2, 1, 1));
            EXPECT_EQ(glm::vec3(scene.nodes[0].frames[size_t(f)][3]), pivot);
            EXPECT_EQ(pivot, moves[size_t(f)]);
        }
    }
}

TEST(UnitScene, FilesBecomeATreeWithTheTurretOffsetAlongPlusX) {
    const auto box = [](int x, int y, int z) { return volumeWhere(x, y, z, [](int, int, int) { return true; }); };
    std::vector<UnitFile> files(3);
    const UnitRole roles[3] = {UnitRole::Body, UnitRole::Turret, UnitRole::Barrel};
    for (int i = 0; i < 3; ++i) {
        files[size_t(i)].role = roles[i];
        files[size_t(i)].name = unitRoleName(roles[i]);
        VxlSection s = makeSection("s", box(4, 3, 2));
        s.maxBounds = glm::vec3(4, 3, 2);
        files[size_t(i)].model = makeModel({s, s});
        HvaAnimation hva;
        hva.frameCount = 3;
        hva.sectionNames = {"a", "b"};
        for (int f = 0; f < 3; ++f)
            for (int k = 0; k < 2; ++k) {
                Matrix3x4 m = kIdentity3x4;
                m[3] = float(12 * (f + k));  // x translation in leptons
                hva.matrices.push_back(m);
            }
        files[size_t(i)].hva = hva;
    }
    UnitSceneOptions options;
    options.turretOffsetLeptons = 120.0f;  // 10 voxels at Det 1/12
    const UnitScene unit = unitScene(files, options);
    ASSERT_EQ(unit.nodes.nodes.size(), 9u);  // 3 files + 6 sections
    EXPECT_EQ(unit.scene.parts.size(), 6u);
    const ExportNode &turret = unit.nodes.nodes[3], &barrel = unit.nodes.nodes[6];
    EXPECT_EQ(turret.name, "turret");
    EXPECT_EQ(barrel.parent, 3);  // the barrel follows the turret
    EXPECT_EQ(glm::vec3(turret.world[3]), glm::vec3(10, 0, 0));
    for (size_t part = 0; part < 6; ++part) {
        const int node = unit.nodes.nodeOfPart(int(part));
        ASSERT_GE(node, 0);
        const ExportNode &n = unit.nodes.nodes[size_t(node)];
        ASSERT_EQ(n.frames.size(), 3u);
        const float offset = part >= 2 ? 10.0f : 0.0f;
        for (size_t f = 0; f < 3; ++f)
            EXPECT_FLOAT_EQ(n.frames[f][3].x, offset + float(f + part % 2));
        // The part's voxels are placed in the node's frame: toModel = world * (voxel -> section),
        // voxel (0,0,0) at the section's minBounds.
        const glm::vec3 minBounds = files[part / 2].model.sections[part % 2].minBounds;
        EXPECT_EQ(glm::vec3(unit.scene.parts[part].toModel[3]), glm::vec3(n.world * glm::vec4(minBounds, 1.0f)));
    }
}
