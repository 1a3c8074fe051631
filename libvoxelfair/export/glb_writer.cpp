// See glb_writer.h.
#include "export/glb_writer.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/matrix_decompose.hpp>
#include <glm/mat4x4.hpp>

namespace voxelfair {

namespace {

// glTF constants (the specification's enums).
constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kUint = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
constexpr int kArrayBuffer = TINYGLTF_TARGET_ARRAY_BUFFER;
constexpr int kElementArrayBuffer = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
constexpr int kNearest = 9728, kLinear = 9729, kNearestMipmapLinear = 9986, kLinearMipmapLinear = 9987;
constexpr int kClampToEdge = 33071;

// One node's triangles, welded: a glTF vertex per distinct (model vertex, UV, colour).
struct NodeMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec4> tangents;
    std::vector<glm::vec4> colours;
    std::vector<uint32_t> indices;
};

struct CornerKey {
    uint32_t vertex;
    glm::vec2 uv;
    glm::vec4 colour;
    glm::vec4 tangent;
    // Bitwise, as the hash: corners weld only when every attribute has the same bit pattern.
    // NOLINTBEGIN(bugprone-suspicious-memory-comparison)
    bool operator==(const CornerKey &o) const {
        return vertex == o.vertex && std::memcmp(&uv, &o.uv, sizeof uv) == 0 &&
               std::memcmp(&colour, &o.colour, sizeof colour) == 0 &&
               std::memcmp(&tangent, &o.tangent, sizeof tangent) == 0;
    }
    // NOLINTEND(bugprone-suspicious-memory-comparison)
};

void check(bool ok, const std::string &problem) {
    if (!ok)
        throw std::invalid_argument("glb writer: " + problem);
}

// Appends `count` items of `bytes` each to the buffer as a bufferView (4-byte aligned).
class BinaryBuilder {
public:
    explicit BinaryBuilder(tinygltf::Model &model) : model_(model) { model_.buffers.emplace_back(); }

    int view(const void *data, size_t bytes, int target) {
        std::vector<unsigned char> &buffer = model_.buffers[0].data;
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = bytes;
        view.target = target;
        const auto *p = static_cast<const unsigned char *>(data);
        buffer.insert(buffer.end(), p, p + bytes);
        buffer.resize((buffer.size() + 3) & ~size_t(3), 0);
        model_.bufferViews.push_back(view);
        return int(model_.bufferViews.size() - 1);
    }

    // A float accessor of `count` elements of `components` floats (type VEC2/VEC3/VEC4/SCALAR).
    int floats(const float *data, size_t count, int components, int type, int target, bool bounds) {
        tinygltf::Accessor accessor;
        accessor.bufferView = view(data, count * size_t(components) * sizeof(float), target);
        accessor.componentType = kFloat;
        accessor.count = count;
        accessor.type = type;
        if (bounds) {
            accessor.minValues.assign(size_t(components), std::numeric_limits<double>::infinity());
            accessor.maxValues.assign(size_t(components), -std::numeric_limits<double>::infinity());
            for (size_t i = 0; i < count; ++i)
                for (int c = 0; c < components; ++c) {
                    const double v = data[i * size_t(components) + size_t(c)];
                    accessor.minValues[size_t(c)] = std::min(accessor.minValues[size_t(c)], v);
                    accessor.maxValues[size_t(c)] = std::max(accessor.maxValues[size_t(c)], v);
                }
        }
        model_.accessors.push_back(accessor);
        return int(model_.accessors.size() - 1);
    }

