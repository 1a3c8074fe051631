// Analytic solids with exact signed distance functions, and their voxelization: test models
// whose true surface is known, to measure how far a mesh built from the voxels lies from it.
//
// Coordinates are the voxel volume's own: voxel (x, y, z) is the unit cube [x, x+1] x [y, y+1]
// x [z, z+1], so lattice vertices from the surface extraction compare directly with the SDF.
// A voxel is solid when the SDF at its centre is negative. Header-only, for any test.
#pragma once

#include "volume/voxel_volume.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace voxelfair::shapes {

struct Shape {
    std::string name;
    std::function<double(const glm::dvec3 &)> sdf;  // exact signed distance, negative inside
    glm::dvec3 boundsMin{0.0}, boundsMax{0.0};      // contains the solid
    double volume = 0.0;                            // of the solid
};

inline constexpr double kPi = 3.14159265358979323846;

inline Shape sphere(const glm::dvec3 &centre, double radius) {
    Shape s;
    s.name = "sphere r" + std::to_string(int(radius));
    s.sdf = [=](const glm::dvec3 &p) { return glm::length(p - centre) - radius; };
    s.boundsMin = centre - radius;
    s.boundsMax = centre + radius;
    s.volume = 4.0 / 3.0 * kPi * radius * radius * radius;
    return s;
}

// Axis-aligned box.
inline Shape box(const glm::dvec3 &centre, const glm::dvec3 &halfExtent) {
    Shape s;
    s.name = "box";
    s.sdf = [=](const glm::dvec3 &p) {
        const glm::dvec3 q = glm::abs(p - centre) - halfExtent;
        return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
    };
    s.boundsMin = centre - halfExtent;
    s.boundsMax = centre + halfExtent;
    s.volume = 8.0 * halfExtent.x * halfExtent.y * halfExtent.z;
    return s;
}

// Ring of tube radius `minor` around a circle of radius `major` in the plane normal to `axis`.
inline Shape torus(const glm::dvec3 &centre, const glm::dvec3 &axis, double major, double minor) {
    const glm::dvec3 a = glm::normalize(axis);
    Shape s;
    s.name = "torus R" + std::to_string(int(major)) + " r" + std::to_string(int(minor));
    s.sdf = [=](const glm::dvec3 &p) {
        const glm::dvec3 w = p - centre;
        const double height = glm::dot(w, a);
        const double radial = glm::length(w - height * a);
        return std::hypot(radial - major, height) - minor;
    };
    s.boundsMin = centre - (major + minor);
    s.boundsMax = centre + (major + minor);
    s.volume = 2.0 * kPi * kPi * major * minor * minor;
    return s;
}

// Solid cylinder of `radius` around the segment a-b, with flat caps at a and b (any direction).
inline Shape cappedCylinder(const glm::dvec3 &a, const glm::dvec3 &b, double radius) {
    const double length = glm::length(b - a);
    const glm::dvec3 u = (b - a) / length;
    Shape s;
    s.name = "cylinder r" + std::to_string(int(radius));
    s.sdf = [=](const glm::dvec3 &p) {
        const glm::dvec3 w = p - a;
        const double t = glm::dot(w, u);
        // 2D box distance in (radial, axial) coordinates.
        const double qr = glm::length(w - t * u) - radius;
        const double qa = std::fabs(t - 0.5 * length) - 0.5 * length;
        return std::hypot(std::max(qr, 0.0), std::max(qa, 0.0)) + std::min(std::max(qr, qa), 0.0);
    };
    s.boundsMin = glm::min(a, b) - radius;
    s.boundsMax = glm::max(a, b) + radius;
    s.volume = kPi * radius * radius * length;
    return s;
}

// The voxels whose centre is inside `shape`, in a volume just large enough to hold its bounds
// (the shape must lie at non-negative coordinates; parts below 0 are cut off). `payload` gives
// each solid voxel its colour/normal.
inline VoxelVolume voxelize(
    const Shape &shape, const std::function<Voxel(int, int, int)> &payload = [](int, int, int) {
        return Voxel{1, 0};
    }) {
    const glm::ivec3 size = glm::max(glm::ivec3(glm::ceil(shape.boundsMax)) + 1, glm::ivec3(1));
    const glm::ivec3 lo = glm::max(glm::ivec3(glm::floor(shape.boundsMin)) - 1, glm::ivec3(0));
    VoxelVolumeBuilder builder(size.x, size.y, size.z);
    for (int y = lo.y; y < size.y; ++y)
        for (int x = lo.x; x < size.x; ++x)
            for (int z = lo.z; z < size.z; ++z)
                if (shape.sdf(glm::dvec3(x + 0.5, y + 0.5, z + 0.5)) < 0.0)
                    builder.add(x, y, z, payload(x, y, z));
    return builder.finish();
}

}  // namespace voxelfair::shapes
