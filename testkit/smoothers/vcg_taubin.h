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

inline void build(Mesh &mesh, const std::vector<glm::vec3> &positions, const std::vector<uint32_t> &triangles) {
    mesh.Clear();
    auto vi = vcg::tri::Allocator<Mesh>::AddVertices(mesh, positions.size());
    for (const glm::vec3 &p : positions)
        (vi++)->P() = vcg::Point3f(p.x, p.y, p.z);
    auto fi = vcg::tri::Allocator<Mesh>::AddFaces(mesh, triangles.size() / 3);
    for (size_t t = 0; t + 2 < triangles.size(); t += 3, ++fi)
        for (int k = 0; k < 3; ++k)
            fi->V(k) = &mesh.vert[triangles[t + k]];
}

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
    for (size_t v = 0; v < positions.size(); ++v) {
        const vcg::Point3f &p = mesh.vert[v].cP();
        positions[v] = glm::vec3(p[0], p[1], p[2]);
    }
}

}  // namespace voxelfair::vcgtaubin

#endif  // VOXELFAIR_HAVE_VCGLIB
