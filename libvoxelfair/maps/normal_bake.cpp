// Tangent-space normal map baking through the shared atlas; the contract is in normal_bake.h.
#include "maps/normal_bake.h"

#include "atlas/edge_adjacency.h"
#include "atlas/texel_raster.h"
#include "maps/mikktspace.h"
#include "base/parallel_bands.h"
#include "maps/surface_walk.h"
#include "maps/texel_dilation.h"
#include "maps/texel_frames.h"
#include "maps/uv_face_index.h"
#include "maps/normal_gutter.h"
#include "base/simd_variant.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <future>

#include <glm/geometric.hpp>

#if VOXELFAIR_SSE2
#include <emmintrin.h>
#endif

namespace voxelfair {

namespace {

constexpr double kMargin = -1.0 / 256;  // the base colour bake's overlap rule (atlas/bake.cpp)

void validate(const NormalBakeMesh &m, const char *what) {
    if (m.faceCount == 0)
        throw MeshError(std::string("the ") + what + " mesh has no faces");
    if (!m.positions || !m.normals || !m.triangles || !m.wedgeUv)
        throw MeshError(std::string("the ") + what +
                        " mesh lacks positions, normals, triangles or texture coordinates");
    for (size_t i = 0; i < 3 * m.faceCount; ++i)
        if (m.triangles[i] >= m.vertexCount)
            throw MeshError(std::string("the ") + what + " mesh has a vertex index out of range (face " +
                            std::to_string(i / 3) + ")");
}

}  // namespace

std::vector<glm::vec4> targetTangents(const NormalBakeMesh &target) {
    std::vector<glm::vec3> positions(3 * target.faceCount), normals(3 * target.faceCount);
    for (size_t c = 0; c < 3 * target.faceCount; ++c) {
        positions[c] = target.positions[target.triangles[c]];
        const glm::vec3 n = target.normals[target.triangles[c]];
        const float length = glm::length(n);
        normals[c] = length > 0.0f ? n / length : n;
    }
    TangentInput input;
    input.positions = positions.data();
    input.normals = normals.data();
    input.uvs = target.wedgeUv;
    input.triangleCount = target.faceCount;
    return computeMikkTSpaceTangents(input);
}

glm::vec3 applyNormalMapTexel(glm::vec3 texel, glm::vec3 n, glm::vec4 t) {
    const glm::vec3 N = glm::normalize(n), T = glm::normalize(glm::vec3(t));
    const glm::vec3 B = (t.w < 0.0f ? -1.0f : 1.0f) * glm::cross(N, T);
    return glm::normalize(texel.x * T + texel.y * B + texel.z * N);
}

// The bake's work, as it is and (GCC on x86) under the target "avx2" (normal_bake_work.h).
namespace {
namespace baseline {
#include "maps/normal_bake_work.h"
}  // namespace baseline
#if VOXELFAIR_SSE2 && defined(__GNUC__) && !defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
#define VOXELFAIR_BAKE_AVX2 1
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
#include "maps/normal_bake_work.h"
}  // namespace avx2
#pragma GCC pop_options
const bool kBakeAvx2 = __builtin_cpu_supports("avx2");
#endif
}  // namespace

int normalMapScale(const NormalBakeOptions &options) {
    const int longSide = std::max(options.width, options.height);
    int scale = 1;
    while (options.level == 0 && scale < 4 && longSide * scale < options.minSide && longSide * scale * 2 <= 16384)
        scale *= 2;
    return scale;
}

NormalMap bakeNormalMap(const NormalBakeMesh &source, const NormalBakeMesh &target, const NormalBakeOptions &options) {
    validate(source, "source");
    validate(target, "target");
    if (options.width < 1 || options.width > 16384 || options.height < 0 || options.height > 16384)
        throw OptionError("the normal map's sides must be between 1 and 16384 texels");
    if (options.level < 0 || options.level > 1)
        throw OptionError("the normal map's level must be 0 (the atlas' size) or 1 (half each side)");
    if (options.minSide < 0)
        throw OptionError("the normal map's minimum side must be 0 (the atlas' size) or more");
    // Level 1: one texel per 2 x 2 block (a side of odd length gets a last half block); level 0:
    // f texels per atlas texel each side.
    const int scale = normalMapScale(options);
    const int width = ((options.width + options.level) >> options.level) * scale,
              height =
                  (((options.height > 0 ? options.height : options.width) + options.level) >> options.level) * scale;
#if VOXELFAIR_BAKE_AVX2
    if (kBakeAvx2)
        return avx2::bakeNormalMapWork(source, target, options, width, height, scale);
#endif
    return baseline::bakeNormalMapWork(source, target, options, width, height, scale);
}

}  // namespace voxelfair
