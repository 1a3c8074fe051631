// Input of the texture atlas (paper §4.5): the triangle-mesh view of mesh/triangle_mesh.h with
// the atlas's own per-face and per-vertex arrays, in the style of xatlas::MeshDecl. Nothing is
// copied; the arrays must outlive the stage calls. The atlas's output (charts, per-corner UVs,
// the texture) is its own (charts.h, packing.h, bake.h).
//
// The pipeline's meshes are voxel surfaces (closed quads split along a-c, so triangles 2k and
// 2k+1 come from quad k), but nothing here assumes that: any triangle mesh is accepted.
//
// Errors follow the library's rule (base/error.h, doc/architecture.md): invalid arrays throw
// MeshError, options out of range OptionError; a mesh without faces is no error, every stage
// returns an empty result for it.
#pragma once

#include "mesh/triangle_mesh.h"

#include <cstddef>
#include <cstdint>

#include <glm/gtc/type_precision.hpp>
#include <glm/vec3.hpp>

namespace voxelfair {

struct AtlasMesh : TriangleMesh {
    // Optional. The crisp colour source: each face's voxel colour.
    const glm::u8vec3 *faceColours = nullptr;
    // Optional. Smoothed per-vertex colours (§4.4), for the paper's Gouraud bake.
    const glm::u8vec3 *vertexColours = nullptr;
    // Optional. Face normals (any length); computed from the positions when null, or for a face
    // whose given normal is zero or not finite.
    const glm::vec3 *faceNormals = nullptr;
    // Optional. Per face, a factor on the texel density (positive, finite): a model whose parts
    // have different voxel sizes (an HVA frame can shrink a section to 1%) passes largest voxel
    // size / the face's part's voxel size, so every part's voxels get the same texels per voxel.
    // A chart never mixes factors; stretch is measured against each face's own density.
    const float *faceTexelScale = nullptr;
};

// Checks what every stage relies on: throws MeshError naming the first bad face (mesh/
// validate(), then the texel scales). A mesh without faces passes.
void validateAtlasMesh(const AtlasMesh &mesh);

}  // namespace voxelfair
