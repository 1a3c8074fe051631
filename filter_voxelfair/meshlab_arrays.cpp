#include "meshlab_arrays.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace voxelfair {

namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

uint32_t findRoot(std::vector<uint32_t> &parent, uint32_t f) {
    while (parent[f] != f)
        f = parent[f] = parent[parent[f]];
    return f;
}

// The one faux edge of a face, or -1 when it has none or several.
int singleFauxEdge(const CFaceO &f) {
    const int count = int(f.IsF(0)) + int(f.IsF(1)) + int(f.IsF(2));
    if (count != 1)
        return -1;
    return f.IsF(0) ? 0 : f.IsF(1) ? 1 : 2;
}

class PolygonGatherer {
public:
    PolygonGatherer(const CMeshO &mesh, const std::vector<uint32_t> &arrayIndex, PolygonArrays &out)
        : mesh_(mesh), arrayIndex_(arrayIndex), out_(out) {}

    void run() {
        out_.polygonOffsets.push_back(0);
        std::vector<uint32_t> others;  // faces not in the common layouts below
        const size_t faces = mesh_.face.size();
        for (size_t f = 0; f < faces; ++f) {
            const CFaceO &face = mesh_.face[f];
            if (face.IsD())
                continue;
            const int e = singleFauxEdge(face);
            if (!face.IsF(0) && !face.IsF(1) && !face.IsF(2)) {
                emitTriangle(f);
            } else if (e >= 0 && f + 1 < faces && isQuadPartner(face, e, mesh_.face[f + 1])) {
                // The importer's layout (and vcg's quad meshes): a quad's triangles are neighbours.
                emitQuad(f, e);
                ++f;
            } else {
                others.push_back(uint32_t(f));
            }
        }
        gatherGeneral(others);
    }

private:
    uint32_t vertex(const CFaceO &f, int k) const { return uint32_t(vcg::tri::Index(mesh_, f.cV(k))); }

    bool isQuadPartner(const CFaceO &first, int e, const CFaceO &second) const {
        const int e2 = second.IsD() ? -1 : singleFauxEdge(second);
        return e2 >= 0 && vertex(first, e) == vertex(second, (e2 + 1) % 3) &&
               vertex(first, (e + 1) % 3) == vertex(second, e2);
    }

    void push(uint32_t meshVertex) {
        const uint32_t v = arrayIndex_[meshVertex];
        if (v != kNone)
            out_.polygonIndices.push_back(v);
    }

    void close(size_t face) {
        out_.polygonOffsets.push_back(uint32_t(out_.polygonIndices.size()));
        out_.polygonFace.push_back(uint32_t(face));
    }

    void emitTriangle(size_t f) {
        for (int k = 0; k < 3; ++k)
            push(vertex(mesh_.face[f], k));
        close(f);
    }

    // Triangles (A, B, C) and (B, A, D) sharing the faux edge A-B make the quad B, C, A, D,
    // counter-clockwise like both triangles.
    void emitQuad(size_t f, int e) {
        const CFaceO &first = mesh_.face[f], &second = mesh_.face[f + 1];
        const int e2 = singleFauxEdge(second);
        push(vertex(first, (e + 1) % 3));
        push(vertex(first, (e + 2) % 3));
        push(vertex(first, e));
        push(vertex(second, (e2 + 2) % 3));
        close(f);
    }

