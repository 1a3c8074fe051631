// MagicaVoxel materials (formats/vox_materials.h) as glTF 2.0 PBR maps in the base colour's atlas
// layout: the "material maps" of the paper's future work (§6), baked per face like the base colour
// (face_value_bake.h), so each voxel's texels carry its own material.
//
// Per colour index (the voxel's material), following the glTF 2.0 specification (metallic-
// roughness model) and the Khronos extensions KHR_materials_emissive_strength,
// KHR_materials_transmission and KHR_materials_ior:
//   metallic      _metal of _metal (absent: 1) and _blend materials; otherwise the default (0)
//   roughness     _rough of _metal, _glass and _blend materials; otherwise the default (0.9)
//   emission      _emit * 2^_flux of _emit (absent _emit: 1) and _blend materials: the emitted
//                 colour is the voxel's colour at that strength (MagicaVoxel publishes no formula
//                 for its Power slider; here each step doubles)
//   transmission  _trans, else _alpha, of _glass (absent: 1) and _blend materials
//   ior           1 + _ior of _glass and _blend materials (absent: 1.5)
// _diffuse and _media voxels keep the defaults. Maps are made only when some face needs them:
//   metallicRoughness  RGB: G roughness, B metallic (glTF's channels), R 255
//   emissive           RGB, sRGB: the voxel colour * emission / strength, where strength is the
//                      largest emission (at least 1): glTF's emissiveTexture * emissiveFactor (1)
//                      * KHR_materials_emissive_strength (written when strength > 1)
//   transmission       grey: KHR_materials_transmission's texture (R), factor 1
// glTF has one index of refraction per material: ior is the transmissive faces' (their most
// common value).
#pragma once

#include "formats/vox_materials.h"
#include "maps/face_value_bake.h"

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/gtc/type_precision.hpp>

namespace voxelfair {

struct PbrDefaults {
    float metallic = 0.0f;
    float roughness = 0.9f;  // the exporter's matte default for painted voxels
};

// One material as glTF sees it.
struct PbrVoxel {
    float metallic = 0.0f, roughness = 0.9f;
    float emission = 0.0f;  // strength of the emitted voxel colour (0: none)
    float transmission = 0.0f;
    float ior = 0.0f;  // 0: not transmissive
};

PbrVoxel pbrOf(const VoxMaterial &material, const PbrDefaults &defaults = {});

struct MaterialMaps {
    int width = 0, height = 0;
    // width x height, rows from the top (v = 1) down as PNG stores them; empty when not needed.
    std::vector<uint8_t> metallicRoughness;  // RGB
    std::vector<uint8_t> emissive;           // RGB
    std::vector<uint8_t> transmission;       // grey
    float emissiveStrength = 1.0f;
    float ior = 0.0f;  // 0: no transmissive face
    size_t metalRoughFaces = 0, emissiveFaces = 0, transmissiveFaces = 0;

    bool empty() const { return metallicRoughness.empty() && emissive.empty() && transmission.empty(); }
};

// `facePaletteIndex` and `faceColours` (the voxel's sRGB colour) hold one entry per face; the
// gutter (`dilation`, `blocks`) as bakeFaceValues'. Throws as bakeFaceValues does.
MaterialMaps bakeMaterialMaps(const FaceValueMesh &mesh, const uint8_t *facePaletteIndex,
                              const glm::u8vec3 *faceColours, const VoxMaterialTable &materials, int width, int height,
                              int dilation, bool blocks = false, const PbrDefaults &defaults = {});

}  // namespace voxelfair
