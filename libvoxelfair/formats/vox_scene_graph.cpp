// See vox_scene_graph.h.
#include "formats/vox_scene_graph.h"

#include <algorithm>
#include <string>
#include <unordered_map>

namespace voxelfair::vox {

namespace {

class GraphChecks {
public:
    GraphChecks(VoxFile &file, const std::vector<Chunk> &nodeChunks) : file_(file), nodeChunks_(nodeChunks) {}

    std::string nodeLabel(size_t index) const {
        return "node " + std::to_string(file_.nodes[index].id) + " (" + nodeChunks_[index].where() + ")";
    }

    void resolve(const std::vector<std::vector<int>> &childIds) {
        std::unordered_map<int, int> indexOf;
        for (size_t i = 0; i < file_.nodes.size(); ++i)
            if (!indexOf.emplace(file_.nodes[i].id, int(i)).second)
                throw FormatError(nodeLabel(i) + ": node id " + std::to_string(file_.nodes[i].id) + " is used twice");
        const auto root = indexOf.find(0);
        if (root == indexOf.end())
            throw FormatError("the scene graph has no root (no node with id 0)");
        file_.root = root->second;

        for (size_t i = 0; i < file_.nodes.size(); ++i) {
            VoxNode &node = file_.nodes[i];
            for (int id : childIds[i]) {
                const auto child = indexOf.find(id);
                if (child == indexOf.end())
                    throw FormatError(nodeLabel(i) + " refers to child node " + std::to_string(id) +
                                      ", which the file does not define");
                node.children.push_back(child->second);
            }
            for (const VoxShapeKey &key : node.shapeKeys)
                if (key.model < 0 || size_t(key.model) >= file_.models.size())
                    throw FormatError(nodeLabel(i) + " shows model " + std::to_string(key.model) +
                                      " but the file has " + std::to_string(file_.models.size()) + " models");
        }
    }

    // Iterative, so a long chain cannot overflow the stack; shared nodes are visited once and
    // their subtree's figures reused.
    void checkShape() const {
        enum : uint8_t { kUnvisited, kOnPath, kDone };
        const size_t n = file_.nodes.size();
        size_t heldVoxels = 0;
        for (const VoxelVolume &model : file_.models)
            heldVoxels += model.voxelCount();
        const size_t maxShown = std::max(kMaxVoxShownVoxels, heldVoxels);
        std::vector<uint8_t> state(n, kUnvisited);
        std::vector<size_t> height(n, 0), instances(n, 0), shown(n, 0);
        struct Step {
            int node;
            size_t nextChild;
        };
        std::vector<Step> path{{file_.root, 0}};
        state[size_t(file_.root)] = kOnPath;
        while (!path.empty()) {
            const int current = path.back().node;
            const VoxNode &node = file_.nodes[size_t(current)];
            if (path.back().nextChild < node.children.size()) {
                const int child = node.children[path.back().nextChild++];
                if (state[size_t(child)] == kOnPath)
                    throw FormatError("the scene graph has a cycle: " + nodeLabel(size_t(child)) +
                                      " is its own descendant (through node " + std::to_string(node.id) + ")");
                if (state[size_t(child)] == kUnvisited) {
                    state[size_t(child)] = kOnPath;
                    path.push_back({child, 0});
                }
                continue;
            }
            size_t h = 0, count = node.kind == VoxNodeKind::Shape ? 1 : 0, voxels = 0;
            for (const VoxShapeKey &key : node.shapeKeys)
                voxels = std::max(voxels, file_.models[size_t(key.model)].voxelCount());
            for (int child : node.children) {
                h = std::max(h, height[size_t(child)]);
                count = std::min(count + instances[size_t(child)], kMaxVoxInstances + 1);  // saturate
                voxels = std::min(voxels + shown[size_t(child)], maxShown + 1);
            }
            height[size_t(current)] = h + 1;
            instances[size_t(current)] = count;
            shown[size_t(current)] = voxels;
            state[size_t(current)] = kDone;
            path.pop_back();
        }
        const size_t root = size_t(file_.root);
        if (height[root] > size_t(kMaxVoxGraphDepth))
            throw FormatError("the scene graph is " + std::to_string(height[root]) +
                              " levels deep, over the limit of " + std::to_string(kMaxVoxGraphDepth));
        if (instances[root] > kMaxVoxInstances)
            throw FormatError("the scene graph expands to more than " + std::to_string(kMaxVoxInstances) +
                              " shape instances");
        if (shown[root] > maxShown)
            throw FormatError("the scene graph's shape instances show more than " + std::to_string(maxShown) +
                              " voxels in all (the larger of " + std::to_string(kMaxVoxShownVoxels) +
                              " and the voxels the models hold)");
    }

private:
    VoxFile &file_;
    const std::vector<Chunk> &nodeChunks_;
};

}  // namespace

void resolveSceneGraph(VoxFile &file, const std::vector<std::vector<int>> &childIds,
                       const std::vector<Chunk> &nodeChunks) {
    if (file.nodes.empty())
        return;
    GraphChecks checks(file, nodeChunks);
    checks.resolve(childIds);
    checks.checkShape();
}

int countFrames(const VoxFile &file) {
    if (file.nodes.empty())
        return file.packed ? int(file.models.size()) : 1;
    int last = 0;
    for (const VoxNode &node : file.nodes) {
        for (const VoxTransformKey &key : node.transformKeys)
            last = std::max(last, key.frame);
        for (const VoxShapeKey &key : node.shapeKeys)
            last = std::max(last, key.frame);
    }
    return last + 1;
}

}  // namespace voxelfair::vox
