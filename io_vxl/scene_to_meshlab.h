// Copies a SceneSurface into a MeshLab mesh: each quad becomes a MeshLab polygon (two triangles
// whose shared diagonal is faux), with the voxel's colour and the part (section) per face.
#pragma once

#include "scene/voxel_scene.h"

#include <common/meshmodel.h>

namespace voxelfair {

// Name of the per-face int attribute holding the part (VXL section, VOX instance) of each face.
// The same number is written to the face quality, which MeshLab's PLY exporter can save.
constexpr const char *kPartAttributeName = "voxelfair_part";

// The MeshLab import mask for what sceneToMeshLab fills.
int sceneImportMask();

// Replaces the content of `model` with `surface`. `model` must have had Enable(sceneImportMask()).
void sceneToMeshLab(const SceneSurface &surface, MeshModel &model);

}  // namespace voxelfair
