// A MagicaVoxel scene's parts for exporters (export/export_scene.h): one node per shape instance
// shown at the imported frame, named as the importer names its part (the scene graph's `_name`,
// else "model N"), its pivot at the model's pivot floor(size / 2) (MagicaVoxel turns a model
// about it). When the file is animated (`_f` keyframes or a PACK) and every frame shows the same
// models in the same order, the nodes carry one transform per frame.
#pragma once

#include "export/export_scene.h"
#include "formats/vox.h"

namespace voxelfair {

// Part i of voxScene(file, {frame}) is node i. Throws FormatError when the frame is out of range.
ExportScene voxExportNodes(const VoxFile &file, int frame);

}  // namespace voxelfair