    int indices(const std::vector<uint32_t> &data) {
        tinygltf::Accessor accessor;
        accessor.bufferView = view(data.data(), data.size() * 4, kElementArrayBuffer);
        accessor.componentType = kUint;
        accessor.count = data.size();
        accessor.type = TINYGLTF_TYPE_SCALAR;
        model_.accessors.push_back(accessor);
        return int(model_.accessors.size() - 1);
    }

private:
    tinygltf::Model &model_;
};

glm::vec3 unitOr(glm::vec3 n, glm::vec3 fallback) {
    const float length = glm::length(n);
    return length > 1e-12f && std::isfinite(length) ? n / length : fallback;
}

struct Trs {
    glm::vec3 translation{0.0f}, scale{1.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
};

Trs decompose(const glm::mat4 &m) {
    Trs trs;
    glm::vec3 skew;
    glm::vec4 perspective;
    if (!glm::decompose(m, trs.scale, trs.rotation, trs.translation, skew, perspective))
        return Trs{};
    trs.rotation = glm::normalize(trs.rotation);
    return trs;
}

std::vector<double> toDoubles(const float *p, int n) { return std::vector<double>(p, p + n); }

// Splits the mesh by node and welds each node's corners; positions and normals go to the node's
// frame in glTF axes: p_local = C * world^-1 * p_model (C = axes * metresPerVoxel). The corners
// met so far at a (node, vertex) are chained from that vertex's slot: a vertex has a handful of
// distinct UVs at most, so a short walk replaces a hash of every corner.
std::vector<NodeMesh> splitByNode(const GlbMesh &mesh, const std::vector<glm::mat4> &modelToLocal,
                                  const std::vector<glm::mat3> &normalToLocal) {
    constexpr uint32_t kNone = ~uint32_t(0);
    struct Seen {
        CornerKey key;
        uint32_t index, next;
    };
    const size_t triangles = mesh.triangles.size() / 3;
    std::vector<NodeMesh> nodes(modelToLocal.size());
    std::vector<std::vector<uint32_t>> first(modelToLocal.size());  // per node, per model vertex
    std::vector<Seen> seen;
    seen.reserve(mesh.positions.size() + mesh.positions.size() / 2);
    const bool hasUv = !mesh.cornerUvs.empty(), hasColour = !mesh.cornerColours.empty(),
               hasNormal = !mesh.normals.empty(), hasTangent = !mesh.cornerTangents.empty();
    for (size_t t = 0; t < triangles; ++t) {
        const size_t node = mesh.triangleNodes.empty() ? 0 : size_t(mesh.triangleNodes[t]);
        NodeMesh &out = nodes[node];
        std::vector<uint32_t> &heads = first[node];
        if (heads.empty())
            heads.assign(mesh.positions.size(), kNone);
        for (int c = 0; c < 3; ++c) {
            const size_t corner = 3 * t + size_t(c);
            const CornerKey key{mesh.triangles[corner], hasUv ? mesh.cornerUvs[corner] : glm::vec2(0.0f),
                                hasColour ? mesh.cornerColours[corner] : glm::vec4(0.0f),
                                hasTangent ? mesh.cornerTangents[corner] : glm::vec4(0.0f)};
            uint32_t found = kNone;
            for (uint32_t s = heads[key.vertex]; s != kNone; s = seen[s].next)
                if (seen[s].key == key) {
                    found = seen[s].index;
                    break;
                }
            if (found == kNone) {
                found = uint32_t(out.positions.size());
                seen.push_back({key, found, heads[key.vertex]});
                heads[key.vertex] = uint32_t(seen.size() - 1);
                out.positions.push_back(glm::vec3(modelToLocal[node] * glm::vec4(mesh.positions[key.vertex], 1.0f)));
                if (hasNormal)
                    out.normals.push_back(unitOr(normalToLocal[node] * mesh.normals[key.vertex], glm::vec3(0, 1, 0)));
                if (hasUv)
                    out.uvs.push_back(glm::vec2(key.uv.x, 1.0f - key.uv.y));
                if (hasColour)
                    out.colours.push_back(key.colour);
                if (hasTangent) {
                    // A surface direction: the frame's linear part; a mirroring frame flips the handedness.
                    const glm::mat3 linear(modelToLocal[node]);
                    const glm::vec3 t = unitOr(linear * glm::vec3(key.tangent), glm::vec3(1, 0, 0));
                    const float w =
                        (key.tangent.w < 0.0f ? -1.0f : 1.0f) * (glm::determinant(linear) < 0.0f ? -1.0f : 1.0f);
                    out.tangents.emplace_back(t, w);
                }
            }
            out.indices.push_back(found);
        }
    }
    return nodes;
}

// Area-weighted mean of the adjacent triangles' normals (the cross product's length is twice the area).
std::vector<glm::vec3> faceWeightedNormals(const GlbMesh &mesh) {
    std::vector<glm::vec3> normals(mesh.positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        const uint32_t a = mesh.triangles[t], b = mesh.triangles[t + 1], c = mesh.triangles[t + 2];
        const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        normals[a] += n, normals[b] += n, normals[c] += n;
    }
    return normals;
}

void checkInput(const GlbMesh &mesh, const ExportScene &scene, size_t nodeCount) {
    check(mesh.triangles.size() % 3 == 0, "the triangle index count is not a multiple of 3");
    const size_t triangles = mesh.triangles.size() / 3;
    for (uint32_t v : mesh.triangles)
        check(v < mesh.positions.size(), "a triangle index is past the vertices");
    check(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size(), "normals are not one per vertex");
    check(mesh.cornerUvs.empty() || mesh.cornerUvs.size() == 3 * triangles, "UVs are not three per triangle");
    check(mesh.cornerTangents.empty() || mesh.cornerTangents.size() == 3 * triangles,
          "tangents are not three per triangle");
    check(mesh.cornerTangents.empty() || !mesh.cornerUvs.empty(), "tangents without texture coordinates");
    check(mesh.cornerColours.empty() || mesh.cornerColours.size() == 3 * triangles,
          "colours are not three per triangle");
    check(mesh.triangleNodes.empty() || mesh.triangleNodes.size() == triangles, "triangle nodes are not one each");
    for (int n : mesh.triangleNodes)
        check(n >= 0 && size_t(n) < nodeCount, "a triangle's node does not exist");
    const size_t frames = scene.frameCount();
    for (size_t i = 0; i < scene.nodes.size(); ++i) {
        const ExportNode &node = scene.nodes[i];
        check(node.parent >= -1 && node.parent < int(i),
              "node " + std::to_string(i) + "'s parent does not come before it");
        check(node.frames.empty() || node.frames.size() == frames, "animated nodes differ in their frame counts");
    }
    check(frames <= 1 || scene.framesPerSecond > 0.0f, "the frame rate must be positive");
}

}  // namespace

glm::mat3 gltfAxes(ModelFront front) {
    // Columns are the images of the model's x, y, z axes in glTF's (X, Y, Z): z -> +Y always.
    if (front == ModelFront::PlusX)
        return glm::mat3(glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0));
    return glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));  // -y -> +Z
}

