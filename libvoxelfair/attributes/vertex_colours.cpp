#include "attributes/vertex_colours.h"

#include <algorithm>

#include "base/error.h"
#include "mesh/csr_adjacency.h"

namespace voxelfair {

void computeVertexColours(const PolygonMesh &mesh, glm::vec4 *vertexColours) {
    if (!mesh.polygonColours && mesh.polygonCount > 0)
        throw MeshError("vertex colours: the mesh has no polygon colours");
    const size_t vertexCount = mesh.vertexCount;
    const glm::vec4 *const polygonColours = mesh.polygonColours;
    if (!polygonColours) {  // no polygons: every vertex is isolated
        std::fill(vertexColours, vertexColours + vertexCount, glm::vec4(0.0f));
        return;
    }
    const CsrAdjacency polygonsOf = buildVertexPolygons(mesh);
    for (size_t v = 0; v < vertexCount; ++v) {
        glm::vec4 sum(0.0f);
        for (const uint32_t *p = polygonsOf.begin(v), *end = polygonsOf.end(v); p != end; ++p)
            sum += polygonColours[*p];
        const size_t count = polygonsOf.size(v);
        vertexColours[v] = count ? sum / float(count) : glm::vec4(0.0f);
    }
}

}  // namespace voxelfair
