// Input of the texture atlas (paper section 4.5): a triangle mesh on caller-owned arrays, in the
// style of xatlas::MeshDecl. Nothing is copied; the arrays must outlive the stage calls.
//
// The pipeline's meshes are voxel surfaces (closed quads split along a-c, so triangles 2k and
// 2k+1 come from quad k), but nothing here assumes that: any triangle mesh is accepted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <glm/gtc/type_precision.hpp>
#include <glm/vec3.hpp>

namespace voxelfair {

struct AtlasMesh {
    const glm::vec3 *positions = nullptr;
    size_t vertexCount = 0;
    // Three vertex indices per face, counter-clockwise seen from outside.
    const uint32_t *triangles = nullptr;
    size_t faceCount = 0;
    // Optional. The crisp colour source: each face's voxel colour.
    const glm::u8vec3 *faceColours = nullptr;
    // Optional. Smoothed per-vertex colours (section 4.4), for the paper's Gouraud bake.
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

enum class AtlasStatus {
    Ok,
    EmptyMesh,     // no faces: every stage returns an empty result
    InvalidInput,  // null arrays with non-zero counts, or a vertex index out of range
};

const char *toString(AtlasStatus status);

// Checks what every stage relies on; `message` says what is wrong when the result is not Ok.
AtlasStatus validateAtlasMesh(const AtlasMesh &mesh, std::string *message);

}  // namespace voxelfair
