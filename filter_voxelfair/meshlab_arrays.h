// Converts between MeshLab's CMeshO and the raw arrays of the host-free units.
#pragma once

#include <common/ml_mesh_type.h>

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/gtc/type_precision.hpp>

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

// The same into `out`, reusing its memory (a filter keeps one between runs: fresh multi-megabyte
// arrays cost more in first-touch page faults than the smoothing itself).
void polygonArrays(const CMeshO &mesh, PolygonArrays &out);

// Writes `positions` back to the vertices they came from.
void writePositions(const PolygonArrays &arrays, const std::vector<glm::vec3> &positions, CMeshO &mesh);

// The polygons of one part of a voxelfair import (a VXL section, a VOX instance), renumbered
// from 0, and where its vertices are in the whole mesh's arrays.
struct PartArrays {
    int part = 0;
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> globalVertex;  // part vertex -> index into PolygonArrays::positions
    std::vector<uint32_t> polygonOffsets;
    std::vector<uint32_t> polygonIndices;
    std::vector<uint8_t> selected;

    size_t polygonCount() const { return polygonOffsets.size() - 1; }
};

// Splits `arrays` by the per-face part attribute io_vxl writes ("voxelfair_part"). Parts may be
// scaled differently (an HVA frame can shrink a section to 1%), so each needs its own voxel
// size. Returns nothing when the mesh has no such attribute or only one part.
std::vector<PartArrays> splitByPart(const PolygonArrays &arrays, const CMeshO &mesh);

// The live triangles of a MeshLab mesh as the host-free units read them (the atlas, the bakes):
// live vertices renumbered from 0, 3 indices per triangle, and per triangle the CMeshO face it
// came from. The optional fields are read when asked for: ask for colours only where the mesh
// has them (MeshModel::hasDataMask(MM_VERTCOLOR / MM_FACECOLOR)).
struct TriangleArrays {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;          // per vertex (TriangleFields::normals)
    std::vector<glm::u8vec3> vertexColours;  // per vertex (TriangleFields::vertexColours)
    std::vector<uint32_t> triangles;
    std::vector<uint32_t> faceOf;          // triangle -> index into CMeshO::face
    std::vector<glm::vec2> wedgeUv;        // 3 per triangle (TriangleFields::wedgeUv)
    std::vector<glm::u8vec3> faceColours;  // per triangle (TriangleFields::faceColours)

    size_t triangleCount() const { return faceOf.size(); }
};

struct TriangleFields {
    bool normals = false, vertexColours = false, wedgeUv = false, faceColours = false;
};

void readTriangleArrays(const CMeshO &mesh, TriangleFields fields, TriangleArrays &out);

// Per CMeshO face, its part number ("voxelfair_part"); empty when the mesh has no such attribute.
std::vector<int> facePartNumbers(const CMeshO &mesh);

// The part every live face of `mesh` is in (the per-face part attribute io_vxl writes), or -1
// when the mesh has no such attribute or its faces are in several parts.
int commonPart(const CMeshO &mesh);

}  // namespace voxelfair
