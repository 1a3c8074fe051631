// The tangent-space texels of one target triangle solved together: the texel stores the unit
// solution c of c.x T + c.y B + c.z N = n, where N and T are the triangle's vertex normals and
// MikkTSpace tangents interpolated at the texel and normalised, B = sign * cross(N, T), and n the
// source normal found for it (normal_bake.h): the exact inverse of the glTF / Blender /
// MikkTSpace pixel shader. The texels are gathered in flat arrays (weights, source normals) and
// solved in one branch-free loop that the compiler vectorises (4 texels per SSE instruction);
// texel_frames.cpp is compiled with -fno-math-errno for that (sqrt without errno).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace voxelfair {

// A target triangle's shading frame: corner normals and tangents (any non-zero length), the
// bitangent sign.
struct TargetFrame {
    float n[3][3], t[3][3];  // [corner][axis]
    float sign;
};

// Texels gathered for one solve: barycentric weights (l1, l2; l0 = 1 - l1 - l2), the source
// normal (zero: none), the caller's two indices; then the results.
struct TexelBatch {
    std::vector<float> l1, l2, nx, ny, nz;
    std::vector<uint32_t> stateIndex, imageIndex;
    std::vector<uint32_t> colour;  // R | G << 8 | B << 16 | 255 << 24, each (c + 1) / 2 * 255
    std::vector<uint8_t> solved;   // 1: colour holds the texel; 0: no frame (see solveTexelBatch)
    size_t size = 0;
    // Room for `count` texels in every array (grown once, kept between triangles).
    void reserve(size_t count) {
        if (count <= l1.size())
            return;
        for (auto *v : {&l1, &l2, &nx, &ny, &nz})
            v->resize(count);
        stateIndex.resize(count), imageIndex.resize(count), colour.resize(count), solved.resize(count);
    }
    // Within the room reserve() made.
    void push(float w1, float w2, const glm::vec3 &n, uint32_t state, uint32_t image) {
        l1[size] = w1, l2[size] = w2, nx[size] = n.x, ny[size] = n.y, nz[size] = n.z;
        stateIndex[size] = state, imageIndex[size] = image;
        ++size;
    }
};

// Solves texels [0, batch.size): colour and solved = 1, or solved = 0 for a texel without a frame
// (zero interpolated normal or tangent, singular basis, zero source normal).
void solveTexelBatch(const TargetFrame &frame, TexelBatch &batch);

}  // namespace voxelfair
