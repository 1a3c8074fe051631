#include "attributes/vertex_colours.h"

namespace voxelfair {

PolygonMeshError computeVertexColours(size_t vertexCount, const uint32_t *polygonOffsets,
                                      const uint32_t *polygonIndices, size_t polygonCount,
                                      const glm::vec4 *polygonColours, glm::vec4 *vertexColours) {
    CsrAdjacency polygonsOf;
    if (PolygonMeshError e = buildVertexPolygons(vertexCount, polygonOffsets, polygonIndices, polygonCount, polygonsOf);
        e != PolygonMeshError::None)
        return e;
    for (size_t v = 0; v < vertexCount; ++v) {
        glm::vec4 sum(0.0f);
        for (const uint32_t *p = polygonsOf.begin(v), *end = polygonsOf.end(v); p != end; ++p)
            sum += polygonColours[*p];
        const size_t count = polygonsOf.size(v);
        vertexColours[v] = count ? sum / float(count) : glm::vec4(0.0f);
    }
    return PolygonMeshError::None;
}

}  // namespace voxelfair
