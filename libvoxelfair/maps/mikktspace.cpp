// MikkTSpace tangents (Mikkelsen 2008); the contract is in mikktspace.h. Arithmetic is in float,
// in the reference's order, so that the threshold decisions (zero areas, opposite derivatives)
// fall the same way as in the reference implementation.
#include "maps/mikktspace.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace voxelfair {

namespace {

using V3 = glm::vec3;

bool notZero(float x) { return std::fabs(x) > FLT_MIN; }
bool vNotZero(const V3 &v) { return notZero(v.x) || notZero(v.y) || notZero(v.z); }
float vlength(const V3 &v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }
V3 normalise(const V3 &v) { return (1.0f / vlength(v)) * v; }
float vdot(const V3 &a, const V3 &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
// The component of v orthogonal to n, normalised when it is not zero.
V3 projectNormalised(const V3 &n, const V3 &v) {
    V3 r = v - vdot(n, v) * n;
    return vNotZero(r) ? normalise(r) : r;
}

enum : uint8_t { Degenerate = 1, GroupWithAny = 2, OrientPreserving = 4 };

struct Triangle {
    int corner[3];  // welded vertex of each corner
    int original;   // index of the input triangle
    uint8_t flags = 0;
    int neighbour[3] = {-1, -1, -1};  // across edge i (corner i -> i + 1)
    int group[3] = {-1, -1, -1};
    V3 os{0.0f}, ot{0.0f};
};

struct Group {
    int vertex;
    bool orientPreserving;
    size_t first, count;  // into the shared face buffer
};

struct Space {
    V3 os{1.0f, 0.0f, 0.0f};
    bool orient = false;
};

struct Builder {
    const TangentInput &in;
    std::vector<Triangle> tris;  // healthy triangles first (input order), then degenerate ones
    size_t healthy = 0;
    std::vector<Group> groups;
    std::vector<int> groupFaces;

    explicit Builder(const TangentInput &input) : in(input) {}

    V3 position(int vertex) const { return in.positions[vertex]; }
    V3 normal(int vertex) const { return in.normals[vertex]; }
    glm::vec2 uv(int vertex) const { return in.uvs[vertex]; }

    // Corners with identical position, normal and texture coordinate share the index of the first.
    std::vector<int> weld() const {
        struct Key {
            float v[8];
            // Bitwise, as the hash: the reference welds identical bit patterns only.
            bool operator==(const Key &o) const {
                return std::memcmp(v, o.v, sizeof v) == 0;  // NOLINT(bugprone-suspicious-memory-comparison)
            }
        };
        struct Hash {
            size_t operator()(const Key &k) const {
                uint32_t bits[8];
                std::memcpy(bits, k.v, sizeof bits);
                uint64_t h = 1469598103934665603ull;
                for (uint32_t b : bits)
                    h = (h ^ b) * 1099511628211ull;
                return size_t(h);
            }
        };
        const size_t corners = 3 * in.triangleCount;
        // Open addressing (linear probing) over the corners' keys: the first corner of each key.
        size_t size = 16;
        while (size < 2 * corners)
            size *= 2;
        std::vector<int> table(size, -1);
        std::vector<Key> keys(corners);
        std::vector<int> welded(corners);
        for (size_t c = 0; c < corners; ++c) {
            const V3 p = in.positions[c], n = in.normals[c];
            const glm::vec2 t = in.uvs[c];
            Key &key = keys[c];
            key = Key{{p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y}};
            for (float &f : key.v)
                if (f == 0.0f)
                    f = 0.0f;  // -0 and +0 compare equal in the reference
            size_t slot = Hash()(key) & (size - 1);
            while (table[slot] >= 0 && !(keys[size_t(table[slot])] == key))
                slot = (slot + 1) & (size - 1);
            if (table[slot] < 0)
                table[slot] = int(c);
            welded[c] = table[slot];
        }
        return welded;
    }

    void initTriangles() {
        const std::vector<int> welded = weld();
        std::vector<Triangle> degenerate;
        for (size_t t = 0; t < in.triangleCount; ++t) {
            Triangle tri;
            for (int k = 0; k < 3; ++k)
                tri.corner[k] = welded[3 * t + size_t(k)];
            tri.original = int(t);
            const V3 p0 = position(tri.corner[0]), p1 = position(tri.corner[1]), p2 = position(tri.corner[2]);
            if (p0 == p1 || p0 == p2 || p1 == p2) {
                tri.flags = Degenerate;
                degenerate.push_back(tri);
            } else {
                tris.push_back(tri);
            }
        }
        healthy = tris.size();
        tris.insert(tris.end(), degenerate.begin(), degenerate.end());

        for (size_t f = 0; f < healthy; ++f) {
            Triangle &tri = tris[f];
            tri.flags |= GroupWithAny;  // assumed bad
            const V3 v1 = position(tri.corner[0]), v2 = position(tri.corner[1]), v3 = position(tri.corner[2]);
            const glm::vec2 t1 = uv(tri.corner[0]), t2 = uv(tri.corner[1]), t3 = uv(tri.corner[2]);
            const float t21x = t2.x - t1.x, t21y = t2.y - t1.y, t31x = t3.x - t1.x, t31y = t3.y - t1.y;
            const V3 d1 = v2 - v1, d2 = v3 - v1;
            const float signedArea = t21x * t31y - t21y * t31x;
            const V3 os = t31y * d1 - t21y * d2;   // thesis eq. 18
            const V3 ot = -t31x * d1 + t21x * d2;  // thesis eq. 19
            if (signedArea > 0)
                tri.flags |= OrientPreserving;
            if (notZero(signedArea)) {
                const float absArea = std::fabs(signedArea);
                const float lenOs = vlength(os), lenOt = vlength(ot);
                const float s = (tri.flags & OrientPreserving) ? 1.0f : -1.0f;
                if (notZero(lenOs))
                    tri.os = (s / lenOs) * os;
                if (notZero(lenOt))
                    tri.ot = (s / lenOt) * ot;
                if (notZero(lenOs / absArea) && notZero(lenOt / absArea))
                    tri.flags &= uint8_t(~GroupWithAny);
            }
        }
        buildNeighbours();
    }

    // Edges of the healthy triangles sorted by (smaller vertex, larger vertex, triangle); each
    // pairs with the first later triangle that runs it the other way and is still unpaired.
    void buildNeighbours() {
        struct Edge {
            int i0, i1, f;
        };
        // A counting sort on the smaller vertex (welded corner indices are below 3 x the triangle
        // count), faces in order within each; then each vertex's few edges by (larger vertex,
        // triangle), by insertion (a fan of many by std::sort). The keys are distinct: the order of
        // a full sort.
        std::vector<int> start(3 * in.triangleCount + 1, 0);
        for (size_t f = 0; f < healthy; ++f)
            for (int i = 0; i < 3; ++i)
                ++start[size_t(std::min(tris[f].corner[i], tris[f].corner[(i + 1) % 3])) + 1];
        for (size_t v = 1; v < start.size(); ++v)
            start[v] += start[v - 1];
        std::vector<Edge> edges(3 * healthy);
        {
            std::vector<int> fill(start.begin(), start.end() - 1);
            for (size_t f = 0; f < healthy; ++f)
                for (int i = 0; i < 3; ++i) {
                    const int a = tris[f].corner[i], b = tris[f].corner[(i + 1) % 3];
                    edges[size_t(fill[size_t(std::min(a, b))]++)] = {std::min(a, b), std::max(a, b), int(f)};
                }
        }
        auto before = [](const Edge &a, const Edge &b) { return a.i1 != b.i1 ? a.i1 < b.i1 : a.f < b.f; };
        for (size_t v = 0; v + 1 < start.size(); ++v) {
            if (start[v + 1] - start[v] > 16) {  // a fan of many triangles
                std::sort(edges.begin() + start[v], edges.begin() + start[v + 1], before);
                continue;
            }
            for (int i = start[v] + 1; i < start[v + 1]; ++i) {
                const Edge e = edges[size_t(i)];
                int j = i;
                for (; j > start[v] && before(e, edges[size_t(j - 1)]); --j)
                    edges[size_t(j)] = edges[size_t(j - 1)];
                edges[size_t(j)] = e;
            }
        }
        // Edge number of (a, b) in triangle f and whether f runs it from a to b.
        auto edgeOf = [&](int f, int a, int b, bool &forward) {
            const int *c = tris[size_t(f)].corner;
            for (int i = 0; i < 3; ++i) {
                const int p = c[i], q = c[(i + 1) % 3];
                if ((p == a && q == b) || (p == b && q == a)) {
                    forward = p == a;
                    return i;
                }
            }
            forward = false;
            return -1;
        };
        for (size_t i = 0; i < edges.size(); ++i) {
            const Edge &e = edges[i];
            bool forwardA;
            const int edgeA = edgeOf(e.f, e.i0, e.i1, forwardA);
            if (edgeA < 0 || tris[size_t(e.f)].neighbour[edgeA] != -1)
                continue;
            for (size_t j = i + 1; j < edges.size() && edges[j].i0 == e.i0 && edges[j].i1 == e.i1; ++j) {
                bool forwardB;
                const int edgeB = edgeOf(edges[j].f, e.i0, e.i1, forwardB);
                if (edgeB >= 0 && forwardB != forwardA && tris[size_t(edges[j].f)].neighbour[edgeB] == -1) {
                    tris[size_t(e.f)].neighbour[edgeA] = edges[j].f;
                    tris[size_t(edges[j].f)].neighbour[edgeB] = e.f;
                    break;
                }
            }
        }
    }

    static int cornerOf(const Triangle &tri, int vertex) {
        for (int i = 0; i < 3; ++i)
            if (tri.corner[i] == vertex)
                return i;
        return -1;
    }

    void assign(int f, int g) {
        Triangle &tri = tris[size_t(f)];
        const int i = cornerOf(tri, groups[size_t(g)].vertex);
        if (i < 0 || tri.group[i] != -1)
            return;
        if ((tri.flags & GroupWithAny) && tri.group[0] == -1 && tri.group[1] == -1 && tri.group[2] == -1) {
            tri.flags &= uint8_t(~OrientPreserving);  // the first group to reach it decides
            if (groups[size_t(g)].orientPreserving)
                tri.flags |= OrientPreserving;
        }
        if (bool(tri.flags & OrientPreserving) != groups[size_t(g)].orientPreserving)
            return;
        join(f, i, g);
    }

    // Corner i of face f joins group g, which then spreads across the two edges at that corner.
    void join(int f, int i, int g) {
        Triangle &tri = tris[size_t(f)];
        groupFaces.push_back(f);
        ++groups[size_t(g)].count;
        tri.group[i] = g;
        const int left = tri.neighbour[i], right = tri.neighbour[i > 0 ? i - 1 : 2];
        if (left >= 0)
            assign(left, g);
        if (right >= 0)
            assign(right, g);
    }

    void buildGroups() {
        groupFaces.reserve(3 * healthy);
        for (size_t f = 0; f < healthy; ++f)
            for (int i = 0; i < 3; ++i) {
                Triangle &tri = tris[f];
                if ((tri.flags & GroupWithAny) || tri.group[i] != -1)
                    continue;
                groups.push_back({tri.corner[i], bool(tri.flags & OrientPreserving), groupFaces.size(), 0});
                join(int(f), i, int(groups.size()) - 1);
            }
    }

    // Corner-angle weighted mean of the members' projected dP/ds at `vertex`.
    V3 evalTangent(const std::vector<int> &members, int vertex) const {
        V3 os(0.0f);
        for (int f : members) {
            const Triangle &tri = tris[size_t(f)];
            if (tri.flags & GroupWithAny)
                continue;
            const int i = cornerOf(tri, vertex);
            const V3 n = normal(tri.corner[i]);
            const V3 tangent = projectNormalised(n, tri.os);
            const V3 p0 = position(tri.corner[i > 0 ? i - 1 : 2]), p1 = position(tri.corner[i]),
                     p2 = position(tri.corner[i < 2 ? i + 1 : 0]);
            const V3 e1 = projectNormalised(n, p0 - p1), e2 = projectNormalised(n, p2 - p1);
            const float c = std::clamp(vdot(e1, e2), -1.0f, 1.0f);
            os = os + float(std::acos(double(c))) * tangent;
        }
        return vNotZero(os) ? normalise(os) : os;
    }

    void generateSpaces(std::vector<Space> &spaces) const {
        const float thresholdCos = float(std::cos(double(180.0f * float(M_PI) / 180.0f)));
        std::vector<std::vector<int>> subgroups;
        std::vector<V3> subgroupTangent, projectedS, projectedT;
        std::vector<int> members;
        for (size_t g = 0; g < groups.size(); ++g) {
            const Group &group = groups[g];
            size_t subgroupCount = 0;
            // Every member's derivatives projected onto the group's vertex normal, once.
            const V3 n = normal(group.vertex);
            projectedS.resize(group.count);
            projectedT.resize(group.count);
            for (size_t j = 0; j < group.count; ++j) {
                const Triangle &t = tris[size_t(groupFaces[group.first + j])];
                projectedS[j] = projectNormalised(n, t.os);
                projectedT[j] = projectNormalised(n, t.ot);
            }
            for (size_t k = 0; k < group.count; ++k) {
                const int f = groupFaces[group.first + k];
                const Triangle &tri = tris[size_t(f)];
                int index = 0;
                while (index < 3 && tri.group[index] != int(g))
                    ++index;
                members.clear();
                for (size_t j = 0; j < group.count; ++j) {
                    const int t = groupFaces[group.first + j];
                    const bool any = ((tri.flags | tris[size_t(t)].flags) & GroupWithAny) != 0;
                    if (any || t == f ||
                        (vdot(projectedS[k], projectedS[j]) > thresholdCos &&
                         vdot(projectedT[k], projectedT[j]) > thresholdCos))
                        members.push_back(t);
                }
                std::sort(members.begin(), members.end());
                size_t s = 0;
                while (s < subgroupCount && subgroups[s] != members)
                    ++s;
                if (s == subgroupCount) {
                    if (subgroups.size() <= s)
                        subgroups.emplace_back();
                    subgroups[s] = members;
                    if (subgroupTangent.size() <= s)
                        subgroupTangent.emplace_back();
                    subgroupTangent[s] = evalTangent(members, group.vertex);
                    ++subgroupCount;
                }
                Space &out = spaces[3 * size_t(tri.original) + size_t(index)];
                out.os = subgroupTangent[s];
                out.orient = group.orientPreserving;
            }
        }
    }

    // Degenerate triangles copy the space of the first healthy corner of the same vertex.
    void degenerateEpilogue(std::vector<Space> &spaces) const {
        if (healthy == tris.size())
            return;
        std::unordered_map<int, size_t> firstCorner;
        for (size_t f = 0; f < healthy; ++f)
            for (int i = 0; i < 3; ++i)
                firstCorner.emplace(tris[f].corner[i], 3 * size_t(tris[f].original) + size_t(i));
        for (size_t t = healthy; t < tris.size(); ++t)
            for (int i = 0; i < 3; ++i) {
                const auto it = firstCorner.find(tris[t].corner[i]);
                if (it != firstCorner.end())
                    spaces[3 * size_t(tris[t].original) + size_t(i)] = spaces[it->second];
            }
    }
};

}  // namespace

std::vector<glm::vec4> computeMikkTSpaceTangents(const TangentInput &input) {
    std::vector<glm::vec4> out(3 * input.triangleCount, glm::vec4(1.0f, 0.0f, 0.0f, -1.0f));
    if (input.triangleCount == 0 || !input.positions || !input.normals || !input.uvs)
        return out;
    Builder b(input);
    b.initTriangles();
    b.buildGroups();
    std::vector<Space> spaces(3 * input.triangleCount);
    b.generateSpaces(spaces);
    b.degenerateEpilogue(spaces);
    for (size_t c = 0; c < spaces.size(); ++c)
        out[c] = glm::vec4(spaces[c].os, spaces[c].orient ? 1.0f : -1.0f);
    return out;
}

}  // namespace voxelfair