std::vector<uint8_t> writeGlb(const GlbMesh &mesh, const ExportScene &inputScene, const GlbTexture *texture,
                              const GlbOptions &options) {
    check(options.metresPerVoxel > 0.0f && std::isfinite(options.metresPerVoxel), "metres per voxel must be positive");
    ExportScene scene = inputScene;
    if (scene.nodes.empty())
        scene.nodes.push_back(ExportNode{options.name, -1, glm::mat4(1.0f), {}});
    checkInput(mesh, scene, scene.nodes.size());

    // C: model frame -> glTF frame; G = C W C^-1 is a node's world transform in glTF.
    const glm::mat4 axes(gltfAxes(scene.front));
    glm::mat4 scale(1.0f);
    scale[0][0] = scale[1][1] = scale[2][2] = options.metresPerVoxel;
    const glm::mat4 c = scale * axes;
    const glm::mat4 cInverse = glm::inverse(c);
    const auto toGltf = [&](const glm::mat4 &world) { return c * world * cInverse; };

    std::vector<glm::mat4> modelToLocal, gltfWorld;
    std::vector<glm::mat3> normalToLocal;
    for (const ExportNode &node : scene.nodes) {
        const glm::mat4 inverseWorld = glm::inverse(node.world);
        modelToLocal.push_back(c * inverseWorld);
        normalToLocal.push_back(glm::transpose(glm::inverse(glm::mat3(c * inverseWorld))));
        gltfWorld.push_back(toGltf(node.world));
    }
    std::vector<NodeMesh> parts;
    if (mesh.normals.empty()) {
        GlbMesh withNormals = mesh;
        withNormals.normals = faceWeightedNormals(mesh);
        parts = splitByNode(withNormals, modelToLocal, normalToLocal);
    } else {
        parts = splitByNode(mesh, modelToLocal, normalToLocal);
    }

    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = options.generator;
    BinaryBuilder bin(model);

    int material = -1;
    {
        tinygltf::Material m;
        m.name = options.name;
        m.pbrMetallicRoughness.metallicFactor = options.metallic;
        m.pbrMetallicRoughness.roughnessFactor = options.roughness;
        if (texture != nullptr && !texture->png.empty()) {
            tinygltf::Image image;
            image.name = texture->name;
            image.mimeType = "image/png";
            image.bufferView = bin.view(texture->png.data(), texture->png.size(), 0);  // no target
            model.images.push_back(image);
            tinygltf::Sampler sampler;
            const bool nearest = options.textureFilter == TextureFilter::Nearest;
            sampler.magFilter = nearest ? kNearest : kLinear;
            sampler.minFilter = nearest ? kNearestMipmapLinear : kLinearMipmapLinear;
            sampler.wrapS = sampler.wrapT = kClampToEdge;
            model.samplers.push_back(sampler);
            tinygltf::Texture t;
            t.source = 0;
            t.sampler = 0;
            model.textures.push_back(t);
            m.pbrMetallicRoughness.baseColorTexture.index = 0;
        }
        if (!options.normalMap.png.empty() && !mesh.cornerUvs.empty()) {
            // The tangent-space normal map: its own, linear sampler (a normal field, not pixel art).
            tinygltf::Image image;
            image.name = options.normalMap.name;
            image.mimeType = "image/png";
            image.bufferView = bin.view(options.normalMap.png.data(), options.normalMap.png.size(), 0);
            model.images.push_back(image);
            tinygltf::Sampler sampler;
            sampler.magFilter = kLinear;
            sampler.minFilter = kLinearMipmapLinear;
            sampler.wrapS = sampler.wrapT = kClampToEdge;
            model.samplers.push_back(sampler);
            tinygltf::Texture t;
            t.source = int(model.images.size() - 1);
            t.sampler = int(model.samplers.size() - 1);
            model.textures.push_back(t);
            m.normalTexture.index = int(model.textures.size() - 1);
        }
        // A map in the base colour's layout: its own image, the base colour's sampler (it lines up
        // with it texel for texel). Returns the texture index, or -1 without a base colour.
        const bool baseColour = !mesh.cornerUvs.empty() && !model.samplers.empty();
        const auto layoutMap = [&](const GlbTexture &png) {
            if (png.png.empty() || !baseColour)
                return -1;
            tinygltf::Image image;
            image.name = png.name;
            image.mimeType = "image/png";
            image.bufferView = bin.view(png.png.data(), png.png.size(), 0);
            model.images.push_back(image);
            tinygltf::Texture t;
            t.source = int(model.images.size() - 1);
            t.sampler = 0;
            model.textures.push_back(t);
            return int(model.textures.size() - 1);
        };
        const auto use = [&](const char *extension) {
            if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), extension) ==
                model.extensionsUsed.end())
                model.extensionsUsed.push_back(extension);
        };
        if (const int index = layoutMap(options.houseMask); index >= 0) {
            tinygltf::Value::Object reference{{"index", tinygltf::Value(index)}};
            tinygltf::Value::Object extras{{"voxelfair_house_colour_mask", tinygltf::Value(reference)}};
            m.extras = tinygltf::Value(extras);
        }
        if (const int index = layoutMap(options.metallicRoughness); index >= 0) {
            m.pbrMetallicRoughness.metallicRoughnessTexture.index = index;
            m.pbrMetallicRoughness.metallicFactor = 1.0;
            m.pbrMetallicRoughness.roughnessFactor = 1.0;
        }
        if (const int index = layoutMap(options.emissive); index >= 0) {
            m.emissiveTexture.index = index;
            m.emissiveFactor = {1.0, 1.0, 1.0};
            if (options.emissiveStrength > 1.0f && std::isfinite(options.emissiveStrength)) {
                m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(
                    tinygltf::Value::Object{{"emissiveStrength", tinygltf::Value(double(options.emissiveStrength))}});
                use("KHR_materials_emissive_strength");
            }
        }
        if (const int index = layoutMap(options.transmission); index >= 0) {
            tinygltf::Value::Object textureInfo{{"index", tinygltf::Value(index)}};
            m.extensions["KHR_materials_transmission"] = tinygltf::Value(tinygltf::Value::Object{
                {"transmissionFactor", tinygltf::Value(1.0)}, {"transmissionTexture", tinygltf::Value(textureInfo)}});
            use("KHR_materials_transmission");
            if (options.ior > 0.0f && std::isfinite(options.ior)) {
                m.extensions["KHR_materials_ior"] =
                    tinygltf::Value(tinygltf::Value::Object{{"ior", tinygltf::Value(double(options.ior))}});
                use("KHR_materials_ior");
            }
        }
        model.materials.push_back(m);
        material = 0;
    }

    tinygltf::Scene gltfScene;
    gltfScene.name = options.name;
    for (size_t i = 0; i < scene.nodes.size(); ++i) {
        const ExportNode &node = scene.nodes[i];
        tinygltf::Node n;
        n.name = node.name;
        const glm::mat4 local =
            node.parent < 0 ? gltfWorld[i] : glm::inverse(gltfWorld[size_t(node.parent)]) * gltfWorld[i];
        const Trs trs = decompose(local);
        if (trs.translation != glm::vec3(0.0f))
            n.translation = toDoubles(&trs.translation.x, 3);
        if (trs.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f))
            n.rotation = {trs.rotation.x, trs.rotation.y, trs.rotation.z, trs.rotation.w};
        if (glm::any(glm::greaterThan(glm::abs(trs.scale - glm::vec3(1.0f)), glm::vec3(1e-6f))))
            n.scale = toDoubles(&trs.scale.x, 3);

        const NodeMesh &part = parts[i];
        if (!part.indices.empty()) {
            tinygltf::Primitive primitive;
            primitive.mode = TINYGLTF_MODE_TRIANGLES;
            primitive.material = material;
            primitive.attributes["POSITION"] =
                bin.floats(&part.positions[0].x, part.positions.size(), 3, TINYGLTF_TYPE_VEC3, kArrayBuffer, true);
            if (!part.normals.empty())
                primitive.attributes["NORMAL"] =
                    bin.floats(&part.normals[0].x, part.normals.size(), 3, TINYGLTF_TYPE_VEC3, kArrayBuffer, false);
            if (!part.uvs.empty())
                primitive.attributes["TEXCOORD_0"] =
                    bin.floats(&part.uvs[0].x, part.uvs.size(), 2, TINYGLTF_TYPE_VEC2, kArrayBuffer, false);
            if (!part.tangents.empty() && !options.normalMap.png.empty())
                primitive.attributes["TANGENT"] =
                    bin.floats(&part.tangents[0].x, part.tangents.size(), 4, TINYGLTF_TYPE_VEC4, kArrayBuffer, false);
            if (!part.colours.empty())
                primitive.attributes["COLOR_0"] =
                    bin.floats(&part.colours[0].x, part.colours.size(), 4, TINYGLTF_TYPE_VEC4, kArrayBuffer, false);
            primitive.indices = bin.indices(part.indices);
            tinygltf::Mesh m;
            m.name = node.name;
            m.primitives.push_back(primitive);
            model.meshes.push_back(m);
            n.mesh = int(model.meshes.size() - 1);
        }
        model.nodes.push_back(n);
        if (node.parent < 0)
            gltfScene.nodes.push_back(int(i));
        else
            model.nodes[size_t(node.parent)].children.push_back(int(i));
    }
    model.scenes.push_back(gltfScene);
    model.defaultScene = 0;

    // Animation: per animated node, its local TRS at each frame.
    const size_t frames = scene.frameCount();
    if (frames > 1) {
        tinygltf::Animation animation;
        animation.name = options.name;
        std::vector<float> times(frames);
        for (size_t f = 0; f < frames; ++f)
            times[f] = float(f) / scene.framesPerSecond;
        const int input = bin.floats(times.data(), frames, 1, TINYGLTF_TYPE_SCALAR, 0, true);
        const auto frameWorld = [&](size_t node, size_t f) {
            const ExportNode &n = scene.nodes[node];
            return toGltf(n.frames.empty() ? n.world : n.frames[f]);
        };
        for (size_t i = 0; i < scene.nodes.size(); ++i) {
            if (scene.nodes[i].frames.empty())
                continue;
            std::vector<glm::vec3> translations(frames), scales(frames);
            std::vector<glm::quat> rotations(frames);
            for (size_t f = 0; f < frames; ++f) {
                const int parent = scene.nodes[i].parent;
                const glm::mat4 local =
                    parent < 0 ? frameWorld(i, f) : glm::inverse(frameWorld(size_t(parent), f)) * frameWorld(i, f);
                const Trs trs = decompose(local);
                translations[f] = trs.translation;
                scales[f] = trs.scale;
                rotations[f] = f > 0 && glm::dot(rotations[f - 1], trs.rotation) < 0.0f ? -trs.rotation : trs.rotation;
            }
            std::vector<float> quats;
            for (const glm::quat &q : rotations)
                quats.insert(quats.end(), {q.x, q.y, q.z, q.w});
            const std::pair<const char *, int> outputs[3] = {
                {"translation", bin.floats(&translations[0].x, frames, 3, TINYGLTF_TYPE_VEC3, 0, false)},
                {"rotation", bin.floats(quats.data(), frames, 4, TINYGLTF_TYPE_VEC4, 0, false)},
                {"scale", bin.floats(&scales[0].x, frames, 3, TINYGLTF_TYPE_VEC3, 0, false)}};
            for (const auto &[path, output] : outputs) {
                tinygltf::AnimationSampler sampler;
                sampler.input = input;
                sampler.output = output;
                sampler.interpolation = "LINEAR";
                animation.samplers.push_back(sampler);
                tinygltf::AnimationChannel channel;
                channel.sampler = int(animation.samplers.size() - 1);
                channel.target_node = int(i);
                channel.target_path = path;
                animation.channels.push_back(channel);
            }
        }
        model.animations.push_back(animation);
    }

    std::ostringstream stream;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, stream, false, true))
        throw std::runtime_error("glb writer: tinygltf could not write the file");
    const std::string bytes = stream.str();
    return std::vector<uint8_t>(bytes.begin(), bytes.end());
}

}  // namespace voxelfair
