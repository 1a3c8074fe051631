// Converts between MeshLab's CMeshO and the raw arrays of the host-free units.
#pragma once

#include <common/ml_mesh_type.h>

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace voxelfair {

// The live (non-deleted) vertices and the polygons of a MeshLab mesh. A MeshLab polygon is a
// group of triangles joined by faux edges (the importer's quads are two triangles sharing a faux
// diagonal); a mesh without faux edges is all triangles.
struct PolygonArrays {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> vertexOf;        // array index -> index into CMeshO::vert
    std::vector<uint32_t> polygonOffsets;  // polygonCount + 1 entries
    std::vector<uint32_t> polygonIndices;  // distinct vertices of each polygon (array indices)
    std::vector<uint32_t> polygonFace;     // per polygon: its first triangle, an index into CMeshO::face
    std::vector<uint8_t> selected;         // per array vertex: 1 if selected in MeshLab
    size_t nonFiniteVertices = 0;          // vertices with a NaN or infinite coordinate

    size_t polygonCount() const { return polygonOffsets.empty() ? 0 : polygonOffsets.size() - 1; }
};

PolygonArrays polygonArrays(const CMeshO &mesh);

// Writes `positions` back to the vertices they came from.
void writePositions(const PolygonArrays &arrays, const std::vector<glm::vec3> &positions, CMeshO &mesh);

}  // namespace voxelfair