    // Any other grouping: triangles joined by faux edges, found by sorting the edges' vertex
    // pairs; each polygon lists its distinct vertices in order of appearance.
    void gatherGeneral(const std::vector<uint32_t> &faces) {
        if (faces.empty())
            return;
        std::vector<uint32_t> parent(faces.size());
        for (size_t i = 0; i < faces.size(); ++i)
            parent[i] = uint32_t(i);
        struct FauxEdge {
            uint64_t key;
            uint32_t item;
        };
        std::vector<FauxEdge> edges;
        for (size_t i = 0; i < faces.size(); ++i) {
            const CFaceO &face = mesh_.face[faces[i]];
            for (int e = 0; e < 3; ++e) {
                if (!face.IsF(e))
                    continue;
                const uint64_t a = vertex(face, e), b = vertex(face, (e + 1) % 3);
                edges.push_back({std::min(a, b) << 32 | std::max(a, b), uint32_t(i)});
            }
        }
        std::sort(edges.begin(), edges.end(), [](const FauxEdge &x, const FauxEdge &y) { return x.key < y.key; });
        for (size_t i = 0; i + 1 < edges.size(); ++i)
            if (edges[i].key == edges[i + 1].key)
                parent[findRoot(parent, edges[i].item)] = findRoot(parent, edges[i + 1].item);

        // Members of each group, in face order (counting sort by root).
        std::vector<uint32_t> start(faces.size() + 1, 0);
        for (size_t i = 0; i < faces.size(); ++i)
            ++start[findRoot(parent, uint32_t(i)) + 1];
        for (size_t i = 0; i < faces.size(); ++i)
            start[i + 1] += start[i];
        std::vector<uint32_t> members(faces.size());
        std::vector<uint32_t> fill(start.begin(), start.end() - 1);
        for (size_t i = 0; i < faces.size(); ++i)
            members[fill[parent[i]]++] = uint32_t(i);

        for (size_t r = 0; r < faces.size(); ++r) {
            if (start[r] == start[r + 1])
                continue;
            const size_t first = out_.polygonIndices.size();
            for (uint32_t m = start[r]; m < start[r + 1]; ++m) {
                const CFaceO &face = mesh_.face[faces[members[m]]];
                for (int k = 0; k < 3; ++k) {
                    const uint32_t v = arrayIndex_[vertex(face, k)];
                    if (v != kNone && std::find(out_.polygonIndices.begin() + long(first), out_.polygonIndices.end(),
                                                v) == out_.polygonIndices.end())
                        out_.polygonIndices.push_back(v);
                }
            }
            close(faces[members[start[r]]]);
        }
    }

    const CMeshO &mesh_;
    const std::vector<uint32_t> &arrayIndex_;
    PolygonArrays &out_;
};

}  // namespace

PolygonArrays polygonArrays(const CMeshO &mesh) {
    PolygonArrays out;
    polygonArrays(mesh, out);
    return out;
}

void polygonArrays(const CMeshO &mesh, PolygonArrays &out) {
    out.positions.clear();
    out.vertexOf.clear();
    out.selected.clear();
    out.polygonOffsets.clear();
    out.polygonFace.clear();
    out.polygonIndices.clear();
    out.nonFiniteVertices = 0;
    out.positions.reserve(size_t(mesh.vn));
    out.vertexOf.reserve(size_t(mesh.vn));
    out.selected.reserve(size_t(mesh.vn));
    out.polygonOffsets.reserve(size_t(mesh.fn) + 1);
    out.polygonFace.reserve(size_t(mesh.fn));
    out.polygonIndices.reserve(2 * size_t(mesh.fn) + 2);  // quads: 4 indices per 2 triangles

    thread_local std::vector<uint32_t> arrayIndex;
    arrayIndex.assign(mesh.vert.size(), kNone);
    for (size_t v = 0; v < mesh.vert.size(); ++v) {
        const CVertexO &vert = mesh.vert[v];
        if (vert.IsD())
            continue;
        const glm::vec3 p(vert.cP()[0], vert.cP()[1], vert.cP()[2]);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            ++out.nonFiniteVertices;
        arrayIndex[v] = uint32_t(out.positions.size());
        out.positions.push_back(p);
        out.vertexOf.push_back(uint32_t(v));
        out.selected.push_back(vert.IsS() ? 1 : 0);
    }
    PolygonGatherer(mesh, arrayIndex, out).run();
}

void writePositions(const PolygonArrays &arrays, const std::vector<glm::vec3> &positions, CMeshO &mesh) {
    for (size_t i = 0; i < arrays.vertexOf.size(); ++i) {
        CVertexO &v = mesh.vert[arrays.vertexOf[i]];
        v.P() = CMeshO::CoordType(positions[i].x, positions[i].y, positions[i].z);
    }
}

// The per-face part attribute io_vxl writes ("voxelfair_part"); false when the mesh has none.
static bool findPartAttribute(const CMeshO &mesh, CMeshO::PerFaceAttributeHandle<int> &partOf) {
    if (!vcg::tri::HasPerFaceAttribute(mesh, "voxelfair_part"))
        return false;
    // vcglib's attribute lookup takes a mutable mesh; nothing is written through it.
    CMeshO &lookup = const_cast<CMeshO &>(mesh);
    partOf = vcg::tri::Allocator<CMeshO>::FindPerFaceAttribute<int>(lookup, "voxelfair_part");
    return vcg::tri::Allocator<CMeshO>::IsValidHandle(lookup, partOf);
}

