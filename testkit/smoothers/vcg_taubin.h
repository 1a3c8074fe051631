// vcglib's Taubin smoothing run exactly as MeshLab 2020.09's "Taubin Smooth" filter runs it
// (filter_unsharp.cpp, FP_TAUBIN_SMOOTH), for side-by-side figures with our fairing:
//   UpdateFlags::FaceBorderFromNone; n = UpdateSelection::VertexFromFaceStrict;
//   Smooth::VertexCoordTaubin(m, steps, lambda, mu, n > 0)     defaults 10, 0.5, -0.53.
// MeshLab meshes are triangle meshes; VertexCoordTaubin (smooth.h, AccumulateLaplacianInfo)
// uses uniform weights over every triangle edge and ignores faux flags, so a quad's diagonal is
// a neighbour like any edge: pass the same triangulation MeshLab holds (a-c diagonals).
// Only with VOXELFAIR_HAVE_VCGLIB (the vcglib::headers target).
#pragma once

#ifdef VOXELFAIR_HAVE_VCGLIB

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "smoothers/vcg_arrays.h"

// vcglib needs complex.h before its algorithms.
#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/smooth.h>
#include <vcg/complex/algorithms/update/flag.h>
#include <vcg/complex/algorithms/update/selection.h>

namespace voxelfair::vcgtaubin {

class Vertex;
class Face;
struct UsedTypes : vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType> {};
// The components Taubin needs, with float coordinates like MeshLab's CMeshO (MESHLAB_SCALAR=float).
class Vertex : public vcg::Vertex<UsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::BitFlags> {};
class Face : public vcg::Face<UsedTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class Mesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face>> {};

using vcgarrays::build;  // positions and triangles into a Mesh (vcg_arrays.h)

// The filter's body: border flags, selection test, then the lambda-mu steps.
inline void taubinLikeMeshLab(Mesh &mesh, int steps = 10, float lambda = 0.5f, float mu = -0.53f) {
    vcg::tri::UpdateFlags<Mesh>::FaceBorderFromNone(mesh);
    const size_t selected = vcg::tri::UpdateSelection<Mesh>::VertexFromFaceStrict(mesh);
    vcg::tri::Smooth<Mesh>::VertexCoordTaubin(mesh, steps, lambda, mu, selected > 0, nullptr);
}

// Smooths `positions` of the triangle mesh in place.
inline void taubinLikeMeshLab(std::vector<glm::vec3> &positions, const std::vector<uint32_t> &triangles, int steps = 10,
                              float lambda = 0.5f, float mu = -0.53f) {
    Mesh mesh;
    build(mesh, positions, triangles);
    taubinLikeMeshLab(mesh, steps, lambda, mu);
    vcgarrays::readPositions(mesh, positions);
}

}  // namespace voxelfair::vcgtaubin

#endif  // VOXELFAIR_HAVE_VCGLIB
