// The .glb writer, read back with tinygltf's loader: over a generated family of node trees
// (random depths, rigid transforms, pivots and fronts; fixed seeds), every vertex lands where the
// model put it, turned to glTF's axes (+Y up, front +Z) and scaled; a node gets exactly its own
// faces; the material, sampler and embedded PNG are as the options say; animations sample every
// frame.
#include "export/glb_writer.h"
#include "fixtures/glb_reader.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

using namespace voxelfair;

namespace {

tinygltf::Model load(const std::vector<uint8_t> &glb) {
    fixtures::GlbRead r = fixtures::readGlb(glb);
    EXPECT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(r.warning.empty()) << r.warning;
    return std::move(r.model);
}

glm::mat4 localMatrix(const tinygltf::Node &n) {
    glm::mat4 m(1.0f);
    if (!n.translation.empty())
        m = glm::translate(m, glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
    if (!n.rotation.empty())
        m *= glm::mat4_cast(
            glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2])));
    if (!n.scale.empty())
        m = glm::scale(m, glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
    return m;
}

template <class T>
std::vector<T> read(const tinygltf::Model &model, int accessorIndex) {
    const tinygltf::Accessor &a = model.accessors[size_t(accessorIndex)];
    const tinygltf::BufferView &v = model.bufferViews[size_t(a.bufferView)];
    std::vector<T> out(a.count);
    std::memcpy(out.data(), model.buffers[size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset,
                a.count * sizeof(T));
    return out;
}

glm::mat4 randomRigid(std::mt19937 &rng, float reach) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const glm::vec3 axis = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0, 0, 1e-3f));
    return glm::rotate(glm::translate(glm::mat4(1.0f), reach * glm::vec3(u(rng), u(rng), u(rng))), 3.0f * u(rng), axis);
}

// A random scene: nodes in a tree, each with a few triangles of its own around its pivot.
struct Generated {
    GlbMesh mesh;
    ExportScene scene;
};

Generated generate(std::mt19937 &rng, size_t frames) {
    Generated g;
    std::uniform_int_distribution<int> nodeCount(1, 6);
    const int nodes = nodeCount(rng);
    g.scene.front = rng() % 2 ? ModelFront::PlusX : ModelFront::MinusY;
    for (int i = 0; i < nodes; ++i) {
        ExportNode node;
        node.name = "node" + std::to_string(i);
        node.parent = i == 0 ? -1 : int(rng() % unsigned(i + 1)) - 1;
        node.world = randomRigid(rng, 20.0f);
        for (size_t f = 0; f < frames; ++f)
            node.frames.push_back(randomRigid(rng, 20.0f));
        g.scene.nodes.push_back(node);
        std::uniform_real_distribution<float> u(-10.0f, 10.0f);
        for (int t = 0; t < 3; ++t) {
            const uint32_t first = uint32_t(g.mesh.positions.size());
            for (int c = 0; c < 3; ++c) {
                g.mesh.positions.push_back(glm::vec3(u(rng), u(rng), u(rng)));
                g.mesh.normals.push_back(glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0, 0, 0.01f)));
                g.mesh.triangles.push_back(first + uint32_t(c));
                g.mesh.cornerUvs.push_back(glm::vec2(float(rng() % 64) / 64.0f, float(rng() % 64) / 64.0f));
            }
            g.mesh.triangleNodes.push_back(i);
        }
    }
    return g;
}

}  // namespace

