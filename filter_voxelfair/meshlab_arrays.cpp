#include "meshlab_arrays.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace voxelfair {

namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

uint32_t findRoot(std::vector<uint32_t> &parent, uint32_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
}

// Joins triangles that share a faux edge into polygons (union-find over faces). The importer
// stores a quad's two triangles next to each other, so the common case is found without a map;
// other faux edges are matched by sorting their vertex pairs.
std::vector<uint32_t> polygonOfFace(const CMeshO &mesh, const std::vector<uint32_t> &faceIndex) {
    const size_t faces = mesh.face.size();
    std::vector<uint32_t> parent(faces);
    for (size_t f = 0; f < faces; ++f) parent[f] = uint32_t(f);

    struct FauxEdge {
        uint64_t key;
        uint32_t face;
    };
    std::vector<FauxEdge> pending;
    auto vertexId = [&](const CFaceO &f, int k) { return uint64_t(vcg::tri::Index(mesh, f.cV(k))); };
    auto fauxKey = [&](const CFaceO &f, int e) {
        const uint64_t a = vertexId(f, e), b = vertexId(f, (e + 1) % 3);
        return std::min(a, b) << 32 | std::max(a, b);
    };
    auto hasFauxEdge = [&](size_t f, uint64_t key) {
        if (f >= faces || faceIndex[f] == kNone) return false;
        for (int e = 0; e < 3; ++e)
            if (mesh.face[f].IsF(e) && fauxKey(mesh.face[f], e) == key) return true;
        return false;
    };
    for (size_t f = 0; f < faces; ++f) {
        const CFaceO &face = mesh.face[f];
        if (faceIndex[f] == kNone) continue;
        for (int e = 0; e < 3; ++e) {
            if (!face.IsF(e)) continue;
            const uint64_t key = fauxKey(face, e);
            if (f > 0 && hasFauxEdge(f - 1, key)) continue;  // joined from the previous face
            if (hasFauxEdge(f + 1, key)) {
                parent[findRoot(parent, uint32_t(f + 1))] = findRoot(parent, uint32_t(f));
                continue;
            }
            pending.push_back({key, uint32_t(f)});
        }
    }
    std::sort(pending.begin(), pending.end(), [](const FauxEdge &x, const FauxEdge &y) { return x.key < y.key; });
    for (size_t i = 0; i + 1 < pending.size(); ++i)
        if (pending[i].key == pending[i + 1].key)
            parent[findRoot(parent, pending[i].face)] = findRoot(parent, pending[i + 1].face);
    for (size_t f = 0; f < faces; ++f) parent[f] = findRoot(parent, uint32_t(f));
    return parent;
}

}  // namespace

PolygonArrays polygonArrays(const CMeshO &mesh) {
    PolygonArrays out;
    out.positions.reserve(size_t(mesh.vn));
    out.vertexOf.reserve(size_t(mesh.vn));
    out.selected.reserve(size_t(mesh.vn));
    out.polygonOffsets.reserve(size_t(mesh.fn) + 1);
    out.polygonFace.reserve(size_t(mesh.fn));
    out.polygonIndices.reserve(2 * size_t(mesh.fn) + 2);  // quads: 4 indices per 2 triangles
    std::vector<uint32_t> arrayIndex(mesh.vert.size(), kNone);
    for (size_t v = 0; v < mesh.vert.size(); ++v) {
        const CVertexO &vert = mesh.vert[v];
        if (vert.IsD()) continue;
        const glm::vec3 p(vert.cP()[0], vert.cP()[1], vert.cP()[2]);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) ++out.nonFiniteVertices;
        arrayIndex[v] = uint32_t(out.positions.size());
        out.positions.push_back(p);
        out.vertexOf.push_back(uint32_t(v));
        out.selected.push_back(vert.IsS() ? 1 : 0);
    }

    std::vector<uint32_t> faceIndex(mesh.face.size(), kNone);
    for (size_t f = 0; f < mesh.face.size(); ++f)
        if (!mesh.face[f].IsD()) faceIndex[f] = uint32_t(f);
    const std::vector<uint32_t> root = polygonOfFace(mesh, faceIndex);

    // Gather each polygon's faces (counting sort by root), then its distinct vertices.
    std::vector<uint32_t> start(mesh.face.size() + 1, 0);
    for (size_t f = 0; f < mesh.face.size(); ++f)
        if (faceIndex[f] != kNone) ++start[root[f] + 1];
    for (size_t i = 0; i < mesh.face.size(); ++i) start[i + 1] += start[i];
    std::vector<uint32_t> members(start.back());
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t f = 0; f < mesh.face.size(); ++f)
        if (faceIndex[f] != kNone) members[fill[root[f]]++] = uint32_t(f);

    out.polygonOffsets.push_back(0);
    for (size_t r = 0; r < mesh.face.size(); ++r) {
        if (start[r] == start[r + 1]) continue;
        const size_t first = out.polygonIndices.size();
        for (uint32_t i = start[r]; i < start[r + 1]; ++i) {
            const CFaceO &face = mesh.face[members[i]];
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = arrayIndex[vcg::tri::Index(mesh, face.cV(k))];
                if (v == kNone) continue;
                if (std::find(out.polygonIndices.begin() + long(first), out.polygonIndices.end(), v) == out.polygonIndices.end())
                    out.polygonIndices.push_back(v);
            }
        }
        out.polygonOffsets.push_back(uint32_t(out.polygonIndices.size()));
        out.polygonFace.push_back(members[start[r]]);
    }
    return out;
}

void writePositions(const PolygonArrays &arrays, const std::vector<glm::vec3> &positions, CMeshO &mesh) {
    for (size_t i = 0; i < arrays.vertexOf.size(); ++i) {
        CVertexO &v = mesh.vert[arrays.vertexOf[i]];
        v.P() = CMeshO::CoordType(positions[i].x, positions[i].y, positions[i].z);
    }
}

}  // namespace voxelfair
