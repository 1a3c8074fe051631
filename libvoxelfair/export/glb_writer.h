// glTF 2.0 binary (.glb) writer: one self-contained file of nodes, meshes, an embedded PNG
// texture, a material and animations, for Blender, Godot, three.js, Babylon and Unity (glTFast).
// JSON and the GLB container are tinygltf's; what is ours is the layout below.
//
// Follows the glTF 2.0 specification (Khronos):
//  - Axes and units: glTF is right-handed, +Y up, the front of an asset towards +Z, metres. The
//    model (z up, one unit per voxel) is turned so that z becomes +Y and its front (ExportScene::
//    front) becomes +Z, and scaled by metresPerVoxel.
//  - Nodes: one per ExportScene node, in its tree, each at its pivot (TRS, no matrices); the
//    faces of a node form its mesh, positions in the node's frame. Without a scene, one node.
//  - Animation: nodes with frames get translation / rotation / scale channels (LINEAR), frame f
//    at time f / framesPerSecond.
//  - Mesh data: per-vertex POSITION (with min/max), unit NORMAL, TEXCOORD_0 when given (v flipped:
//    glTF's origin is the image's top left), COLOR_0 when given; uint32 indices; a vertex is
//    split where its corners differ in UV or colour.
//  - Material: pbrMetallicRoughness, the texture as baseColorTexture (PNG in a bufferView),
//    metallicFactor 0, roughnessFactor `roughness`; sampler magFilter NEAREST (9728) with
//    minFilter NEAREST_MIPMAP_LINEAR (9986) for pixel art, or LINEAR / LINEAR_MIPMAP_LINEAR;
//    CLAMP_TO_EDGE.
//  - Normal map (when GlbOptions::normalMap has a PNG): material normalTexture with its own
//    LINEAR / LINEAR_MIPMAP_LINEAR sampler, and per-vertex TANGENT (xyz unit, w the bitangent sign)
//    from GlbMesh::cornerTangents: the MikkTSpace frame the map was baked against (maps/), computed
//    with v up, so the map's green is +V as glTF's normalTexture expects; corners split where their
//    tangents differ.
//  - House colour mask (when GlbOptions::houseMask has a PNG): a texture with the base colour's
//    sampler, named from the material's extras as
//    "extras": {"voxelfair_house_colour_mask": {"index": TEXTURE}} (glTF's place for
//    application-specific data; TEXTURE indexes "textures", sampled with TEXCOORD_0).
//  - Material maps (GlbOptions::metallicRoughness, emissive, transmission), each with the base
//    colour's sampler: pbrMetallicRoughness.metallicRoughnessTexture (factors 1);
//    emissiveTexture with emissiveFactor [1, 1, 1] and, when the strength exceeds 1,
//    KHR_materials_emissive_strength; KHR_materials_transmission (factor 1, the map as
//    transmissionTexture) with KHR_materials_ior. Extensions used are listed in extensionsUsed
//    (none is required: a viewer without them still shows the base colour).
//
// The options struct is the place for later additions (normal maps, tangents, more textures):
// each new field gets a default that leaves today's output unchanged.
#pragma once

#include "export/export_scene.h"

#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace voxelfair {

enum class TextureFilter { Nearest, Linear };

// An encoded PNG, embedded as it is.
struct GlbTexture {
    std::vector<uint8_t> png;
    std::string name;
};

struct GlbOptions {
    // Size of one voxel (one model unit) in metres. 0.1: a 30-voxel C&C tank is 3 m long, a
    // 126-voxel MagicaVoxel character 12.6 m tall; engines import it at that size.
    float metresPerVoxel = 0.1f;
    TextureFilter textureFilter = TextureFilter::Nearest;
    float metallic = 0.0f;           // voxel art is painted, not metal
    float roughness = 0.9f;          // matte: no plastic shine
    std::string name = "voxelfair";  // the scene's and the single node's name
    std::string generator = "voxelfair";
    GlbTexture normalMap;  // empty: no normalTexture, no TANGENT
    // A VXL model's house colour mask (maps/house_mask.h) in the base colour's layout: white where
    // an engine tints by the player's colour. Empty: none.
    GlbTexture houseMask;
    // MagicaVoxel materials as PBR maps in the base colour's layout (maps/material_maps.h); each
    // empty one is left out. With a metallic-roughness map, metallic and roughness above are
    // replaced by factors of 1 (the map holds the values).
    GlbTexture metallicRoughness;   // G roughness, B metallic
    GlbTexture emissive;            // sRGB emitted colour
    float emissiveStrength = 1.0f;  // > 1: KHR_materials_emissive_strength
    GlbTexture transmission;        // R: KHR_materials_transmission's texture
    float ior = 0.0f;               // > 0 with a transmission map: KHR_materials_ior
};

// A triangle mesh in model space; the corner arrays hold 3 entries per triangle.
struct GlbMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;         // per vertex; empty: area-weighted face normals
    std::vector<uint32_t> triangles;        // 3 vertex indices per triangle, counter-clockwise
    std::vector<glm::vec2> cornerUvs;       // empty: no TEXCOORD_0; (0,0) is the image's bottom left
    std::vector<glm::vec4> cornerColours;   // empty: no COLOR_0; linear RGBA in [0, 1]
    std::vector<glm::vec4> cornerTangents;  // empty: no TANGENT; model frame, w = bitangent sign
    std::vector<int> triangleNodes;         // index into ExportScene::nodes per triangle; empty: node 0
};

// Throws std::invalid_argument for inconsistent input (sizes, indices, node numbers, a node
// whose parent does not come before it) and std::runtime_error when tinygltf cannot write.
std::vector<uint8_t> writeGlb(const GlbMesh &mesh, const ExportScene &scene, const GlbTexture *texture,
                              const GlbOptions &options = {});

// The rotation that takes the model's frame (z up, `front`) to glTF's (+Y up, front +Z).
glm::mat3 gltfAxes(ModelFront front);

}  // namespace voxelfair