TEST(GlbWriter, GeneratedTreesPutEveryVertexWhereTheModelHadIt) {
    std::mt19937 rng(2012);
    for (int trial = 0; trial < 30; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const Generated g = generate(rng, 0);
        GlbOptions options;
        options.metresPerVoxel = 0.05f + float(rng() % 10) / 20.0f;
        const tinygltf::Model model = load(writeGlb(g.mesh, g.scene, nullptr, options));
        ASSERT_EQ(model.nodes.size(), g.scene.nodes.size());
        const glm::mat3 axes = gltfAxes(g.scene.front);
        std::vector<glm::mat4> world(model.nodes.size());
        for (size_t i = 0; i < model.nodes.size(); ++i) {  // parents come first
            const int parent = g.scene.nodes[i].parent;
            world[i] = (parent < 0 ? glm::mat4(1.0f) : world[size_t(parent)]) * localMatrix(model.nodes[i]);
            EXPECT_EQ(model.nodes[i].name, g.scene.nodes[i].name);
            // The pivot: the node's origin is the model's pivot, turned and scaled.
            const glm::vec3 pivot = options.metresPerVoxel * (axes * glm::vec3(g.scene.nodes[i].world[3]));
            EXPECT_LT(glm::length(glm::vec3(world[i][3]) - pivot), 1e-3f);
        }
        for (size_t i = 0; i < model.nodes.size(); ++i) {
            ASSERT_GE(model.nodes[i].mesh, 0);
            const tinygltf::Primitive &p = model.meshes[size_t(model.nodes[i].mesh)].primitives[0];
            const std::vector<glm::vec3> positions = read<glm::vec3>(model, p.attributes.at("POSITION"));
            const std::vector<glm::vec3> normals = read<glm::vec3>(model, p.attributes.at("NORMAL"));
            const std::vector<glm::vec2> uvs = read<glm::vec2>(model, p.attributes.at("TEXCOORD_0"));
            const std::vector<uint32_t> indices = read<uint32_t>(model, p.indices);
            ASSERT_EQ(indices.size(), 9u);  // its own three triangles
            for (size_t k = 0; k < 9; ++k) {
                const uint32_t source = g.mesh.triangles[9 * i + k];
                const glm::vec3 expected = options.metresPerVoxel * (axes * g.mesh.positions[source]);
                const glm::vec3 got(world[i] * glm::vec4(positions[indices[k]], 1.0f));
                EXPECT_LT(glm::length(got - expected), 1e-3f);
                const glm::vec3 n = glm::normalize(glm::mat3(world[i]) * normals[indices[k]]);
                EXPECT_GT(glm::dot(n, axes * g.mesh.normals[source]), 0.9999f);
                EXPECT_NEAR(glm::length(normals[indices[k]]), 1.0f, 1e-5f);
                EXPECT_EQ(uvs[indices[k]],
                          glm::vec2(g.mesh.cornerUvs[9 * i + k].x, 1.0f - g.mesh.cornerUvs[9 * i + k].y));
            }
        }
    }
}

TEST(GlbWriter, AxesAreYUpAndFrontTowardsPlusZ) {
    EXPECT_EQ(gltfAxes(ModelFront::PlusX) * glm::vec3(0, 0, 1), glm::vec3(0, 1, 0));
    EXPECT_EQ(gltfAxes(ModelFront::PlusX) * glm::vec3(1, 0, 0), glm::vec3(0, 0, 1));
    EXPECT_EQ(gltfAxes(ModelFront::MinusY) * glm::vec3(0, 0, 1), glm::vec3(0, 1, 0));
    EXPECT_EQ(gltfAxes(ModelFront::MinusY) * glm::vec3(0, -1, 0), glm::vec3(0, 0, 1));
    for (ModelFront front : {ModelFront::PlusX, ModelFront::MinusY})
        EXPECT_NEAR(glm::determinant(gltfAxes(front)), 1.0f, 1e-6f);  // a rotation: right-handed stays so
}

