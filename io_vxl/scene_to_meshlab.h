// Copies a SceneSurface into a MeshLab mesh: each quad becomes a MeshLab polygon (two triangles
// whose shared diagonal is faux), with the voxel's colour and the part (section) per face.
#pragma once

#include "export/export_scene.h"
#include "formats/vox_materials.h"
#include "scene/voxel_scene.h"

#include <common/meshmodel.h>
#include <vcg/complex/allocate.h>

#include <cstdint>
#include <string>
#include <vector>

namespace voxelfair {

// Name of the per-face int attribute holding the part (VXL section, VOX instance) of each face.
// The same number is written to the face quality, which MeshLab's PLY exporter can save.
constexpr const char *kPartAttributeName = "voxelfair_part";

// Name of the per-face uint8_t attribute holding each face's voxel palette index (VXL: the index
// into the section's palette, 16..31 being the house colours; VOX: the colour index, which is
// also the MATL material id). The material filters bake it into maps (maps/house_mask.h).
constexpr const char *kPaletteIndexAttributeName = "voxelfair_palette_index";

// Each part's voxel size (index: the per-face part; 0 for a part without faces), a per-mesh
// std::vector<float> attribute the importer measures on the voxel surface, where every edge is
// one voxel. Filters that work per voxel (the fairing, the atlas' texels per voxel) pass it to
// detectVoxelSize (fairing/voxel_size.h) rather than detecting the size afresh on a mesh they may
// get faired, where a thin part's cross-sections shrink into a mode of their own.
constexpr const char *kPartVoxelSizeAttributeName = "voxelfair_part_voxel_size";

// The voxel size the importer measured for `part`, or 0 when the mesh has none for it.
inline float importedVoxelSize(const CMeshO &m, int part) {
    CMeshO &lookup = const_cast<CMeshO &>(m);  // vcglib's attribute look-up is not const
    if (part < 0 || !vcg::tri::HasPerMeshAttribute(lookup, kPartVoxelSizeAttributeName))
        return 0.0f;
    auto handle =
        vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<std::vector<float>>(lookup, kPartVoxelSizeAttributeName);
    if (!vcg::tri::Allocator<CMeshO>::IsValidHandle(lookup, handle) || size_t(part) >= handle().size())
        return 0.0f;
    return handle()[size_t(part)];
}

// What the palette indices mean: a per-mesh int attribute set by the importer.
enum class PaletteKind : int { Westwood = 1, MagicaVoxel = 2 };
constexpr const char *kPaletteKindAttributeName = "voxelfair_palette_kind";

// The maps baked beside the base colour for exporters (io_gltf): file names as the filters wrote
// them (relative to the base colour's folder) and the material-wide factors. A per-mesh attribute;
// Bake Normal Map copies it onto the decimated layer with the parts.
struct MaterialMapFiles {
    std::string houseMask;          // grey: 255 where the house colour shows
    std::string metallicRoughness;  // glTF channels: G roughness, B metallic
    std::string emissive;           // sRGB emitted colour
    std::string transmission;       // R: transmission
    float emissiveStrength = 1.0f;  // KHR_materials_emissive_strength when > 1
    float ior = 0.0f;               // KHR_materials_ior when > 0
};
constexpr const char *kMaterialMapsAttributeName = "voxelfair_material_maps";

inline void storeMaterialMaps(const MaterialMapFiles &maps, CMeshO &m) {
    auto handle = vcg::tri::Allocator<CMeshO>::GetPerMeshAttribute<MaterialMapFiles>(m, kMaterialMapsAttributeName);
    handle() = maps;
}

// The stored maps, or null when no filter baked any.
inline const MaterialMapFiles *findMaterialMaps(CMeshO &m) {
    if (!vcg::tri::HasPerMeshAttribute(m, kMaterialMapsAttributeName))
        return nullptr;
    auto handle = vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<MaterialMapFiles>(m, kMaterialMapsAttributeName);
    return vcg::tri::Allocator<CMeshO>::IsValidHandle(m, handle) ? &handle() : nullptr;
}

// A VOX model's MATL materials by colour index, for Bake Material Maps: a per-mesh attribute.
constexpr const char *kVoxMaterialsAttributeName = "voxelfair_vox_materials";

inline void storeVoxMaterials(const VoxMaterialTable &materials, CMeshO &m) {
    auto handle = vcg::tri::Allocator<CMeshO>::GetPerMeshAttribute<VoxMaterialTable>(m, kVoxMaterialsAttributeName);
    handle() = materials;
}

inline const VoxMaterialTable *findVoxMaterials(CMeshO &m) {
    if (!vcg::tri::HasPerMeshAttribute(m, kVoxMaterialsAttributeName))
        return nullptr;
    auto handle = vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<VoxMaterialTable>(m, kVoxMaterialsAttributeName);
    return vcg::tri::Allocator<CMeshO>::IsValidHandle(m, handle) ? &handle() : nullptr;
}

// The MeshLab import mask for what sceneToMeshLab fills.
int sceneImportMask();

// Replaces the content of `model` with `surface` (positions, polygons, colours, parts, palette
// indices, the palette kind). `model` must have had Enable(sceneImportMask()).
void sceneToMeshLab(const SceneSurface &surface, PaletteKind kind, MeshModel &model);

// The model's parts for exporters (export/export_scene.h) travel with the mesh as a per-mesh
// attribute, through every filter, to io_gltf; faces name their node by the per-face part.
constexpr const char *kExportSceneAttributeName = "voxelfair_export_scene";

inline void storeExportScene(const ExportScene &scene, CMeshO &m) {
    auto handle = vcg::tri::Allocator<CMeshO>::GetPerMeshAttribute<ExportScene>(m, kExportSceneAttributeName);
    handle() = scene;
}

// The stored scene, or null when the mesh has none (not imported by io_vxl).
inline const ExportScene *findExportScene(CMeshO &m) {
    if (!vcg::tri::HasPerMeshAttribute(m, kExportSceneAttributeName))
        return nullptr;
    auto handle = vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<ExportScene>(m, kExportSceneAttributeName);
    return vcg::tri::Allocator<CMeshO>::IsValidHandle(m, handle) ? &handle() : nullptr;
}

}  // namespace voxelfair
