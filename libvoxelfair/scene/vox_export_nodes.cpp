// See vox_export_nodes.h.
#include "scene/vox_export_nodes.h"

#include "scene/vox_scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace voxelfair {

namespace {

glm::mat4 pivotToModel(const VoxFile &file, const VoxInstance &instance) {
    const VoxelVolume &v = file.models[size_t(instance.model)];
    return glm::translate(instance.toModel, glm::vec3(v.sizeX / 2, v.sizeY / 2, v.sizeZ / 2));
}

}  // namespace

ExportScene voxExportNodes(const VoxFile &file, int frame) {
    ExportScene scene;
    scene.front = ModelFront::MinusY;
    const VoxelScene placed = voxScene(file, VoxSceneOptions{frame});
    const std::vector<VoxInstance> shown = voxInstances(file, frame);
    for (size_t i = 0; i < shown.size(); ++i) {
        ExportNode node;
        node.name = i < placed.parts.size() ? placed.parts[i].name : "model " + std::to_string(shown[i].model);
        node.world = pivotToModel(file, shown[i]);
        scene.nodes.push_back(node);
    }
    if (file.frameCount <= 1 || file.nodes.empty())
        return scene;  // a PACK's frames are other models

    std::vector<std::vector<glm::mat4>> frames(shown.size());
    for (int f = 0; f < file.frameCount; ++f) {
        const std::vector<VoxInstance> at = voxInstances(file, f);
        if (at.size() != shown.size())
            return scene;
        for (size_t i = 0; i < at.size(); ++i) {
            if (at[i].model != shown[i].model)
                return scene;
            frames[i].push_back(pivotToModel(file, at[i]));
        }
    }
    for (size_t i = 0; i < shown.size(); ++i) {
        bool moves = false;
        for (const glm::mat4 &m : frames[i])
            moves = moves || m != frames[i][0];
        if (moves)
            scene.nodes[i].frames = std::move(frames[i]);
    }
    return scene;
}

}  // namespace voxelfair
