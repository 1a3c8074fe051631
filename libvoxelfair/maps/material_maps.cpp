#include "maps/material_maps.h"

#include "base/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace voxelfair {

PbrVoxel pbrOf(const VoxMaterial &m, const PbrDefaults &defaults) {
    PbrVoxel p;
    p.metallic = defaults.metallic;
    p.roughness = defaults.roughness;
    const VoxMaterialType t = m.type;
    const bool blend = t == VoxMaterialType::Blend;
    if (t == VoxMaterialType::Metal || blend)
        p.metallic = m.metal.value_or(blend ? defaults.metallic : 1.0f);
    if (t == VoxMaterialType::Metal || t == VoxMaterialType::Glass || blend)
        p.roughness = m.rough.value_or(defaults.roughness);
    if (t == VoxMaterialType::Emit || blend)
        p.emission = m.emission.value_or(blend ? 0.0f : 1.0f) * std::exp2(m.flux.value_or(0.0f));
    if (t == VoxMaterialType::Glass || blend) {
        p.transmission = m.trans ? *m.trans : m.alpha.value_or(blend ? 0.0f : 1.0f);
        if (p.transmission > 0.0f)
            p.ior = 1.0f + m.ior.value_or(0.5f);
    }
    return p;
}

namespace {

float linearFromSrgb(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
float srgbFromLinear(float c) { return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }
uint8_t unorm(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

std::vector<uint8_t> channels(const FaceValueImage &image, int count) {
    std::vector<uint8_t> out(size_t(image.width) * size_t(image.height) * size_t(count));
    for (size_t i = 0, n = size_t(image.width) * size_t(image.height); i < n; ++i)
        for (int c = 0; c < count; ++c)
            out[i * size_t(count) + size_t(c)] = image.rgba[4 * i + size_t(c)];
    return out;
}

}  // namespace

MaterialMaps bakeMaterialMaps(const FaceValueMesh &mesh, const uint8_t *facePaletteIndex,
                              const glm::u8vec3 *faceColours, const VoxMaterialTable &materials, int width, int height,
                              int dilation, bool blocks, const PbrDefaults &defaults) {
    if (mesh.faceCount > 0 && (facePaletteIndex == nullptr || faceColours == nullptr))
        throw MeshError("material maps: every face needs its palette index and colour");
    MaterialMaps out;
    out.width = width;
    out.height = height;
    std::array<PbrVoxel, 256> pbr;
    for (size_t i = 0; i < 256; ++i)
        pbr[i] = pbrOf(materials.byIndex[i], defaults);

    std::map<float, size_t> iorFaces;
    for (size_t f = 0; f < mesh.faceCount; ++f) {
        const PbrVoxel &p = pbr[facePaletteIndex[f]];
        out.metalRoughFaces += p.metallic != defaults.metallic || p.roughness != defaults.roughness ? 1 : 0;
        out.emissiveFaces += p.emission > 0.0f ? 1 : 0;
        out.emissiveStrength = std::max(out.emissiveStrength, p.emission);
        if (p.transmission > 0.0f) {
            ++out.transmissiveFaces;
            ++iorFaces[p.ior];
        }
    }
    const auto mostFaces = std::max_element(iorFaces.begin(), iorFaces.end(),
                                            [](const auto &a, const auto &b) { return a.second < b.second; });
    out.ior = mostFaces == iorFaces.end() ? 0.0f : mostFaces->first;

    std::vector<glm::u8vec3> values(mesh.faceCount);
    if (out.metalRoughFaces > 0) {
        for (size_t f = 0; f < mesh.faceCount; ++f) {
            const PbrVoxel &p = pbr[facePaletteIndex[f]];
            values[f] = glm::u8vec3(255, unorm(p.roughness), unorm(p.metallic));
        }
        out.metallicRoughness =
            channels(bakeFaceValues(mesh, values.data(), width, height, dilation,
                                    glm::u8vec3(255, unorm(defaults.roughness), unorm(defaults.metallic)), blocks),
                     3);
    }
    if (out.emissiveFaces > 0) {
        for (size_t f = 0; f < mesh.faceCount; ++f) {
            const float k = pbr[facePaletteIndex[f]].emission / out.emissiveStrength;
            glm::u8vec3 c(0);
            for (int i = 0; i < 3 && k > 0.0f; ++i)
                c[i] = unorm(srgbFromLinear(linearFromSrgb(float(faceColours[f][i]) / 255.0f) * k));
            values[f] = c;
        }
        out.emissive = channels(bakeFaceValues(mesh, values.data(), width, height, dilation, {0, 0, 0}, blocks), 3);
    }
    if (out.transmissiveFaces > 0) {
        for (size_t f = 0; f < mesh.faceCount; ++f)
            values[f] = glm::u8vec3(unorm(pbr[facePaletteIndex[f]].transmission));
        out.transmission = channels(bakeFaceValues(mesh, values.data(), width, height, dilation, {0, 0, 0}, blocks), 1);
    }
    return out;
}

}  // namespace voxelfair
