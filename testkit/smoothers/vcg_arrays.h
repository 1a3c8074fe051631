// Plain arrays into and out of a vcglib triangle mesh, for the comparison smoothers that run
// vcglib as MeshLab does (vcg_taubin.h, vcg_smoothers.h): any vcg::tri::TriMesh whose vertices
// have Coord3f and whose faces have VertexRef. Only with VOXELFAIR_HAVE_VCGLIB.
#pragma once

#ifdef VOXELFAIR_HAVE_VCGLIB

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include <vcg/complex/complex.h>

namespace voxelfair::vcgarrays {

// Replaces the mesh's contents with the positions and the triangles (3 indices per face).
template <class Mesh>
void build(Mesh &mesh, const std::vector<glm::vec3> &positions, const std::vector<uint32_t> &triangles) {
    mesh.Clear();
    auto vi = vcg::tri::Allocator<Mesh>::AddVertices(mesh, positions.size());
    for (const glm::vec3 &p : positions)
        (vi++)->P() = vcg::Point3f(p.x, p.y, p.z);
    auto fi = vcg::tri::Allocator<Mesh>::AddFaces(mesh, triangles.size() / 3);
    for (size_t t = 0; t + 2 < triangles.size(); t += 3, ++fi)
        for (int k = 0; k < 3; ++k)
            fi->V(k) = &mesh.vert[triangles[t + k]];
}

// The positions of the first positions.size() vertices, back into the array.
template <class Mesh>
void readPositions(const Mesh &mesh, std::vector<glm::vec3> &positions) {
    for (size_t v = 0; v < positions.size(); ++v) {
        const vcg::Point3f &p = mesh.vert[v].cP();
        positions[v] = glm::vec3(p[0], p[1], p[2]);
    }
}

}  // namespace voxelfair::vcgarrays

#endif  // VOXELFAIR_HAVE_VCGLIB