TEST(GlbWriter, MaterialSamplerAndTextureFollowTheOptions) {
    std::mt19937 rng(5);
    const Generated g = generate(rng, 0);
    GlbTexture texture{{0x89, 'P', 'N', 'G', 1, 2, 3, 4, 5}, "atlas"};
    for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Linear}) {
        GlbOptions options;
        options.textureFilter = filter;
        const tinygltf::Model model = load(writeGlb(g.mesh, g.scene, &texture, options));
        ASSERT_EQ(model.materials.size(), 1u);
        const tinygltf::PbrMetallicRoughness &pbr = model.materials[0].pbrMetallicRoughness;
        EXPECT_EQ(pbr.metallicFactor, 0.0);
        EXPECT_NEAR(pbr.roughnessFactor, 0.9, 1e-6);
        EXPECT_EQ(pbr.baseColorTexture.index, 0);
        ASSERT_EQ(model.samplers.size(), 1u);
        EXPECT_EQ(model.samplers[0].magFilter, filter == TextureFilter::Nearest ? 9728 : 9729);
        EXPECT_EQ(model.samplers[0].minFilter, filter == TextureFilter::Nearest ? 9986 : 9987);
        ASSERT_EQ(model.images.size(), 1u);
        EXPECT_EQ(model.images[0].mimeType, "image/png");
        const tinygltf::BufferView &view = model.bufferViews[size_t(model.images[0].bufferView)];
        EXPECT_EQ(std::vector<uint8_t>(model.buffers[0].data.begin() + long(view.byteOffset),
                                       model.buffers[0].data.begin() + long(view.byteOffset + view.byteLength)),
                  texture.png);
    }
}

// The maps in the base colour's layout: the house colour mask named by the material's extras, the
// PBR maps with their extensions (listed in extensionsUsed), all on the base colour's sampler.
TEST(GlbWriter, HouseMaskAndMaterialMapsAreReferencedFromTheMaterial) {
    std::mt19937 rng(7);
    const Generated g = generate(rng, 0);
    GlbTexture texture{{0x89, 'P', 'N', 'G', 1}, "atlas"};
    GlbOptions options;
    options.houseMask = {{0x89, 'P', 'N', 'G', 2}, "house"};
    options.metallicRoughness = {{0x89, 'P', 'N', 'G', 3}, "metal"};
    options.emissive = {{0x89, 'P', 'N', 'G', 4}, "emissive"};
    options.emissiveStrength = 2.5f;
    options.transmission = {{0x89, 'P', 'N', 'G', 5}, "transmission"};
    options.ior = 1.3f;
    const tinygltf::Model model = load(writeGlb(g.mesh, g.scene, &texture, options));
    ASSERT_EQ(model.materials.size(), 1u);
    const tinygltf::Material &m = model.materials[0];
    const auto bytesOf = [&](int textureIndex) {
        const tinygltf::Texture &t = model.textures[size_t(textureIndex)];
        EXPECT_EQ(t.sampler, 0);
        const tinygltf::BufferView &view = model.bufferViews[size_t(model.images[size_t(t.source)].bufferView)];
        return std::vector<uint8_t>(model.buffers[0].data.begin() + long(view.byteOffset),
                                    model.buffers[0].data.begin() + long(view.byteOffset + view.byteLength));
    };
    ASSERT_TRUE(m.extras.Has("voxelfair_house_colour_mask"));
    EXPECT_EQ(bytesOf(m.extras.Get("voxelfair_house_colour_mask").Get("index").GetNumberAsInt()),
              options.houseMask.png);
    EXPECT_EQ(bytesOf(m.pbrMetallicRoughness.metallicRoughnessTexture.index), options.metallicRoughness.png);
    EXPECT_EQ(m.pbrMetallicRoughness.metallicFactor, 1.0);
    EXPECT_EQ(m.pbrMetallicRoughness.roughnessFactor, 1.0);
    EXPECT_EQ(bytesOf(m.emissiveTexture.index), options.emissive.png);
    EXPECT_EQ(m.emissiveFactor, (std::vector<double>{1.0, 1.0, 1.0}));
    EXPECT_NEAR(m.extensions.at("KHR_materials_emissive_strength").Get("emissiveStrength").GetNumberAsDouble(), 2.5,
                1e-6);
    const tinygltf::Value &transmission = m.extensions.at("KHR_materials_transmission");
    EXPECT_EQ(bytesOf(transmission.Get("transmissionTexture").Get("index").GetNumberAsInt()), options.transmission.png);
    EXPECT_NEAR(m.extensions.at("KHR_materials_ior").Get("ior").GetNumberAsDouble(), 1.3, 1e-6);
    EXPECT_EQ(model.extensionsUsed.size(), 3u);
    EXPECT_TRUE(model.extensionsRequired.empty());
    // Strength 1 needs no extension; without a base colour texture no map is written.
    options.emissiveStrength = 1.0f;
    options.transmission = {};
    const tinygltf::Model plain = load(writeGlb(g.mesh, g.scene, &texture, options));
    EXPECT_EQ(plain.materials[0].extensions.count("KHR_materials_emissive_strength"), 0u);
    EXPECT_TRUE(plain.extensionsUsed.empty());
    const tinygltf::Model bare = load(writeGlb(g.mesh, g.scene, nullptr, options));
    EXPECT_TRUE(bare.textures.empty());
    EXPECT_EQ(bare.materials[0].emissiveTexture.index, -1);
}

