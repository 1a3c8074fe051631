// MeshLab's other smoothers run exactly as MeshLab 2020.09's filters run them (filter_unsharp.cpp),
// with vcglib in the same process as ours, for side-by-side figures:
//   "HC Laplacian Smooth"  UpdateFlags::FaceBorderFromNone; n = UpdateSelection::VertexFromFaceStrict;
//                          Smooth::VertexCoordLaplacianHC(m, 1, n > 0)       (no parameters)
//   "TwoStep Smooth"       Clean::RemoveUnreferencedVertex; UpdateSelection::VertexFromFaceStrict;
//                          stepSmoothNum times: UpdateNormal::PerFaceNormalized and
//                          Smooth::VertexCoordPasoDoble(m, stepNormalNum, cos(normalThr), stepFitNum)
//                          defaults 3, 60 degrees, 20, 20 (Belyaev and Ohtake's two-step scheme)
//   "Taubin Smooth"        see vcg_taubin.h (lambda 0.5, mu -0.53, 10 steps)
// Like MeshLab, on the triangle mesh (quads split along a-c). Only with VOXELFAIR_HAVE_VCGLIB.
#pragma once

#ifdef VOXELFAIR_HAVE_VCGLIB

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "smoothers/vcg_arrays.h"

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/smooth.h>
#include <vcg/complex/algorithms/update/flag.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/algorithms/update/topology.h>

namespace voxelfair::vcgsmooth {

class Vertex;
class Face;
struct UsedTypes : vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType> {};
// The components the three filters need (float like MeshLab's CMeshO).
class Vertex : public vcg::Vertex<UsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::VFAdj,
                                  vcg::vertex::Mark, vcg::vertex::BitFlags> {};
class Face : public vcg::Face<UsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::VFAdj, vcg::face::Mark,
                              vcg::face::BitFlags> {};
class Mesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face>> {};

using vcgarrays::build;  // positions and triangles into a Mesh (vcg_arrays.h)

inline void hcLaplacian(std::vector<glm::vec3> &positions, const std::vector<uint32_t> &triangles) {
    Mesh m;
    build(m, positions, triangles);
    vcg::tri::UpdateFlags<Mesh>::FaceBorderFromNone(m);
    const size_t selected = vcg::tri::UpdateSelection<Mesh>::VertexFromFaceStrict(m);
    vcg::tri::Smooth<Mesh>::VertexCoordLaplacianHC(m, 1, selected > 0);
    vcgarrays::readPositions(m, positions);
}

struct TwoStepSettings {
    int stepSmoothNum = 3;
    float normalThresholdDegrees = 60.0f;
    int stepNormalNum = 20;
    int stepFitNum = 20;
};

// (Every vertex of a voxel surface is referenced: RemoveUnreferencedVertex leaves the indices.)
inline void twoStep(std::vector<glm::vec3> &positions, const std::vector<uint32_t> &triangles,
                    const TwoStepSettings &s = {}) {
    Mesh m;
    build(m, positions, triangles);
    vcg::tri::UpdateTopology<Mesh>::VertexFace(m);  // MeshLab's MM_VERTFACETOPO
    vcg::tri::UpdateSelection<Mesh>::VertexFromFaceStrict(m);
    float sigma = std::cos(s.normalThresholdDegrees * 3.14159265f / 180.0f);
    if (sigma < 0)
        sigma = 0;
    for (int i = 0; i < s.stepSmoothNum; ++i) {
        vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(m);
        vcg::tri::Smooth<Mesh>::VertexCoordPasoDoble(m, s.stepNormalNum, sigma, s.stepFitNum, false);
    }
    vcgarrays::readPositions(m, positions);
}

}  // namespace voxelfair::vcgsmooth

#endif  // VOXELFAIR_HAVE_VCGLIB
