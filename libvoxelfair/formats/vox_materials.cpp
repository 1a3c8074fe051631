#include "formats/vox_materials.h"

#include "formats/vox_chunks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace voxelfair {

const char *toString(VoxMaterialType type) {
    switch (type) {
    case VoxMaterialType::Diffuse: return "diffuse";
    case VoxMaterialType::Metal: return "metal";
    case VoxMaterialType::Glass: return "glass";
    case VoxMaterialType::Emit: return "emit";
    case VoxMaterialType::Blend: return "blend";
    case VoxMaterialType::Media: return "media";
    }
    return "unknown";
}

bool VoxMaterialTable::any() const {
    return std::any_of(byIndex.begin() + 1, byIndex.end(),
                       [](const VoxMaterial &m) { return m.type != VoxMaterialType::Diffuse; });
}

namespace {

// The whole text as a finite decimal number, or nothing.
std::optional<float> number(const std::string &text) {
    const char *begin = text.data(), *end = text.data() + text.size();
    while (begin < end && *begin == ' ')
        ++begin;
    if (begin < end && *begin == '+')
        ++begin;
    float value = 0.0f;
    const auto [at, error] = std::from_chars(begin, end, value);
    if (error != std::errc() || at != end || !std::isfinite(value))
        return std::nullopt;
    return value;
}

}  // namespace

void applyVoxMaterial(int32_t id, const std::vector<std::pair<std::string, std::string>> &properties,
                      VoxMaterialTable &table) {
    if (id < 1 || id > 255) {
        ++table.ignoredChunks;
        return;
    }
    VoxMaterial material;
    if (const std::string *type = vox::lookup(properties, "_type")) {
        static const std::pair<const char *, VoxMaterialType> kTypes[] = {
            {"_diffuse", VoxMaterialType::Diffuse}, {"_metal", VoxMaterialType::Metal},
            {"_glass", VoxMaterialType::Glass},     {"_emit", VoxMaterialType::Emit},
            {"_blend", VoxMaterialType::Blend},     {"_media", VoxMaterialType::Media}};
        const auto *found =
            std::find_if(std::begin(kTypes), std::end(kTypes), [&](const auto &entry) { return *type == entry.first; });
        if (found != std::end(kTypes))
            material.type = found->second;
        else
            ++table.ignoredValues;  // an unknown type stays diffuse
    }
    const auto read = [&](const char *key, std::optional<float> &into, float lo, float hi) {
        const std::string *text = vox::lookup(properties, key);
        if (text == nullptr)
            return;
        if (const std::optional<float> value = number(*text))
            into = std::clamp(*value, lo, hi);
        else
            ++table.ignoredValues;
    };
    read("_metal", material.metal, 0.0f, 1.0f);
    read("_rough", material.rough, 0.0f, 1.0f);
    read("_spec", material.spec, 0.0f, 1.0f);
    read("_ior", material.ior, 0.0f, 4.0f);  // index of refraction - 1: 1..5
    read("_flux", material.flux, 0.0f, 4.0f);
    read("_emit", material.emission, 0.0f, 1.0f);
    read("_trans", material.trans, 0.0f, 1.0f);
    read("_alpha", material.alpha, 0.0f, 1.0f);
    table.byIndex[size_t(id)] = material;
    ++table.chunks;
}

}  // namespace voxelfair
