#include "mesh/polygon_mesh.h"

#include "base/error.h"

#include <algorithm>
#include <limits>
#include <string>

namespace voxelfair {

namespace {

constexpr size_t kMaxIndex = std::numeric_limits<uint32_t>::max();

}  // namespace

void validatePolygons(const PolygonMesh &mesh) {
    if (mesh.vertexCount > kMaxIndex)
        throw MeshError(std::to_string(mesh.vertexCount) + " vertices: more than 32-bit indices can address");
    if (mesh.polygonCount == 0)
        return;
    if (!mesh.polygonOffsets)
        throw MeshError(std::to_string(mesh.polygonCount) + " polygons but no polygon offsets (null)");
    if (mesh.polygonOffsets[0] != 0)
        throw MeshError("polygon offsets must start at 0, the first is " + std::to_string(mesh.polygonOffsets[0]));
    for (size_t p = 0; p < mesh.polygonCount; ++p)
        if (mesh.polygonOffsets[p + 1] < mesh.polygonOffsets[p])
            throw MeshError("polygon " + std::to_string(p) + ": its offsets decrease (" +
                            std::to_string(mesh.polygonOffsets[p]) + " then " +
                            std::to_string(mesh.polygonOffsets[p + 1]) + ")");
    const uint32_t indexCount = mesh.polygonOffsets[mesh.polygonCount];
    if (indexCount > 0 && !mesh.polygonIndices)
        throw MeshError(std::to_string(indexCount) + " polygon indices announced but no index array (null)");
    for (uint32_t i = 0; i < indexCount; ++i)
        if (mesh.polygonIndices[i] >= mesh.vertexCount) {
            const uint32_t *const after =
                std::upper_bound(mesh.polygonOffsets, mesh.polygonOffsets + mesh.polygonCount + 1, i);
            throw MeshError("polygon " + std::to_string(after - mesh.polygonOffsets - 1) + " uses vertex " +
                            std::to_string(mesh.polygonIndices[i]) + ", but there are " +
                            std::to_string(mesh.vertexCount) + " vertices");
        }
}

void validate(const PolygonMesh &mesh) {
    validatePolygons(mesh);
    if (!mesh.positions && mesh.vertexCount > 0)
        throw MeshError(std::to_string(mesh.vertexCount) + " vertices but no positions (null)");
}

}  // namespace voxelfair
