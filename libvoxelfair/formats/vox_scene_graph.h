// The VOX scene graph's checks (private to the VOX reader): node references resolved, model ids
// checked, and the graph's shape bounded (MagicaVoxel's scene-graph extension; limits in vox.h).
#pragma once

#include "formats/vox.h"
#include "formats/vox_chunks.h"

#include <vector>

namespace voxelfair::vox {

// Turns the nodes' child ids (childIds[i] for file.nodes[i], read from nodeChunks[i]) into
// indices, sets file.root (node id 0), checks the shapes' model ids, then from the root: no
// cycle, at most kMaxVoxGraphDepth levels, at most kMaxVoxInstances shape instances showing at
// most kMaxVoxShownVoxels voxels. Throws FormatError naming the node and its chunk. Does nothing
// for a file without nodes.
void resolveSceneGraph(VoxFile &file, const std::vector<std::vector<int>> &childIds,
                       const std::vector<Chunk> &nodeChunks);

// 1 + the largest `_f` of the graph; without a graph, the model count of a PACK file, else 1.
int countFrames(const VoxFile &file);

}  // namespace voxelfair::vox
