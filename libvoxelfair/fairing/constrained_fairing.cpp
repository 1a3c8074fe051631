#include "fairing/constrained_fairing.h"

#include "fairing/voxel_size.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

namespace voxelfair {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

// How a free vertex's edge enters its fit (step 3).
enum EdgeUse : uint8_t { kUnused, kBothNormals, kLendNormal };

enum class VertexKind : uint8_t {
    Free,      // fitted along its normal to its neighbours
    EdgeLine,  // on a line of sharp edges: fitted to the planes of its polygons
    Pinned,    // sharp edges end or meet here, or not selected, or no usable polygon
    Skipped,   // non-finite coordinates
};

bool isFinite(const glm::vec3 &p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

glm::vec3 normalizedOrZero(const glm::vec3 &v) {
    const float length2 = glm::dot(v, v);
    return length2 > 0.0f && length2 <= std::numeric_limits<float>::max() ? v * (1.0f / std::sqrt(length2))
                                                                            : glm::vec3(0.0f);
}

// Unit normal of a polygon from its vector area (Newell), exact for non-planar polygons too; a
// quad's vector area is half the cross product of its diagonals.
glm::vec3 areaNormal(const glm::vec3 *positions, const uint32_t *indices, uint32_t first, uint32_t last) {
    if (last - first == 4)
        return normalizedOrZero(glm::cross(positions[indices[first + 2]] - positions[indices[first]],
                                           positions[indices[first + 3]] - positions[indices[first + 1]]));
    glm::vec3 n(0.0f);
    for (uint32_t i = first; i < last; ++i) {
        const glm::vec3 &a = positions[indices[i]];
        const glm::vec3 &b = positions[indices[i + 1 < last ? i + 1 : first]];
        n += glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return normalizedOrZero(n);
}

// Polygon connectivity by corners: corner c is polygonIndices[c] and the edge from it to the next
// vertex of its polygon. A mesh of quads only (the voxel surface) needs no per-corner polygon or
// next-vertex table: they follow from c itself, which saves memory and time.
struct Corners {
    const uint32_t *offsets = nullptr;
    const uint32_t *indices = nullptr;
    bool allQuads = false;
    std::vector<uint32_t> polygonTable;   // corner -> polygon (empty when allQuads)
    std::vector<uint32_t> nextTable;      // corner -> the vertex its edge goes to (empty when allQuads)
    std::vector<uint32_t> twin;           // corner -> corner of the same edge in the other polygon, or kNone
    std::vector<uint32_t> vertexOffsets;  // CSR: the corners of live polygons at each vertex,
    std::vector<uint32_t> vertexCorners;  // and where the edge of each goes
    std::vector<uint32_t> vertexNext;

    uint32_t polygonOf(uint32_t c) const { return allQuads ? c >> 2 : polygonTable[c]; }
    uint32_t nextVertex(uint32_t c) const { return allQuads ? indices[(c & ~3u) | ((c + 1) & 3u)] : nextTable[c]; }
    uint32_t arity(uint32_t p) const { return offsets[p + 1] - offsets[p]; }
    uint32_t nextCorner(uint32_t c) const {
        const uint32_t p = polygonOf(c);
        return c + 1 < offsets[p + 1] ? c + 1 : offsets[p];
    }
    // The corner across the quad of corner c (its edge is opposite c's edge).
    uint32_t oppositeCorner(uint32_t c) const {
        const uint32_t first = offsets[polygonOf(c)];
        return first + (c - first + 2) % 4;
    }
};

// Dead polygons (see fairConstrained) get no corner in the vertex lists and no twin: to their
// neighbours they are holes.
void buildCorners(size_t vertexCount, const uint32_t *offsets, const uint32_t *indices, size_t polygonCount,
                  const std::vector<uint8_t> &livePolygon, Corners &k) {
    k.offsets = offsets;
    k.indices = indices;
    const uint32_t cornerCount = offsets[polygonCount];
    k.allQuads = cornerCount == 4 * polygonCount;
    for (size_t p = 0; k.allQuads && p < polygonCount; ++p)
        k.allQuads = offsets[p + 1] - offsets[p] == 4;
    if (!k.allQuads) {
        k.polygonTable.resize(cornerCount);
        k.nextTable.resize(cornerCount);
        for (uint32_t p = 0; p < polygonCount; ++p)
            for (uint32_t c = offsets[p]; c < offsets[p + 1]; ++c) {
                k.polygonTable[c] = p;
                k.nextTable[c] = indices[c + 1 < offsets[p + 1] ? c + 1 : offsets[p]];
            }
    }
    // Counting sort of the corners by vertex: count into offsets[v + 2], prefix, then fill
    // through offsets[v + 1], which leaves every offset in place.
    k.vertexOffsets.assign(vertexCount + 2, 0);
    for (uint32_t c = 0; c < cornerCount; ++c)
        if (livePolygon[k.polygonOf(c)])
            ++k.vertexOffsets[indices[c] + 2];
    for (size_t v = 1; v < vertexCount + 1; ++v)
        k.vertexOffsets[v + 1] += k.vertexOffsets[v];
    k.vertexCorners.resize(k.vertexOffsets[vertexCount + 1]);
    k.vertexNext.resize(k.vertexCorners.size());
    for (uint32_t c = 0; c < cornerCount; ++c)
        if (livePolygon[k.polygonOf(c)]) {
            const uint32_t slot = k.vertexOffsets[indices[c] + 1]++;
            k.vertexCorners[slot] = c;
            k.vertexNext[slot] = k.nextVertex(c);
        }
    k.vertexOffsets.pop_back();

    // Twins: a -> b and the one edge b -> a, when no other polygon has either direction. Anything
    // else (a boundary, a non-manifold or misoriented edge) stays without twin and counts as sharp.
    auto edgesFrom = [&](uint32_t from, uint32_t to, uint32_t &found) {
        uint32_t count = 0;
        for (uint32_t i = k.vertexOffsets[from]; i < k.vertexOffsets[from + 1]; ++i)
            if (k.vertexNext[i] == to) {
                found = k.vertexCorners[i];
                ++count;
            }
        return count;
    };
    k.twin.assign(cornerCount, kNone);
    for (uint32_t c = 0; c < cornerCount; ++c) {
        const uint32_t a = indices[c], b = k.nextVertex(c);
        if (k.twin[c] != kNone || a == b || !livePolygon[k.polygonOf(c)])
            continue;
        uint32_t back = kNone, same = kNone;
        if (edgesFrom(b, a, back) == 1 && edgesFrom(a, b, same) == 1 && k.polygonOf(back) != k.polygonOf(c)) {
            k.twin[c] = back;
            k.twin[back] = c;
        }
    }
}

// Step 1 of the header: which edges stay sharp. Returns one flag per corner (both corners of a
// manifold edge agree); counts into the report.
std::vector<uint8_t> classifyEdges(const Corners &k, size_t polygonCount, const std::vector<uint8_t> &livePolygon,
                                   const glm::vec3 *positions, const std::vector<glm::vec3> &unitNormal,
                                   const ConstrainedFairingOptions &options, ConstrainedFairingReport &report) {
    const uint32_t cornerCount = k.offsets[polygonCount];
    const float creaseCos = std::cos(options.creaseAngleDegrees * 3.14159265f / 180.0f);

    // +1 convex crease, -1 concave crease, 0 flat (or no twin). Convex: the far end of the other
    // polygon's next edge lies below this polygon's plane.
    std::vector<int8_t> crease(cornerCount, 0);
    for (uint32_t c = 0; c < cornerCount; ++c) {
        const uint32_t t = k.twin[c];
        if (t == kNone || t < c)
            continue;
        const glm::vec3 &np = unitNormal[k.polygonOf(c)], &nq = unitNormal[k.polygonOf(t)];
        if (glm::dot(np, nq) >= creaseCos)
            continue;
        const uint32_t a = k.indices[c], far = k.nextVertex(k.nextCorner(t));  // t runs b -> a
        const int8_t sign = glm::dot(np, positions[far] - positions[a]) < 0.0f ? 1 : -1;
        crease[c] = crease[t] = sign;
        ++report.creaseEdges;
    }

    std::vector<uint8_t> sharp(cornerCount, 0);
    if (options.keepSharpEdges) {
        // Walks across quads away from the edge of corner c, through flat edges, to the next
        // crease: its corner and how many quads were crossed (kNone past maxSteps, at a boundary
        // or at a polygon that is not a quad).
        struct WalkEnd {
            uint32_t corner = kNone;
            int steps = 0;
        };
        auto walk = [&](uint32_t c, int maxSteps) {
            for (int step = 1; step <= maxSteps && k.arity(k.polygonOf(c)) == 4; ++step) {
                const uint32_t opposite = k.oppositeCorner(c);
                if (crease[opposite] != 0)
                    return WalkEnd{opposite, step};
                if (k.twin[opposite] == kNone)
                    break;
                c = k.twin[opposite];
            }
            return WalkEnd{};
        };

        struct Candidate {
            uint32_t corner;
            bool thin;
        };
        std::vector<Candidate> candidates;
        for (uint32_t c = 0; c < cornerCount; ++c) {
            const uint32_t t = k.twin[c];
            if (crease[c] == 0 || t < c)
                continue;
            const WalkEnd side[2] = {walk(c, options.stepReach), walk(t, options.stepReach)};
            // The nearest crease within stepReach decides: turning back = a riser (staircase);
            // turning the same way one quad away = a 1-voxel plate or rod (genuine).
            int nearest = options.stepReach + 1;
            for (const WalkEnd &s : side)
                if (s.corner != kNone)
                    nearest = std::min(nearest, s.steps);
            bool step = false, sameAtNearest = false;
            for (const WalkEnd &s : side)
                if (s.corner != kNone && s.steps == nearest)
                    (crease[s.corner] != crease[c] ? step : sameAtNearest) = true;
            const bool isThin = !step && sameAtNearest && nearest == 1;
            if (!step && !isThin)
                for (const WalkEnd &s : side)
                    if (s.corner != kNone && crease[s.corner] != crease[c])
                        step = true;
            if (step)
                continue;
            sharp[c] = sharp[t] = 1;
            candidates.push_back({c, isThin});
        }
        // A straight edge whose faces end, both ways, on staircase steps is a flat run of a
        // rounded part (a circle of radius 3 voxelizes with a 5-voxel straight corner).
        std::vector<uint32_t> demoted;
        if (options.featureReach > 0)
            for (const Candidate &candidate : candidates) {
                const uint32_t c = candidate.corner;
                if (candidate.thin)
                    continue;
                const uint32_t a = walk(c, options.featureReach).corner, b = walk(k.twin[c], options.featureReach).corner;
                if (a != kNone && b != kNone && !sharp[a] && !sharp[b])
                    demoted.push_back(c);
            }
        for (uint32_t c : demoted)
            sharp[c] = sharp[k.twin[c]] = 0;
        // A single sharp edge touching no other is a corner of a small pole terrace, not a feature.
        std::vector<uint8_t> degree(k.vertexOffsets.size() - 1, 0);
        for (const Candidate &candidate : candidates)
            if (sharp[candidate.corner])
                for (uint32_t v : {k.indices[candidate.corner], k.nextVertex(candidate.corner)})
                    degree[v] = uint8_t(std::min(degree[v] + 1, 2));
        for (const Candidate &candidate : candidates) {
            const uint32_t c = candidate.corner;
            if (sharp[c] && degree[k.indices[c]] == 1 && degree[k.nextVertex(c)] == 1)
                sharp[c] = sharp[k.twin[c]] = 0;
        }
    }

    // Boundary, non-manifold and misoriented edges of live polygons are always sharp.
    for (uint32_t c = 0; c < cornerCount; ++c) {
        if (!livePolygon[k.polygonOf(c)] || k.indices[c] == k.nextVertex(c))
            continue;
        if (k.twin[c] == kNone)
            sharp[c] = 1;
        if (sharp[c] && (k.twin[c] == kNone || k.twin[c] > c))
            ++report.sharpEdges;
    }
    return sharp;
}

}  // namespace

ConstrainedFairingReport fairConstrained(glm::vec3 *positions, size_t vertexCount, const uint32_t *polygonOffsets,
                                         const uint32_t *polygonIndices, size_t polygonCount,
                                         const uint8_t *vertexSelected, const ConstrainedFairingOptions &options) {
    ConstrainedFairingReport report;
    auto finish = [&](FairingStatus status, const char *message) {
        report.status = status;
        report.message = message;
        return report;
    };
    if (options.passes < 0 || options.normalLevels < 0 || options.normalLevels > 8 || options.positionSweeps < 0 ||
        options.stepReach < 1 || options.featureReach < 0 || !(options.cellHalfWidth > 0.0f) ||
        !std::isfinite(options.cellHalfWidth) ||
        !(options.creaseAngleDegrees > 0.0f && options.creaseAngleDegrees < 180.0f) ||
        !std::isfinite(options.voxelSize) || options.voxelSize < 0.0f)
        return finish(FairingStatus::InvalidOptions,
                      "passes, positionSweeps >= 0, normalLevels in [0, 8], stepReach >= 1, featureReach >= 0, "
                      "cellHalfWidth > 0, creaseAngle in (0, 180), voxelSize finite and >= 0");
    if (PolygonMeshError e = validatePolygons(vertexCount, polygonOffsets, polygonIndices, polygonCount);
        e != PolygonMeshError::None)
        return finish(FairingStatus::InvalidMesh, describe(e));
    if (!positions && vertexCount > 0)
        return finish(FairingStatus::InvalidMesh, "positions missing (null)");
    if (vertexCount == 0 || polygonCount == 0)
        return finish(FairingStatus::NothingToDo, "no vertex or no polygon");
    if (options.passes == 0)
        return finish(FairingStatus::NothingToDo, "zero passes requested");

    report.voxelSize = options.voxelSize > 0.0f
                           ? options.voxelSize
                           : detectVoxelSize(positions, vertexCount, polygonOffsets, polygonIndices, polygonCount);
    if (!(report.voxelSize > 0.0f))
        return finish(FairingStatus::NothingToDo, "no polygon edge of non-zero finite length to take the voxel size from");

    std::vector<VertexKind> kind(vertexCount, VertexKind::Free);
    for (size_t v = 0; v < vertexCount; ++v)
        if (!isFinite(positions[v])) {
            kind[v] = VertexKind::Skipped;
            ++report.skippedVertices;
        }

    // Live polygons: 3+ corners, finite vertices, non-zero area. The others are holes.
    std::vector<glm::vec3> normal(polygonCount + 1, glm::vec3(0.0f));  // [polygonCount]: "no neighbour"
    std::vector<uint8_t> live(polygonCount, 0);
    for (size_t p = 0; p < polygonCount; ++p) {
        const uint32_t first = polygonOffsets[p], last = polygonOffsets[p + 1];
        bool finite = last - first >= 3;
        for (uint32_t i = first; finite && i < last; ++i)
            finite = kind[polygonIndices[i]] != VertexKind::Skipped;
        if (!finite)
            continue;
        normal[p] = areaNormal(positions, polygonIndices, first, last);
        live[p] = normal[p] != glm::vec3(0.0f);
    }

    Corners k;
    buildCorners(vertexCount, polygonOffsets, polygonIndices, polygonCount, live, k);
    const std::vector<uint8_t> sharp = classifyEdges(k, polygonCount, live, positions, normal, options, report);

    // Vertex kinds from the sharp edges around them (each edge counted once per end).
    const uint32_t cornerCount = polygonOffsets[polygonCount];
    std::vector<uint8_t> sharpDegree(vertexCount, 0);
    for (uint32_t c = 0; c < cornerCount; ++c)
        if (sharp[c] && (k.twin[c] == kNone || k.twin[c] > c))
            for (uint32_t v : {polygonIndices[c], k.nextVertex(c)})
                sharpDegree[v] = uint8_t(std::min(sharpDegree[v] + 1, 3));
    std::vector<uint32_t> freeVertices, lineVertices;
    for (size_t v = 0; v < vertexCount; ++v) {
        if (kind[v] == VertexKind::Skipped)
            continue;
        if ((vertexSelected && !vertexSelected[v]) || k.vertexOffsets[v] == k.vertexOffsets[v + 1] ||
            (sharpDegree[v] != 0 && sharpDegree[v] != 2)) {
            kind[v] = VertexKind::Pinned;
            ++report.pinnedVertices;
        } else if (sharpDegree[v] == 2) {
            kind[v] = VertexKind::EdgeLine;
            lineVertices.push_back(uint32_t(v));
        } else {
            freeVertices.push_back(uint32_t(v));
        }
    }
    report.edgeLineVertices = lineVertices.size();

    // Step 2's neighbours, per level and corner: the polygon 2^level quads straight across the
    // corner's edge (polygonCount, a zero normal, when a sharp edge, a hole or a non-quad is in
    // the way; at level 0 any polygon across a smooth edge). By pointer doubling: each table
    // first holds the corner reached 2^level quads on, facing on, then that corner's polygon.
    const int levels = options.normalLevels;
    std::vector<std::vector<uint32_t>> across(levels);
    for (int level = 0; level < levels; ++level) {
        std::vector<uint32_t> &ahead = across[level];
        ahead.resize(cornerCount);
        for (uint32_t c = 0; c < cornerCount; ++c) {
            if (level == 0) {
                const uint32_t t = k.twin[c];
                ahead[c] = t != kNone && !sharp[c] && k.arity(k.polygonOf(t)) == 4 ? k.oppositeCorner(t) : kNone;
            } else {
                const uint32_t midway = across[level - 1][c];
                ahead[c] = midway != kNone ? across[level - 1][midway] : kNone;
            }
        }
    }
    for (int level = levels - 1; level >= 0; --level)
        for (uint32_t c = 0; c < cornerCount; ++c) {
            uint32_t &entry = across[level][c];
            if (level == 0)
                entry = k.twin[c] != kNone && !sharp[c] ? k.polygonOf(k.twin[c]) : uint32_t(polygonCount);
            else
                entry = entry != kNone ? k.polygonOf(entry) : uint32_t(polygonCount);
        }

    const std::vector<glm::vec3> input(positions, positions + vertexCount);
    const glm::vec3 half(options.cellHalfWidth * report.voxelSize);
    std::vector<glm::vec3> filtered(polygonCount + 1, glm::vec3(0.0f)), vertexNormal(vertexCount, glm::vec3(0.0f));
    std::vector<uint8_t> edgeUse(k.vertexNext.size(), kUnused);
    std::vector<float> stepScale(freeVertices.size());

    for (int pass = 0; pass < options.passes; ++pass) {
        if (pass > 0)
            for (size_t p = 0; p < polygonCount; ++p)
                if (live[p])
                    normal[p] = areaNormal(positions, polygonIndices, polygonOffsets[p], polygonOffsets[p + 1]);
        // Step 2 (Jacobi, a trous): each polygon's normal becomes the mean of itself and the four
        // polygons 1, 2, 4, ... quads away, so each level doubles the reach (Holschneider et al.,
        // "A real-time algorithm for signal analysis with the help of the wavelet transform", 1989).
        // Later passes start from the faired surface, whose normals need one level less (measured:
        // smaller errors on spheres, tori and cylinders than with all levels again).
        const int passLevels = pass == 0 ? levels : std::max(levels - 1, std::min(levels, 1));
        for (int level = 0; level < passLevels; ++level) {
            const std::vector<uint32_t> &table = across[level];
            for (size_t p = 0; p < polygonCount; ++p) {
                glm::vec3 sum = normal[p];
                for (uint32_t c = polygonOffsets[p]; c < polygonOffsets[p + 1]; ++c)
                    sum += normal[table[c]];
                filtered[p] = normalizedOrZero(sum);
            }
            normal.swap(filtered);
        }
        for (uint32_t v : freeVertices) {
            glm::vec3 sum(0.0f);
            for (uint32_t j = k.vertexOffsets[v]; j < k.vertexOffsets[v + 1]; ++j)
                sum += normal[k.polygonOf(k.vertexCorners[j])];
            vertexNormal[v] = normalizedOrZero(sum);
        }
        // Step 3's least squares for a free vertex v with normal n: each edge v-u wants to be
        // perpendicular to s = n + n_u (to the bisector of the two normals, which holds exactly on
        // a sphere); v moves along n by 2 sum s.(x_u - x_v) / sum |s|^2. A neighbour that is not
        // free lends n (s = 2n); one more than 90 degrees away (another sheet) is left out.
        for (size_t i = 0; i < freeVertices.size(); ++i) {
            const uint32_t v = freeVertices[i];
            const glm::vec3 n = vertexNormal[v];
            float sum2 = 0.0f;
            for (uint32_t j = k.vertexOffsets[v]; j < k.vertexOffsets[v + 1]; ++j) {
                const uint32_t u = k.vertexNext[j];
                const bool lend = kind[u] != VertexKind::Free;
                const glm::vec3 s = n + (lend ? n : vertexNormal[u]);
                const float s2 = glm::dot(s, s);
                edgeUse[j] = s2 > 2.0f ? (lend ? kLendNormal : kBothNormals) : kUnused;
                sum2 += s2 > 2.0f ? s2 : 0.0f;
            }
            stepScale[i] = sum2 > 0.0f ? 2.0f / sum2 : 0.0f;
        }

        // Gauss-Seidel sweeps, each vertex clamped into its cell (step 4) as it moves.
        for (int sweep = 0; sweep < options.positionSweeps; ++sweep) {
            // On a sharp edge line: towards the plane of each polygon through its centroid.
            for (uint32_t v : lineVertices) {
                const glm::vec3 x = positions[v];
                glm::vec3 move(0.0f);
                for (uint32_t j = k.vertexOffsets[v]; j < k.vertexOffsets[v + 1]; ++j) {
                    const uint32_t p = k.polygonOf(k.vertexCorners[j]);
                    glm::vec3 centroid(0.0f);
                    for (uint32_t c = polygonOffsets[p]; c < polygonOffsets[p + 1]; ++c)
                        centroid += positions[polygonIndices[c]];
                    centroid /= float(k.arity(p));
                    move += normal[p] * glm::dot(normal[p], centroid - x);
                }
                move /= float(k.vertexOffsets[v + 1] - k.vertexOffsets[v]);
                positions[v] = glm::clamp(x + move, input[v] - half, input[v] + half);
            }
            // Free vertices, alternating direction so that no side of the mesh leads.
            const size_t count = freeVertices.size();
            for (size_t step = 0; step < count; ++step) {
                const size_t i = sweep % 2 == 0 ? step : count - 1 - step;
                const uint32_t v = freeVertices[i];
                const glm::vec3 x = positions[v], n = vertexNormal[v];
                float along = 0.0f;
                for (uint32_t j = k.vertexOffsets[v]; j < k.vertexOffsets[v + 1]; ++j) {
                    const uint32_t u = k.vertexNext[j];
                    if (edgeUse[j] == kBothNormals)
                        along += glm::dot(n + vertexNormal[u], positions[u] - x);
                    else if (edgeUse[j] == kLendNormal)
                        along += 2.0f * glm::dot(n, positions[u] - x);
                }
                positions[v] = glm::clamp(x + (along * stepScale[i]) * n, input[v] - half, input[v] + half);
            }
        }
        ++report.passes;
    }

    const float moved2 = 1e-12f * report.voxelSize * report.voxelSize;
    float maxMove2 = 0.0f;
    for (const std::vector<uint32_t> *list : {&freeVertices, &lineVertices})
        for (uint32_t v : *list) {
            const glm::vec3 d = positions[v] - input[v];
            const float d2 = glm::dot(d, d);
            maxMove2 = std::max(maxMove2, d2);
            if (d2 > moved2)
                ++report.movedVertices;
            if (glm::any(glm::greaterThanEqual(glm::abs(d), half * (1.0f - 1e-5f))))
                ++report.clampedVertices;
        }
    report.maxDisplacement = std::sqrt(maxMove2);
    return finish(FairingStatus::Ok, "ok");
}

}  // namespace voxelfair
