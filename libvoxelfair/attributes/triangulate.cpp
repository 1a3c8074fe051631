#include "attributes/triangulate.h"

namespace voxelfair {

size_t countFanTriangles(const PolygonMesh &mesh) {
    size_t count = 0;
    for (size_t p = 0; p < mesh.polygonCount; ++p) {
        const uint32_t arity = mesh.arity(p);
        if (arity >= 3)
            count += arity - 2;
    }
    return count;
}

void triangulatePolygons(const PolygonMesh &mesh, uint32_t *triangles, uint32_t *triangleToPolygon) {
    validatePolygons(mesh);
    const uint32_t *const polygonOffsets = mesh.polygonOffsets, *const polygonIndices = mesh.polygonIndices;
    size_t t = 0;
    for (size_t p = 0; p < mesh.polygonCount; ++p) {
        const uint32_t first = polygonOffsets[p], last = polygonOffsets[p + 1];
        for (uint32_t i = first + 1; i + 1 < last; ++i, ++t) {
            triangles[3 * t + 0] = polygonIndices[first];
            triangles[3 * t + 1] = polygonIndices[i];
            triangles[3 * t + 2] = polygonIndices[i + 1];
            if (triangleToPolygon)
                triangleToPolygon[t] = uint32_t(p);
        }
    }
}

}  // namespace voxelfair
