// Small vector helpers every mesh stage needs, in one place.
//
// normalizedOrZero is the exact expression the constrained fairing's SSE2 kernels reproduce bit
// for bit (fairing/constrained/vec3_simd.h): v * (1 / sqrt(dot(v, v))), dot = (x x + y y) + z z.
#pragma once

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace voxelfair {

inline bool isFinite(const glm::vec3 &p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// v scaled to unit length; (0, 0, 0) when v is zero, not finite, or its squared length overflows.
inline glm::vec3 normalizedOrZero(const glm::vec3 &v) {
    const float length2 = glm::dot(v, v);
    return length2 > 0.0f && length2 <= std::numeric_limits<float>::max() ? v * (1.0f / std::sqrt(length2))
                                                                          : glm::vec3(0.0f);
}

}  // namespace voxelfair
