#include "mesh/triangle_mesh.h"

#include "base/error.h"

#include <cstdint>
#include <string>

namespace voxelfair {

void validate(const TriangleMesh &mesh) {
    if (mesh.faceCount == 0)
        return;
    if (!mesh.triangles)
        throw MeshError(std::to_string(mesh.faceCount) + " faces but no triangle indices (null)");
    if (mesh.vertexCount == 0 || !mesh.positions)
        throw MeshError(std::to_string(mesh.faceCount) + " faces but no vertex positions");
    if (mesh.vertexCount >= UINT32_MAX || mesh.faceCount >= UINT32_MAX / 3)
        throw MeshError(std::to_string(mesh.vertexCount) + " vertices, " + std::to_string(mesh.faceCount) +
                        " faces: more than 32-bit indices can address");
    for (size_t i = 0; i < mesh.faceCount * 3; ++i)
        if (mesh.triangles[i] >= mesh.vertexCount)
            throw MeshError("face " + std::to_string(i / 3) + " uses vertex " + std::to_string(mesh.triangles[i]) +
                            ", but there are " + std::to_string(mesh.vertexCount) + " vertices");
}

}  // namespace voxelfair
