#include "attributes/vertex_colours.h"

#include <algorithm>
#include <string>

#include "base/error.h"
#include "mesh/csr_adjacency.h"

namespace voxelfair {

void computeVertexColours(const PolygonMesh &mesh, glm::vec4 *vertexColours) {
    if (!mesh.polygonColours && mesh.polygonCount > 0)
        throw MeshError("vertex colours: the mesh has no polygon colours");
    if (!mesh.polygonColours) {  // no polygons: every vertex is isolated
        std::fill(vertexColours, vertexColours + mesh.vertexCount, glm::vec4(0.0f));
        return;
    }
    computeVertexColours(mesh, buildVertexPolygons(mesh), vertexColours);
}

void computeVertexColours(const PolygonMesh &mesh, const CsrAdjacency &polygonsOf, glm::vec4 *vertexColours) {
    if (!mesh.polygonColours && mesh.polygonCount > 0)
        throw MeshError("vertex colours: the mesh has no polygon colours");
    const size_t vertexCount = mesh.vertexCount;
    if (polygonsOf.rowCount() != vertexCount)
        throw MeshError("vertex colours: vertex polygons for " + std::to_string(polygonsOf.rowCount()) +
                        " vertices on a mesh of " + std::to_string(vertexCount));
    const glm::vec4 *const polygonColours = mesh.polygonColours;
    if (!polygonColours) {  // no polygons: every vertex is isolated
        std::fill(vertexColours, vertexColours + vertexCount, glm::vec4(0.0f));
        return;
    }
    for (size_t v = 0; v < vertexCount; ++v) {
        glm::vec4 sum(0.0f);
        for (const uint32_t *p = polygonsOf.begin(v), *end = polygonsOf.end(v); p != end; ++p)
            sum += polygonColours[*p];
        const size_t count = polygonsOf.size(v);
        vertexColours[v] = count ? sum / float(count) : glm::vec4(0.0f);
    }
}

}  // namespace voxelfair
