// Copies a SceneSurface into a MeshLab mesh: each quad becomes a MeshLab polygon (two triangles
// whose shared diagonal is faux), with the voxel's colour and the part (section) per face.
#pragma once

#include "export/export_scene.h"
#include "scene/voxel_scene.h"

#include <common/meshmodel.h>
#include <vcg/complex/allocate.h>

namespace voxelfair {

// Name of the per-face int attribute holding the part (VXL section, VOX instance) of each face.
// The same number is written to the face quality, which MeshLab's PLY exporter can save.
constexpr const char *kPartAttributeName = "voxelfair_part";

// The MeshLab import mask for what sceneToMeshLab fills.
int sceneImportMask();

// Replaces the content of `model` with `surface`. `model` must have had Enable(sceneImportMask()).
void sceneToMeshLab(const SceneSurface &surface, MeshModel &model);

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
