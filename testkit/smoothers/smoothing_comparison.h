// Fidelity of the smoothers on voxelized analytic shapes (shared by tools/compare_smoothing,
// tools/comparison_report and the fidelity tests): voxelize, extract the boundary quads (section
// 4.2), smooth, and measure the distance of the triangulated result to the true surface
// (shapes/surface_error.h). The line-up: raw voxels, the paper's pass, MeshLab's Taubin Smooth, HC
// Laplacian Smooth and TwoStep Smooth as MeshLab runs them (with vcglib), VTK's discrete marching
// cubes + windowed sinc (with VTK), and the constrained mode.
#pragma once

#include "attributes/triangulate.h"
#include "extraction/boundary_surface.h"
#include "fairing/constrained_fairing.h"
#include "fairing/lanczos_fairing.h"
#include "smoothers/vcg_smoothers.h"
#include "smoothers/vcg_taubin.h"
#include "smoothers/vtk_windowed_sinc.h"
#include "shapes/analytic_shapes.h"
#include "checks/surface_error.h"

#include <algorithm>
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

// A wider set for the second mode (constrained_fairing.h), so nothing is tuned to one input:
// spheres of radius 6 to 24 at three sub-voxel offsets each (the last one puts the centre on a
// voxel centre in x and y), tori with axes along z, x and (1, 1, 1), capped cylinders of radius 3
// to 6 along each axis, and lattice-aligned boxes down to 2 voxels thin.
struct FamilyShape {
    std::string family;  // "sphere", "torus", "cylinder", "box"
    shapes::Shape shape;
    double size = 0.0;  // sphere radius, torus major radius, cylinder radius, box smallest side
};

inline std::vector<FamilyShape> fidelityShapes() {
    using glm::dvec3;
    std::vector<FamilyShape> list;
    const dvec3 offsets[3] = {{0.31, 0.17, 0.43}, {0.77, 0.52, 0.09}, {0.5, 0.5, 0.0}};
    for (double r : {6.0, 9.0, 12.0, 18.0, 24.0})
        for (int i = 0; i < 3; ++i) {
            list.push_back({"sphere", shapes::sphere(dvec3(r + 2.0) + offsets[i], r), r});
            list.back().shape.name += std::string(" ") + "abc"[i];
        }
    list.push_back({"torus", shapes::torus(dvec3(22.37, 21.71, 8.29), dvec3(0, 0, 1), 14.0, 5.0), 14.0});
    list.push_back({"torus", shapes::torus(dvec3(8.61, 16.13, 16.55), dvec3(1, 0, 0), 12.0, 4.0), 12.0});
    list.push_back({"torus", shapes::torus(dvec3(24.2, 24.7, 24.4), dvec3(1, 1, 1), 16.0, 6.0), 16.0});
    for (double r : {3.0, 4.0, 5.0, 6.0})
        for (int axis = 0; axis < 3; ++axis) {
            dvec3 a(r + 2.37, r + 2.61, r + 2.83), b = a;
            a[axis] = 3.0;
            b[axis] = 33.0;
            list.push_back({"cylinder", shapes::cappedCylinder(a, b, r), r});
            list.back().shape.name += std::string(" ") + "xyz"[axis];
        }
    const dvec3 boxes[4][2] = {
        {{12, 11, 10}, {9, 8, 7}}, {{5, 6, 7}, {3, 4, 5}}, {{4, 4, 4}, {1, 1, 1}}, {{10, 10, 10}, {6, 1, 3}}};
    for (const auto &b : boxes) {
        list.push_back({"box", shapes::box(b[0], b[1]), 2.0 * std::min({b[1].x, b[1].y, b[1].z})});
        list.back().shape.name += " " + std::to_string(int(2 * b[1].x)) + "x" + std::to_string(int(2 * b[1].y)) + "x" +
                                  std::to_string(int(2 * b[1].z));
    }
    return list;
}

struct Row {
    std::string shape;
    std::string method;
    shapes::SurfaceError error;
};

