// Places a parsed .vox file's models for one animation frame: the scene graph flattened to shape
// instances, then a VoxelScene. Coordinates stay MagicaVoxel's (z up, one unit per voxel).
#pragma once

#include "formats/vox.h"
#include "scene/voxel_scene.h"

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

namespace voxelfair {

// One shown shape: a model placed in world space.
struct VoxInstance {
    int model = 0;  // index into VoxFile::models
    // Voxel coordinates -> world: the model's pivot floor(size / 2) moved to the origin (ogt_vox's
    // convention, so rotations turn the model about its centre), then the transforms of the path
    // from the root, innermost first.
    glm::mat4 toModel{1.0f};
    std::string name;  // `_name` of the nearest named transform above the shape, or empty
    int layer = -1;    // the layer of the shape's own transform, -1 for none
};

// The visible shapes at `frame` (0 <= frame < file.frameCount), in depth-first file order.
//  * Each transform and shape uses its keyframe with the largest `_f` <= frame, as MagicaVoxel
//    does (before its first keyframe, the first one).
//  * A shape is left out when a node on its path is hidden or a transform on its path is in a
//    hidden layer.
//  * Without a scene graph: every model at its pivot-centred position, unrotated; for a PACK
//    animation only model `frame`.
// Throws FormatError when the frame is out of range.
std::vector<VoxInstance> voxInstances(const VoxFile &file, int frame);

struct VoxSceneOptions {
    int frame = 0;  // animation frame, 0 .. VoxFile::frameCount - 1
};

// One part per instance (part = instance index, name = the instance's name or "model N"), with
// the file's palette. The parts point into `file.models`: keep the file alive with the scene.
VoxelScene voxScene(const VoxFile &file, const VoxSceneOptions &options = {});

}  // namespace voxelfair
