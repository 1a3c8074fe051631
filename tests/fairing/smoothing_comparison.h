// Fidelity of the smoothers on voxelized analytic shapes (shared by tools/compare_smoothing and
// the fidelity test): voxelize, extract the boundary quads (section 4.2), smooth, and measure the
// distance of the triangulated result to the true surface (shapes/surface_error.h).
#pragma once

#include "attributes/triangulate.h"
#include "extraction/boundary_surface.h"
#include "fairing/lanczos_fairing.h"
#include "fairing/vcg_taubin.h"
#include "shapes/analytic_shapes.h"
#include "shapes/surface_error.h"

#include <string>
#include <vector>

namespace voxelfair::comparison {

// Spheres of several radii, a torus, thin and thick capped cylinders (a tank's cannon) and a
// box. Centres sit at sub-voxel offsets so no surface is aligned with the lattice by luck; the
// box is aligned on purpose (its raw surface is exact, only its edges and corners can suffer).
inline std::vector<shapes::Shape> comparisonShapes() {
    using glm::dvec3;
    std::vector<shapes::Shape> list;
    for (double r : {6.0, 12.0, 18.0, 24.0})
        list.push_back(shapes::sphere(dvec3(r + 2.31, r + 2.17, r + 2.43), r));
    list.push_back(shapes::torus(dvec3(22.37, 21.71, 8.29), dvec3(0, 0, 1), 14.0, 5.0));
    list.push_back(shapes::cappedCylinder(dvec3(3.0, 5.37, 5.61), dvec3(33.0, 5.37, 5.61), 3.0));
    list.push_back(shapes::cappedCylinder(dvec3(3.0, 8.29, 8.83), dvec3(33.0, 8.29, 8.83), 6.0));
    list.push_back(shapes::box(dvec3(12.0, 11.0, 10.0), dvec3(9.0, 8.0, 7.0)));
    return list;
}

struct Row {
    std::string shape;
    std::string method;
    shapes::SurfaceError error;
};

struct Options {
    size_t samples = 200000;
    bool taubin = true;  // when vcglib is available
};

// Raw voxel surface, one default pass of the paper's fairing, and (with vcglib) MeshLab's
// Taubin Smooth with its defaults on the same triangulation.
inline std::vector<Row> compare(const shapes::Shape &shape, const Options &options = {}) {
    const BoundarySurface surface = extractBoundarySurface(shapes::voxelize(shape));
    const size_t quadCount = surface.quadCount();
    std::vector<uint32_t> offsets(quadCount + 1);
    for (size_t q = 0; q <= quadCount; ++q)
        offsets[q] = uint32_t(4 * q);
    std::vector<uint32_t> triangles(3 * countFanTriangles(offsets.data(), quadCount));
    triangulatePolygons(surface.positions.size(), offsets.data(), surface.quads.data(), quadCount,
                        triangles.data(), nullptr);

    std::vector<Row> rows;
    auto measure = [&](const char *method, const std::vector<glm::vec3> &positions) {
        rows.push_back({shape.name, method, shapes::measureSurfaceError(positions, triangles, shape, options.samples)});
    };
    measure("raw voxels", surface.positions);

    std::vector<glm::vec3> faired = surface.positions;
    fairModifiedLanczos(faired.data(), faired.size(), offsets.data(), surface.quads.data(), quadCount, nullptr);
    measure("paper (1 pass)", faired);

#ifdef VOXELFAIR_HAVE_VCGLIB
    if (options.taubin) {
        std::vector<glm::vec3> taubin = surface.positions;
        vcgtaubin::taubinLikeMeshLab(taubin, triangles);
        measure("vcg Taubin (10)", taubin);
    }
#endif
    return rows;
}

}  // namespace voxelfair::comparison
