// How far a triangle mesh lies from an analytic shape's true surface: distances from points
// sampled uniformly by area on the mesh to the shape (its exact SDF), and the enclosed volume.
// Header-only, for any test.
#pragma once

#include "shapes/analytic_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace voxelfair::shapes {

struct SurfaceError {
    double rms = 0.0;                  // root mean square distance of the samples to the true surface
    double max = 0.0;                  // largest |distance| among the samples
    double bias = 0.0;                 // mean signed distance: > 0 = the mesh lies outside on average
    double volume = 0.0;               // enclosed by the mesh
    double volumeChangePercent = 0.0;  // (mesh volume - true volume) / true volume * 100
};

// Volume enclosed by a closed, outward-wound triangle mesh (divergence theorem).
inline double enclosedVolume(const std::vector<glm::vec3> &positions, const std::vector<uint32_t> &triangles) {
    double sixVolume = 0.0;
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const glm::dvec3 a = positions[triangles[t]], b = positions[triangles[t + 1]], c = positions[triangles[t + 2]];
        sixVolume += glm::dot(a, glm::cross(b, c));
    }
    return sixVolume / 6.0;
}

// `sampleCount` points, uniform by area (triangle picked by area, then uniform barycentrics),
// from a fixed-seed generator: the same mesh always gives the same figures.
inline SurfaceError measureSurfaceError(const std::vector<glm::vec3> &positions, const std::vector<uint32_t> &triangles,
                                        const Shape &shape, size_t sampleCount = 200000, uint64_t seed = 20100808) {
    SurfaceError e;
    e.volume = enclosedVolume(positions, triangles);
    e.volumeChangePercent = (e.volume - shape.volume) / shape.volume * 100.0;
    const size_t triangleCount = triangles.size() / 3;
    if (triangleCount == 0 || sampleCount == 0)
        return e;

    std::vector<double> cumulativeArea(triangleCount);
    double total = 0.0;
    for (size_t t = 0; t < triangleCount; ++t) {
        const glm::dvec3 a = positions[triangles[3 * t]], b = positions[triangles[3 * t + 1]],
                         c = positions[triangles[3 * t + 2]];
        total += 0.5 * glm::length(glm::cross(b - a, c - a));
        cumulativeArea[t] = total;
    }

    std::mt19937_64 random(seed);
    auto uniform = [&random] { return double(random() >> 11) * 0x1.0p-53; };  // [0, 1), portable
    double sum2 = 0.0, sum = 0.0;
    for (size_t i = 0; i < sampleCount; ++i) {
        const size_t t = std::min<size_t>(
            std::upper_bound(cumulativeArea.begin(), cumulativeArea.end(), uniform() * total) - cumulativeArea.begin(),
            triangleCount - 1);
        const glm::dvec3 a = positions[triangles[3 * t]], b = positions[triangles[3 * t + 1]],
                         c = positions[triangles[3 * t + 2]];
        const double s = std::sqrt(uniform()), r = uniform();
        const glm::dvec3 p = (1.0 - s) * a + s * (1.0 - r) * b + s * r * c;
        const double d = shape.sdf(p);
        sum += d;
        sum2 += d * d;
        e.max = std::max(e.max, std::fabs(d));
    }
    e.rms = std::sqrt(sum2 / double(sampleCount));
    e.bias = sum / double(sampleCount);
    return e;
}

}  // namespace voxelfair::shapes
