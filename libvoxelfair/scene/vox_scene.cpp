#include "scene/vox_scene.h"

#include "formats/format_error.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

namespace voxelfair {

namespace {

// The keyframe in effect at `frame`: the last with key.frame <= frame, else the first.
template <class Key>
const Key &keyAt(const std::vector<Key> &keys, int frame) {
    const auto after =
        std::upper_bound(keys.begin(), keys.end(), frame, [](int f, const Key &k) { return f < k.frame; });
    return after == keys.begin() ? keys.front() : *(after - 1);
}

glm::mat4 centredOnPivot(const VoxelVolume &model) {
    // Integer division: the pivot of an odd side is the voxel corner just below its centre.
    const glm::ivec3 pivot(model.sizeX / 2, model.sizeY / 2, model.sizeZ / 2);
    return glm::translate(glm::mat4(1.0f), -glm::vec3(pivot));
}

// Depth-first walk below one node. The reader checked the graph (no cycles, depth and instance
// count bounded), so the recursion terminates and stays shallow.
class GraphWalk {
public:
    GraphWalk(const VoxFile &file, int frame) : file_(file), frame_(frame) {
        for (const VoxLayer &layer : file.layers)
            if (layer.hidden)
                hiddenLayers_.push_back(layer.id);
    }

    std::vector<VoxInstance> run() {
        visit(file_.root, glm::mat4(1.0f), nullptr, -1);
        return std::move(instances_);
    }

private:
    void visit(int index, const glm::mat4 &toWorld, const std::string *name, int layer) {
        const VoxNode &node = file_.nodes[size_t(index)];
        if (node.hidden)
            return;
        switch (node.kind) {
        case VoxNodeKind::Transform: {
            if (std::find(hiddenLayers_.begin(), hiddenLayers_.end(), node.layer) != hiddenLayers_.end())
                return;
            const glm::mat4 placed = toWorld * keyAt(node.transformKeys, frame_).transform;
            visit(node.children.front(), placed, node.name.empty() ? name : &node.name, node.layer);
            break;
        }
        case VoxNodeKind::Group:
            for (int child : node.children)
                visit(child, toWorld, name, layer);
            break;
        case VoxNodeKind::Shape: {
            VoxInstance instance;
            instance.model = keyAt(node.shapeKeys, frame_).model;
            instance.toModel = toWorld * centredOnPivot(file_.models[size_t(instance.model)]);
            if (name != nullptr)
                instance.name = *name;
            instance.layer = layer;
            instances_.push_back(std::move(instance));
            break;
        }
        }
    }

    const VoxFile &file_;
    int frame_;
    std::vector<int> hiddenLayers_;
    std::vector<VoxInstance> instances_;
};

}  // namespace

std::vector<VoxInstance> voxInstances(const VoxFile &file, int frame) {
    if (frame < 0 || frame >= file.frameCount)
        throw FormatError("there is no frame " + std::to_string(frame) + " (the file has " +
                          std::to_string(file.frameCount) + " frames, numbered from 0)");
    if (file.root >= 0)
        return GraphWalk(file, frame).run();

    std::vector<VoxInstance> instances;
    for (size_t m = 0; m < file.models.size(); ++m) {
        if (file.packed && m != size_t(frame))
            continue;
        VoxInstance instance;
        instance.model = int(m);
        instance.toModel = centredOnPivot(file.models[m]);
        instances.push_back(std::move(instance));
    }
    return instances;
}

VoxelScene voxScene(const VoxFile &file, const VoxSceneOptions &options) {
    VoxelScene scene;
    scene.palette = file.palette;
    const std::vector<VoxInstance> instances = voxInstances(file, options.frame);
    scene.parts.reserve(instances.size());
    for (size_t i = 0; i < instances.size(); ++i) {
        const VoxInstance &instance = instances[i];
        PlacedVolume part;
        part.volume = &file.models[size_t(instance.model)];
        part.toModel = instance.toModel;
        part.part = int(i);
        part.name = instance.name.empty() ? "model " + std::to_string(instance.model) : instance.name;
        scene.parts.push_back(std::move(part));
    }
    return scene;
}

}  // namespace voxelfair
