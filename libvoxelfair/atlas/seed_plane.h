// The projection of a chart onto its seed plane (paper section 4.5, equation 11).
//
// The paper rotates the seed normal onto the z axis with two Euler angles and keeps x, y; the
// authors' later code uses one Rodrigues rotation (doc/method.md §6c). Any rotation taking the
// seed normal to +Z gives the same orthographic projection up to an in-plane rotation, which the
// packer may change anyway. We take the orthonormal basis of Duff et al., "Building an
// Orthonormal Basis, Revisited" (JCGT 2017): continuous, branch-light, and for the six axis
// directions of voxel faces its tangents are axes too, so voxel edges land on texel rows and
// columns. (t1, t2, n) is right-handed, so a face counter-clockwise seen from outside stays
// counter-clockwise in UV.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace voxelfair {

struct SeedPlane {
    glm::dvec3 t1, t2;  // u and v axes; n = t1 x t2 is the seed normal
};

inline SeedPlane seedPlane(const glm::dvec3 &n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    return {glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), glm::dvec3(b, sign + n.y * n.y * a, -n.y)};
}

// Point p on the plane, relative to `origin`, times the texel scale: the one expression every
// projection of a chart uses, so a vertex shared by two of its faces gets the same UV bits.
inline glm::vec2 projectOnPlane(const SeedPlane &plane, const glm::dvec3 &origin, const glm::vec3 &p, double scale) {
    const glm::dvec3 d = glm::dvec3(p) - origin;
    return glm::vec2(glm::dvec2(glm::dot(d, plane.t1), glm::dot(d, plane.t2)) * scale);
}

}  // namespace voxelfair
