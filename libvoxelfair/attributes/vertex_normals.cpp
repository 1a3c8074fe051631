#include "attributes/vertex_normals.h"

#include "base/error.h"
#include "mesh/csr_adjacency.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

namespace voxelfair {

void computeVertexNormals(const PolygonMesh &mesh, const glm::vec3 *polygonNormals, glm::vec3 *vertexNormals,
                          const VertexNormalOptions &options) {
    computeVertexNormals(mesh, buildVertexPolygons(mesh), polygonNormals, vertexNormals, options);
}

void computeVertexNormals(const PolygonMesh &mesh, const CsrAdjacency &polygonsOf, const glm::vec3 *polygonNormals,
                          glm::vec3 *vertexNormals, const VertexNormalOptions &options) {
    const size_t vertexCount = mesh.vertexCount;
    if (polygonsOf.rowCount() != vertexCount)
        throw MeshError("vertex normals: vertex polygons for " + std::to_string(polygonsOf.rowCount()) +
                        " vertices on a mesh of " + std::to_string(vertexCount));

    // A handful of faces meet at a vertex, so a linear scan of the directions kept so far is
    // the cheapest dedupe; the scratch holds the longest row, so it never grows in the loop.
    size_t longestRow = 0;
    for (size_t v = 0; v < vertexCount; ++v)
        longestRow = std::max(longestRow, polygonsOf.size(v));
    std::vector<glm::vec3> distinct(longestRow);
    const float sameDirection = options.sameDirection;
    for (size_t v = 0; v < vertexCount; ++v) {
        size_t distinctCount = 0;
        glm::vec3 sum(0.0f);
        for (const uint32_t *p = polygonsOf.begin(v), *end = polygonsOf.end(v); p != end; ++p) {
            const glm::vec3 n = polygonNormals[*p];
            bool skip = glm::dot(n, n) == 0.0f;  // degenerate face
            for (size_t k = 0; k < distinctCount && !skip; ++k)
                skip = glm::dot(n, distinct[k]) > sameDirection;
            if (skip)
                continue;
            distinct[distinctCount++] = n;
            sum += n;
        }
        const float length = glm::length(sum);
        vertexNormals[v] = length > 1e-6f && std::isfinite(length) ? sum / length : glm::vec3(0.0f);
    }
}

}  // namespace voxelfair