struct Options {
    size_t samples = 200000;
    bool taubin = true;        // when vcglib is available
    bool otherMeshLab = true;  // HC Laplacian and TwoStep, when vcglib is available
    bool vtk = true;           // when VTK is available
};

inline constexpr const char kConstrainedMethod[] = "constrained";

// Method names of the rows (in this order; some only with vcglib or VTK).
inline constexpr const char kRawMethod[] = "raw voxels", kPaperMethod[] = "paper (1 pass)",
                            kTaubinMethod[] = "vcg Taubin (10)", kHcMethod[] = "vcg HC Laplacian",
                            kTwoStepMethod[] = "vcg TwoStep", kVtkMethod[] = "VTK windowed sinc";

// A voxel boundary's quads as the library's polygon view takes them (quad q is corners 4q .. 4q+3,
// mesh/polygon_mesh.h) and their fan triangles (attributes/triangulate.h): the mesh every smoother
// moves and every row is measured on.
struct QuadFan {
    std::vector<uint32_t> offsets, triangles;
};

inline QuadFan quadFan(const BoundarySurface &surface) {
    const size_t quadCount = surface.quadCount();
    QuadFan fan;
    fan.offsets.resize(quadCount + 1);
    for (size_t q = 0; q <= quadCount; ++q)
        fan.offsets[q] = uint32_t(4 * q);
    fan.triangles.resize(3 * countFanTriangles({nullptr, 0, fan.offsets.data(), nullptr, quadCount}));
    triangulatePolygons({nullptr, surface.positions.size(), fan.offsets.data(), surface.quads.data(), quadCount},
                        fan.triangles.data(), nullptr);
    return fan;
}

// Raw voxel surface, one default pass of the paper's fairing, (with vcglib) MeshLab's Taubin, HC
// Laplacian and TwoStep Smooth with their defaults on the same triangulation, (with VTK) VTK's
// windowed sinc on its own marching-cubes surface, and the second mode with its defaults.
inline std::vector<Row> compare(const shapes::Shape &shape, const Options &options = {}) {
    const VoxelVolume volume = shapes::voxelize(shape);
    const BoundarySurface surface = extractBoundarySurface(volume);
    const size_t quadCount = surface.quadCount();
    const QuadFan fan = quadFan(surface);
    const std::vector<uint32_t> &offsets = fan.offsets, &triangles = fan.triangles;

    std::vector<Row> rows;
    auto measure = [&](const char *method, const std::vector<glm::vec3> &positions) {
        rows.push_back({shape.name, method, shapes::measureSurfaceError(positions, triangles, shape, options.samples)});
    };
    measure(kRawMethod, surface.positions);

    std::vector<glm::vec3> faired = surface.positions;
    fairModifiedLanczos({faired.data(), faired.size(), offsets.data(), surface.quads.data(), quadCount}, nullptr);
    measure(kPaperMethod, faired);

#ifdef VOXELFAIR_HAVE_VCGLIB
    if (options.taubin) {
        std::vector<glm::vec3> taubin = surface.positions;
        vcgtaubin::taubinLikeMeshLab(taubin, triangles);
        measure(kTaubinMethod, taubin);
    }
    if (options.otherMeshLab) {
        std::vector<glm::vec3> hc = surface.positions;
        vcgsmooth::hcLaplacian(hc, triangles);
        measure(kHcMethod, hc);
        std::vector<glm::vec3> twoStep = surface.positions;
        vcgsmooth::twoStep(twoStep, triangles);
        measure(kTwoStepMethod, twoStep);
    }
#endif
#ifdef VOXELFAIR_HAVE_VTK
    if (options.vtk) {
        const vtksinc::TriangleMesh vtk = vtksinc::smoothLikeVtk(volume);
        rows.push_back({shape.name, kVtkMethod,
                        shapes::measureSurfaceError(vtk.positions, vtk.triangles, shape, options.samples)});
    }
#endif

    std::vector<glm::vec3> constrained = surface.positions;
    fairConstrained({constrained.data(), constrained.size(), offsets.data(), surface.quads.data(), quadCount}, nullptr);
    measure(kConstrainedMethod, constrained);
    return rows;
}

}  // namespace voxelfair::comparison
