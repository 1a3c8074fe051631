// What an exporter needs to know about a model's parts beyond its triangles: the node tree
// (a unit's body, turret and barrel; their sections; a VOX scene's shape instances), where each
// node's pivot sits, its animation, and which way the model faces. The importer builds it
// (scene/unit_scene.h, scene/vox_export_nodes.h) and each face of the mesh keeps the index of
// its node (the per-face part), so the exporter can give every node its own faces.
//
// All transforms are in the importer's model space: right-handed, z up, one unit per voxel.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

namespace voxelfair {

// The model's front, in model space (z is always up).
enum class ModelFront {
    PlusX,   // Westwood VXL: a unit drives and aims along +x
    MinusY,  // MagicaVoxel: the editor's front view looks along +y at the model's -y side
};

struct ExportNode {
    std::string name;
    int parent = -1;  // index into ExportScene::nodes, -1 for a top-level node; parents come first
    // Node frame -> model space at the imported pose; the node frame's origin is its pivot
    // (a section's or a part's rotation origin, a VOX instance's model pivot).
    glm::mat4 world{1.0f};
    // Node frame -> model space per animation frame; empty when the node does not move. All
    // animated nodes of a scene have the same number of frames.
    std::vector<glm::mat4> frames;
};

struct ExportScene {
    std::vector<ExportNode> nodes;
    // The node of each face part (PlacedVolume::part, the per-face part the importer records);
    // empty: a part's number is its node's index.
    std::vector<int> partNodes;
    ModelFront front = ModelFront::PlusX;
    float framesPerSecond = 15.0f;  // animation frames (HVA frames, MagicaVoxel `_f`) per second

    bool empty() const { return nodes.empty(); }
    // The node of face part `part`, or -1 when there is none.
    int nodeOfPart(int part) const {
        if (partNodes.empty())
            return part >= 0 && size_t(part) < nodes.size() ? part : -1;
        return part >= 0 && size_t(part) < partNodes.size() ? partNodes[size_t(part)] : -1;
    }
    size_t frameCount() const {
        size_t n = 0;
        for (const ExportNode &node : nodes)
            n = std::max(n, node.frames.size());
        return n;
    }
};

}  // namespace voxelfair
