// MagicaVoxel materials: the MATL chunks of the scene-graph extension (MagicaVoxel's vox file
// format extension text, "Material Chunk"; doc/formats/magicavoxel.md). Chunk: int32 material id,
// then a DICT of properties whose values are decimal numbers written as text.
//
// The material id is the colour index it applies to (1..255): a voxel of colour index c renders
// with material c. MagicaVoxel writes a MATL for all 256 entries, most of them `_diffuse`, and
// keeps every slider's value whatever the type; only the type's own properties take effect:
//   _diffuse  none (matte)
//   _metal    _metal (metalness 0..1), _rough (roughness 0..1), _spec
//   _glass    _rough, _ior (stored as the index of refraction minus 1), _trans or _alpha (how much
//             light passes, 0..1; files of MagicaVoxel 0.99.5 on write the glass' transparency as
//             _alpha), _d (density, for volumes)
//   _emit     _emit (emission 0..1), _flux (the Power slider, 0..4), _ldr
//   _blend    all of the above together
//   _media    a participating medium (clouds): no surface material
// Reading follows the rule of the spec's readers: a value that is not a finite number is ignored
// (counted in ignoredValues), values are clamped into the ranges above, ids outside 1..255 are
// ignored (id 256 is colour index 0, the empty voxel); a truncated chunk is the caller's
// FormatError.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace voxelfair {

enum class VoxMaterialType { Diffuse, Metal, Glass, Emit, Blend, Media };

const char *toString(VoxMaterialType type);

struct VoxMaterial {
    VoxMaterialType type = VoxMaterialType::Diffuse;
    // As given (clamped); absent keys stay empty.
    std::optional<float> metal, rough, spec, ior, flux, emission, trans, alpha;  // emission: `_emit`
};

struct VoxMaterialTable {
    std::array<VoxMaterial, 256> byIndex{};  // by colour index; index 0 (empty) unused
    size_t chunks = 0;                       // MATL chunks applied
    size_t ignoredChunks = 0;                // ids outside 1..255
    size_t ignoredValues = 0;                // values that were not finite numbers, unknown types

    // True when some index has a type other than _diffuse.
    bool any() const;
};

// Applies one MATL chunk's id and properties to `table`.
void applyVoxMaterial(int32_t id, const std::vector<std::pair<std::string, std::string>> &properties,
                      VoxMaterialTable &table);

}  // namespace voxelfair
