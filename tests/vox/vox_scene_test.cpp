// Flattening a .vox scene graph (pivots, rotations, translations, instancing, hidden nodes and
// layers, keyframes) and meshing the result, on files written from code.
#include "scene/vox_scene.h"
#include "fixtures/vox_writer.h"
#include "formats/format_error.h"
#include "formats/vox.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include <glm/geometric.hpp>

using namespace voxelfair;
using namespace voxelfair::fixtures;

namespace {

using Cell = std::array<int, 3>;

VoxFile read(const Bytes &bytes) { return readVox(bytes.data(), bytes.size()); }

// The world cell each voxel of the instance lands in: the cell holding its transformed centre.
std::set<Cell> worldCells(const VoxFile &file, const VoxInstance &instance) {
    std::set<Cell> cells;
    const VoxelVolume &m = file.models[size_t(instance.model)];
    for (int y = 0; y < m.sizeY; ++y)
        for (int x = 0; x < m.sizeX; ++x)
            for (int z = 0; z < m.sizeZ; ++z)
                if (m.solid(x, y, z)) {
                    const glm::vec4 c = instance.toModel * glm::vec4(x + 0.5f, y + 0.5f, z + 0.5f, 1.0f);
                    cells.insert({int(std::floor(c.x)), int(std::floor(c.y)), int(std::floor(c.z))});
                }
    return cells;
}

glm::vec3 apply(const glm::mat4 &m, glm::vec3 p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

// Every quad's normal (right-hand rule) points away from `inside`.
void expectQuadsFaceAwayFrom(const SceneSurface &surface, glm::vec3 inside) {
    for (size_t q = 0; q < surface.quadCount(); ++q) {
        const glm::vec3 p0 = surface.positions[surface.quads[4 * q]];
        const glm::vec3 p1 = surface.positions[surface.quads[4 * q + 1]];
        const glm::vec3 p2 = surface.positions[surface.quads[4 * q + 2]];
        EXPECT_GT(glm::dot(glm::cross(p1 - p0, p2 - p0), p0 - inside), 0.0f) << "quad " << q;
    }
}

void expectBounds(const SceneSurface &surface, glm::vec3 lo, glm::vec3 hi) {
    glm::vec3 mn(INFINITY), mx(-INFINITY);
    for (const glm::vec3 &p : surface.positions) {
        mn = glm::min(mn, p);
        mx = glm::max(mx, p);
    }
    EXPECT_EQ(mn, lo);
    EXPECT_EQ(mx, hi);
}

// root nTRN 0 -> nGRP 1 -> the given children.
VoxWriter &rootGroup(VoxWriter &w, const std::vector<int> &children) {
    return w.transform(0, 1, {{}}).group(1, children);
}

}  // namespace

TEST(VoxScene, OneVoxelMeshesAsSixQuadsAroundThePivot) {
    // Size 2: pivot (1, 1, 1), so voxel (0, 0, 0) becomes the cube [-1, 0]^3.
    const VoxFile file = read(VoxWriter().model(2, 2, 2, {{0, 0, 0, 3}}).bytes());
    const VoxelScene scene = voxScene(file);
    ASSERT_EQ(scene.parts.size(), 1u);
    EXPECT_EQ(scene.parts[0].name, "model 0");
    EXPECT_EQ(scene.parts[0].volume, &file.models[0]);
    const SceneSurface surface = extractSceneSurface(scene);
    EXPECT_EQ(surface.quadCount(), 6u);
    EXPECT_EQ(surface.positions.size(), 8u);
    expectBounds(surface, glm::vec3(-1), glm::vec3(0));
    expectQuadsFaceAwayFrom(surface, glm::vec3(-0.5f));
    for (const Rgb &c : surface.quadColours)
        EXPECT_EQ(c, file.palette.colours[3]);
}

TEST(VoxScene, OddSidesPutThePivotAtTheCornerBelowTheCentre) {
    // Size 3: pivot floor(3 / 2) = 1, so the centre voxel (1, 1, 1) becomes [0, 1]^3.
    const VoxFile file = read(VoxWriter().model(3, 3, 3, {{1, 1, 1, 1}}).bytes());
    expectBounds(extractSceneSurface(voxScene(file)), glm::vec3(0), glm::vec3(1));
}

TEST(VoxScene, RotatesAndTranslatesAnInstanceExactly) {
    // The spec's example rotation: rows (0 1 0), (0 0 -1), (-1 0 0); _r = 1 | 2 << 2 | 1 << 5 | 1 << 6 = 105.
    const int r = voxRotationByte(1, 2, false, true, true);
    ASSERT_EQ(r, 105);
    VoxWriter w;
    w.model(3, 2, 1, {{0, 0, 0, 1}, {2, 0, 0, 2}, {2, 1, 0, 3}});
    rootGroup(w, {2}).transform(2, 3, {{{"_r", std::to_string(r)}, {"_t", "10 -20 30"}}}).shape(3, 0);
    const VoxFile file = read(w.bytes());
    const std::vector<VoxInstance> instances = voxInstances(file, 0);
    ASSERT_EQ(instances.size(), 1u);
    const glm::mat4 &m = instances[0].toModel;

    // Pivot (1, 1, 0); voxel (2, 0, 0) is the cube q in [1, 2] x [-1, 0] x [0, 1]; world = R q + t.
    EXPECT_EQ(apply(m, {2, 0, 0}), glm::vec3(10 + -1, -20 - 0, 30 - 1));
    EXPECT_EQ(apply(m, {3, 1, 1}), glm::vec3(10 + 0, -20 - 1, 30 - 2));
    // Voxel (0,0,0): q [-1,0]x[-1,0]x[0,1] -> cell (9, -21, 30); (2,0,0) -> (9, -21, 28); (2,1,0) -> (10, -21, 28).
    EXPECT_EQ(worldCells(file, instances[0]), (std::set<Cell>{{9, -21, 30}, {9, -21, 28}, {10, -21, 28}}));

    const SceneSurface surface = extractSceneSurface(voxScene(file));
    expectBounds(surface, {9, -21, 28}, {11, -20, 31});
}

TEST(VoxScene, MirroringRotationKeepsQuadsOutward) {
    // _r = 20: row 0 picks column 0 negated -> x mirrored.
    VoxWriter w;
    w.model(1, 1, 1, {{0, 0, 0, 1}});
    rootGroup(w, {2}).transform(2, 3, {{{"_r", "20"}, {"_t", "5 0 0"}}}).shape(3, 0);
    const VoxFile file = read(w.bytes());
    const SceneSurface surface = extractSceneSurface(voxScene(file));
    ASSERT_EQ(surface.quadCount(), 6u);
    expectBounds(surface, {4, 0, 0}, {5, 1, 1});
    expectQuadsFaceAwayFrom(surface, {4.5f, 0.5f, 0.5f});
}

TEST(VoxScene, ComposesTransformsFromTheRoot) {
    // Outer: a quarter turn about z (rows (0 -1 0), (1 0 0), (0 0 1): _r = 1 | 0 << 2 | 1 << 4 = 17)
    // and _t (100, 0, 0); inner: _t (1, 0, 0). World = R (t_inner + q) + t_outer.
    VoxWriter w;
    w.model(1, 1, 1, {{0, 0, 0, 1}});
    w.transform(0, 1, {{{"_r", "17"}, {"_t", "100 0 0"}}})
        .group(1, {2})
        .transform(2, 3, {{{"_t", "1 0 0"}}})
        .shape(3, 0);
    const VoxFile file = read(w.bytes());
    const std::vector<VoxInstance> instances = voxInstances(file, 0);
    ASSERT_EQ(instances.size(), 1u);
    // q in [0,1]^3 -> inner [1,2]x[0,1]x[0,1] -> rotated x' = -y in [-1,0], y' = x in [1,2] -> + (100,0,0).
    EXPECT_EQ(worldCells(file, instances[0]), (std::set<Cell>{{99, 1, 0}}));
}

TEST(VoxScene, InstancesOneModelSeveralTimes) {
    VoxWriter w;
    w.model(1, 1, 1, {{0, 0, 0, 1}}).model(1, 1, 1, {{0, 0, 0, 2}});
    rootGroup(w, {2, 4, 6, 8})
        .transform(2, 3, {{{"_t", "10 0 0"}}})
        .shape(3, 0)
        .transform(4, 5, {{{"_t", "20 0 0"}}})
        .shape(5, 0)
        .transform(6, 5, {{{"_t", "30 0 0"}}})  // shares shape node 5 (vengi writes such files)
        .transform(8, 9, {{}})
        .shape(9, 1);
    const VoxFile file = read(w.bytes());
    const VoxelScene scene = voxScene(file);
    ASSERT_EQ(scene.parts.size(), 4u);
    EXPECT_EQ(scene.parts[0].volume, &file.models[0]);
    EXPECT_EQ(scene.parts[1].volume, &file.models[0]);
    EXPECT_EQ(scene.parts[2].volume, &file.models[0]);
    EXPECT_EQ(scene.parts[3].volume, &file.models[1]);
    for (size_t i = 0; i < 4; ++i)
        EXPECT_EQ(scene.parts[i].part, int(i));
    EXPECT_EQ(apply(scene.parts[0].toModel, {0, 0, 0}), glm::vec3(10, 0, 0));
    EXPECT_EQ(apply(scene.parts[1].toModel, {0, 0, 0}), glm::vec3(20, 0, 0));
    EXPECT_EQ(apply(scene.parts[2].toModel, {0, 0, 0}), glm::vec3(30, 0, 0));
    const SceneSurface surface = extractSceneSurface(scene);
    EXPECT_EQ(surface.quadCount(), 24u);
    EXPECT_EQ(surface.partQuadCounts, (std::vector<size_t>{6, 6, 6, 6}));
}

TEST(VoxScene, LeavesOutHiddenNodesAndHiddenLayers) {
    VoxWriter w;
    w.model(1, 1, 1, {{0, 0, 0, 1}});
    rootGroup(w, {2, 4, 8, 10, 12, 14})
        .transform(2, 3, {{}}, {{"_hidden", "1"}})  // hidden transform
        .shape(3, 0)
        .transform(4, 5, {{}})
        .group(5, {6}, {{"_hidden", "1"}})  // hidden group
        .transform(6, 7, {{}})
        .shape(7, 0)
        .transform(8, 9, {{}}, {}, 1)  // in hidden layer 1
        .shape(9, 0)
        .transform(10, 11, {{}})
        .shape(11, 0, {{"_hidden", "1"}})  // hidden shape
        .transform(12, 13, {{}}, {{"_name", "shown"}}, 2)
        .shape(13, 0)
        .transform(14, 15, {{}}, {}, 1)  // a group in hidden layer 1 hides what it holds
        .group(15, {16})
        .transform(16, 17, {{}}, {}, 2)
        .shape(17, 0)
        .layer(1, {{"_hidden", "1"}})
        .layer(2, {{"_hidden", "0"}});
    const std::vector<VoxInstance> instances = voxInstances(read(w.bytes()), 0);
    ASSERT_EQ(instances.size(), 1u);
    EXPECT_EQ(instances[0].name, "shown");
    EXPECT_EQ(instances[0].layer, 2);
}

TEST(VoxScene, NamesComeFromTheNearestNamedTransform) {
    VoxWriter w;
    w.model(1, 1, 1, {{0, 0, 0, 1}}).model(1, 1, 1, {{0, 0, 0, 1}});
    rootGroup(w, {2, 6, 8})
        .transform(2, 3, {{}}, {{"_name", "outer"}})
        .group(3, {4})
        .transform(4, 5, {{}})
        .shape(5, 0)
        .transform(6, 7, {{}}, {{"_name", "inner"}})
        .shape(7, 0)
        .transform(8, 9, {{}})
        .shape(9, 1);
    const VoxFile file = read(w.bytes());
    const VoxelScene scene = voxScene(file);
    ASSERT_EQ(scene.parts.size(), 3u);
    EXPECT_EQ(scene.parts[0].name, "outer");
    EXPECT_EQ(scene.parts[1].name, "inner");
    EXPECT_EQ(scene.parts[2].name, "model 1");
}

TEST(VoxScene, PicksTheKeyframeOfTheRequestedFrame) {
    VoxWriter w;
    w.model(1, 1, 1, {{0, 0, 0, 1}}).model(2, 1, 1, {{0, 0, 0, 1}});
    rootGroup(w, {2, 4})
        // Keyframes listed out of order: _f 5 then _f 0.
        .transform(2, 3, {{{"_f", "5"}, {"_t", "10 0 0"}}, {{"_f", "0"}, {"_t", "0 0 0"}}})
        .shape(3, {{0, {}}, {1, {{"_f", "3"}}}})
        // First keyframe at _f 2: it also holds before.
        .transform(4, 5, {{{"_f", "2"}, {"_t", "0 7 0"}}, {{"_f", "4"}, {"_t", "0 8 0"}}})
        .shape(5, 0);
    const VoxFile file = read(w.bytes(200));
    ASSERT_EQ(file.frameCount, 6);
    const auto at = [&](int frame) { return voxInstances(file, frame); };
    EXPECT_EQ(at(0)[0].model, 0);
    EXPECT_EQ(apply(at(0)[0].toModel, {0, 0, 0}), glm::vec3(0, 0, 0));
    EXPECT_EQ(at(2)[0].model, 0);
    EXPECT_EQ(at(3)[0].model, 1);  // model 1 has size 2: pivot 1
    EXPECT_EQ(apply(at(3)[0].toModel, {1, 0, 0}), glm::vec3(0, 0, 0));
    EXPECT_EQ(apply(at(4)[0].toModel, {1, 0, 0}), glm::vec3(0, 0, 0));
    EXPECT_EQ(apply(at(5)[0].toModel, {1, 0, 0}), glm::vec3(10, 0, 0));
    EXPECT_EQ(apply(at(0)[1].toModel, {0, 0, 0}), glm::vec3(0, 7, 0));
    EXPECT_EQ(apply(at(3)[1].toModel, {0, 0, 0}), glm::vec3(0, 7, 0));
    EXPECT_EQ(apply(at(5)[1].toModel, {0, 0, 0}), glm::vec3(0, 8, 0));
    EXPECT_EQ(voxScene(file, {5}).parts[0].volume, &file.models[1]);
    EXPECT_THROW(voxInstances(file, 6), FormatError);
    EXPECT_THROW(voxScene(file, {-1}), FormatError);
}

TEST(VoxScene, WithoutSceneGraphPlacesEachModelAtItsPivot) {
    const VoxFile file = read(VoxWriter().model(3, 3, 3, {{0, 0, 0, 1}}).model(4, 2, 1, {{0, 0, 0, 1}}).bytes());
    const std::vector<VoxInstance> instances = voxInstances(file, 0);
    ASSERT_EQ(instances.size(), 2u);
    EXPECT_EQ(instances[0].model, 0);
    EXPECT_EQ(instances[1].model, 1);
    EXPECT_EQ(apply(instances[0].toModel, {1, 1, 1}), glm::vec3(0));
    EXPECT_EQ(apply(instances[1].toModel, {2, 1, 0}), glm::vec3(0));
    EXPECT_EQ(instances[1].toModel[0], glm::vec4(1, 0, 0, 0));  // unrotated
    EXPECT_EQ(instances[0].layer, -1);
    EXPECT_TRUE(instances[0].name.empty());
    EXPECT_THROW(voxInstances(file, 1), FormatError);
}

TEST(VoxScene, PackAnimationShowsOneModelPerFrame) {
    const VoxFile file = read(
        VoxWriter().pack(3).model(1, 1, 1, {{0, 0, 0, 1}}).model(1, 1, 1, {{0, 0, 0, 2}}).model(1, 1, 1, {}).bytes());
    ASSERT_EQ(file.frameCount, 3);
    for (int f = 0; f < 3; ++f) {
        const std::vector<VoxInstance> instances = voxInstances(file, f);
        ASSERT_EQ(instances.size(), 1u);
        EXPECT_EQ(instances[0].model, f);
    }
}

TEST(VoxScene, UsesTheFilePalette) {
    const VoxFile file = read(
        VoxWriter().model(1, 1, 1, {{0, 0, 0, 2}}).palette([](int i) { return i == 1 ? 0xff030201u : 0u; }).bytes());
    const VoxelScene scene = voxScene(file);
    EXPECT_EQ(scene.palette.colours[2], (Rgb{1, 2, 3}));
    const SceneSurface surface = extractSceneSurface(scene);
    ASSERT_EQ(surface.quadCount(), 6u);
    EXPECT_EQ(surface.quadColours[0], (Rgb{1, 2, 3}));
    EXPECT_EQ(surface.quadVoxels[0].colour, 2);
}