std::vector<int> facePartNumbers(const CMeshO &mesh) {
    CMeshO::PerFaceAttributeHandle<int> partOf;
    if (!findPartAttribute(mesh, partOf))
        return {};
    std::vector<int> parts(mesh.face.size());
    for (size_t f = 0; f < mesh.face.size(); ++f)
        parts[f] = partOf[f];
    return parts;
}

int commonPart(const CMeshO &mesh) {
    CMeshO::PerFaceAttributeHandle<int> partOf;
    if (!findPartAttribute(mesh, partOf))
        return -1;
    int part = -1;
    for (size_t f = 0; f < mesh.face.size(); ++f) {
        if (mesh.face[f].IsD())
            continue;
        if (part >= 0 && partOf[f] != part)
            return -1;
        part = partOf[f];
    }
    return part;
}

std::vector<PartArrays> splitByPart(const PolygonArrays &arrays, const CMeshO &mesh) {
    CMeshO::PerFaceAttributeHandle<int> partOf;
    if (!findPartAttribute(mesh, partOf))
        return {};

    // Most meshes are one part: find out before copying anything.
    bool severalParts = false;
    for (size_t p = 1; p < arrays.polygonCount() && !severalParts; ++p)
        severalParts = partOf[arrays.polygonFace[p]] != partOf[arrays.polygonFace[0]];
    if (!severalParts)
        return {};

    std::vector<PartArrays> parts;
    std::vector<int> slotOfPart;  // part number -> index into parts (parts are small numbers)
    std::vector<uint32_t> localVertex(arrays.positions.size(), kNone);
    std::vector<uint32_t> vertexPart(arrays.positions.size(), kNone);
    for (size_t p = 0; p < arrays.polygonCount(); ++p) {
        const int part = partOf[arrays.polygonFace[p]];
        if (part < 0)
            return {};
        if (size_t(part) >= slotOfPart.size())
            slotOfPart.resize(size_t(part) + 1, -1);
        if (slotOfPart[size_t(part)] < 0) {
            slotOfPart[size_t(part)] = int(parts.size());
            parts.push_back(PartArrays{part, {}, {}, {0}, {}, {}});
        }
        PartArrays &out = parts[size_t(slotOfPart[size_t(part)])];
        for (uint32_t i = arrays.polygonOffsets[p]; i < arrays.polygonOffsets[p + 1]; ++i) {
            const uint32_t v = arrays.polygonIndices[i];
            if (vertexPart[v] == kNone) {
                vertexPart[v] = uint32_t(slotOfPart[size_t(part)]);
                localVertex[v] = uint32_t(out.positions.size());
                out.positions.push_back(arrays.positions[v]);
                out.globalVertex.push_back(v);
                out.selected.push_back(arrays.selected[v]);
            } else if (vertexPart[v] != uint32_t(slotOfPart[size_t(part)])) {
                return {};  // parts sharing vertices: not an import's layout, treat as one
            }
            out.polygonIndices.push_back(localVertex[v]);
        }
        out.polygonOffsets.push_back(uint32_t(out.polygonIndices.size()));
    }
    if (parts.size() < 2)
        return {};
    return parts;
}

void readTriangleArrays(const CMeshO &mesh, TriangleFields fields, TriangleArrays &out) {
    std::vector<uint32_t> arrayIndex(mesh.vert.size(), 0);
    for (size_t v = 0; v < mesh.vert.size(); ++v) {
        const CVertexO &vert = mesh.vert[v];
        if (vert.IsD())
            continue;
        arrayIndex[v] = uint32_t(out.positions.size());
        out.positions.emplace_back(vert.cP()[0], vert.cP()[1], vert.cP()[2]);
        if (fields.normals)
            out.normals.emplace_back(vert.cN()[0], vert.cN()[1], vert.cN()[2]);
        if (fields.vertexColours)
            out.vertexColours.emplace_back(vert.cC()[0], vert.cC()[1], vert.cC()[2]);
    }
    for (size_t f = 0; f < mesh.face.size(); ++f) {
        const CFaceO &face = mesh.face[f];
        if (face.IsD())
            continue;
        for (int k = 0; k < 3; ++k) {
            out.triangles.push_back(arrayIndex[vcg::tri::Index(mesh, face.cV(k))]);
            if (fields.wedgeUv)
                out.wedgeUv.emplace_back(face.cWT(k).U(), face.cWT(k).V());
        }
        out.faceOf.push_back(uint32_t(f));
        if (fields.faceColours)
            out.faceColours.emplace_back(face.cC()[0], face.cC()[1], face.cC()[2]);
    }
}

}  // namespace voxelfair
