// VTK's answer to the same problem, for side-by-side figures: discrete marching cubes on the
// voxels (vtkDiscreteMarchingCubes, label 1 against 0) smoothed by the windowed sinc filter
// (vtkWindowedSincPolyDataFilter, Taubin, Zhang and Golub, "Optimal surface smoothing as filter
// design", ECCV 1996) with the filter's own defaults: 20 iterations, pass band 0.1, boundary
// smoothing on, feature-edge smoothing off, coordinates not normalized. Those are VTK's best here:
// on the shape families of testkit/shapes/shape_families.h (4 of each) the settings of VTK's
// label-smoothing examples (pass band 0.001, coordinates normalized, non-manifold smoothing)
// shrink the shapes by 5-38% (worst RMS 0.19-0.54 voxel), pass band 0.01 or 0.05 is worse on
// most families. Only with VOXELFAIR_HAVE_VTK (Debian's libvtk9-dev).
#pragma once

#ifdef VOXELFAIR_HAVE_VTK

#include "extraction/cavity_fill.h"
#include "volume/voxel_volume.h"

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include <vtkCellArray.h>
#include <vtkDiscreteMarchingCubes.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkPointData.h>
#include <vtkWindowedSincPolyDataFilter.h>

namespace voxelfair::vtksinc {

struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> triangles;
};

struct Settings {
    int iterations = 20;
    double passBand = 0.1;
    bool normalizeCoordinates = false;
    bool nonManifoldSmoothing = false;
    bool boundarySmoothing = true;
};

// The voxels as VTK's image (one voxel of empty padding around, voxel centres at x + 0.5 like the
// volume's own coordinates), enclosed cavities filled first as our extraction does (section 4.2:
// a hollow VXL hull would otherwise get inner walls), through discrete marching cubes, then
// `settings.iterations` of the windowed sinc filter (0: the marching-cubes surface as it is).
inline TriangleMesh smoothLikeVtk(const VoxelVolume &input, const Settings &settings = {}) {
    size_t filled = 0;
    const VoxelVolume volume = fillEnclosedCavities(input, &filled, Voxel{1, 0});
    vtkNew<vtkImageData> image;
    image->SetDimensions(volume.sizeX + 2, volume.sizeY + 2, volume.sizeZ + 2);
    image->SetOrigin(-0.5, -0.5, -0.5);
    image->SetSpacing(1.0, 1.0, 1.0);
    vtkNew<vtkUnsignedCharArray> labels;
    const size_t nx = size_t(volume.sizeX) + 2, ny = size_t(volume.sizeY) + 2, nz = size_t(volume.sizeZ) + 2;
    const size_t pointCount = nx * ny * nz;
    labels->SetNumberOfTuples(vtkIdType(pointCount));
    for (size_t z = 0; z < nz; ++z)
        for (size_t y = 0; y < ny; ++y)
            for (size_t x = 0; x < nx; ++x) {
                const bool inside = x >= 1 && y >= 1 && z >= 1 && x <= size_t(volume.sizeX) &&
                                    y <= size_t(volume.sizeY) && z <= size_t(volume.sizeZ) &&
                                    volume.solid(int(x - 1), int(y - 1), int(z - 1));
                const size_t point = (z * ny + y) * nx + x;
                labels->SetValue(vtkIdType(point), inside ? 1 : 0);
            }
    image->GetPointData()->SetScalars(labels);

    vtkNew<vtkDiscreteMarchingCubes> cubes;
    cubes->SetInputData(image);
    cubes->GenerateValues(1, 1, 1);
    cubes->ComputeNormalsOff();
    cubes->ComputeGradientsOff();
    cubes->ComputeScalarsOff();

    vtkNew<vtkWindowedSincPolyDataFilter> sinc;
    vtkNew<vtkTriangleFilter> triangles;
    if (settings.iterations > 0) {
        sinc->SetInputConnection(cubes->GetOutputPort());
        sinc->SetNumberOfIterations(settings.iterations);
        sinc->SetBoundarySmoothing(settings.boundarySmoothing);
        sinc->FeatureEdgeSmoothingOff();
        sinc->SetPassBand(settings.passBand);
        sinc->SetNonManifoldSmoothing(settings.nonManifoldSmoothing);
        sinc->SetNormalizeCoordinates(settings.normalizeCoordinates);
        triangles->SetInputConnection(sinc->GetOutputPort());
    } else {
        triangles->SetInputConnection(cubes->GetOutputPort());
    }
    triangles->Update();

    vtkPolyData *out = triangles->GetOutput();
    TriangleMesh mesh;
    mesh.positions.resize(size_t(out->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
        double p[3];
        out->GetPoint(i, p);
        mesh.positions[size_t(i)] = glm::vec3(float(p[0]), float(p[1]), float(p[2]));
    }
    vtkCellArray *polys = out->GetPolys();
    polys->InitTraversal();
    vtkNew<vtkIdList> cell;
    while (polys->GetNextCell(cell))
        if (cell->GetNumberOfIds() == 3)
            for (int k = 0; k < 3; ++k)
                mesh.triangles.push_back(uint32_t(cell->GetId(k)));
    return mesh;
}

}  // namespace voxelfair::vtksinc

#endif  // VOXELFAIR_HAVE_VTK