TEST(GlbWriter, AnimationSamplesEveryFrame) {
    std::mt19937 rng(9);
    for (size_t frames : {2u, 7u}) {
        const Generated g = generate(rng, frames);
        const tinygltf::Model model = load(writeGlb(g.mesh, g.scene, nullptr));
        ASSERT_EQ(model.animations.size(), 1u);
        const tinygltf::Animation &a = model.animations[0];
        EXPECT_EQ(a.channels.size(), 3 * g.scene.nodes.size());
        const std::vector<float> times = read<float>(model, a.samplers[0].input);
        ASSERT_EQ(times.size(), frames);
        EXPECT_FLOAT_EQ(times[1], 1.0f / 15.0f);
        // Each frame's local TRS composes back to the frame's world transform.
        for (const tinygltf::AnimationChannel &channel : a.channels) {
            if (channel.target_path != "rotation")
                continue;
            const std::vector<glm::vec4> q = read<glm::vec4>(model, a.samplers[size_t(channel.sampler)].output);
            for (const glm::vec4 &r : q)
                EXPECT_NEAR(glm::length(r), 1.0f, 1e-5f);
        }
    }
}

TEST(GlbWriter, InconsistentInputIsRefused) {
    GlbMesh mesh;
    mesh.positions = {glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
    mesh.triangles = {0, 1, 3};
    EXPECT_THROW(writeGlb(mesh, {}, nullptr), std::invalid_argument);
    mesh.triangles = {0, 1, 2};
    mesh.triangleNodes = {1};
    EXPECT_THROW(writeGlb(mesh, {}, nullptr), std::invalid_argument);
    mesh.triangleNodes.clear();
    EXPECT_NO_THROW(writeGlb(mesh, {}, nullptr));
}

TEST(GlbWriter, CornersWeldUnlessTheirUvsDiffer) {
    // A random n x n grid of quads: every corner of a vertex has the same UV except along one
    // seam column, whose vertices get a second UV on the right-hand quads.
    std::mt19937 rng(31);
    for (int trial = 0; trial < 10; ++trial) {
        const int n = 2 + int(rng() % 12), seam = 1 + int(rng() % unsigned(n - 1));
        GlbMesh mesh;
        for (int y = 0; y <= n; ++y)
            for (int x = 0; x <= n; ++x)
                mesh.positions.push_back(glm::vec3(x, y, 0));
        const auto at = [&](int x, int y) { return uint32_t(y * (n + 1) + x); };
        const auto uv = [&](int x, int y, int quadX) {
            return glm::vec2(float(x) / float(n) + (x == seam && quadX >= seam ? 0.5f : 0.0f), float(y) / float(n));
        };
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const int corners[6][2] = {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y}, {x + 1, y + 1}, {x, y + 1}};
                for (const auto &c : corners) {
                    mesh.triangles.push_back(at(c[0], c[1]));
                    mesh.cornerUvs.push_back(uv(c[0], c[1], x));
                }
            }
        const tinygltf::Model model = load(writeGlb(mesh, {}, nullptr));
        const tinygltf::Primitive &p = model.meshes[0].primitives[0];
        EXPECT_EQ(model.accessors[size_t(p.attributes.at("POSITION"))].count, size_t((n + 1) * (n + 1) + n + 1));
        EXPECT_EQ(model.accessors[size_t(p.indices)].count, size_t(6 * n * n));
    }
}
