// Flat faces at any orientation: digital plane regions of the voxel surface, fitted planes, and the
// vertices they hold (the constrained fairing's feature stage beyond the lattice classes of
// edge_classes.cpp).
//
// The idea: a quad of the voxel surface separates the centre of a solid voxel p_in from the centre
// of an empty one p_out = p_in + a (a its unit normal, one voxel long). A plane (N, c) can be the
// true surface there only if it separates them: N . p_in < c <= N . p_out. A set of quads is a
// piece of one flat face exactly when one plane separates all of their centres (digital plane
// recognition; Reveilles, "Geometrie discrete, calcul en nombres entiers et algorithmique", 1991;
// for the recognition as linear separability see Debled-Rennesson and Reveilles, "A linear
// algorithm for segmentation of digital curves", 1995). So flat faces are found, at any
// orientation, by growing regions of quads that one plane separates, and their plane is fitted to
// the quads themselves, not to smoothed normals: a face of a turned box comes out flat, at the
// right offset (no drift, no pillow), and two faces meet in a straight, sharp edge (their planes'
// line), as in feature-preserving reconstruction by plane intersection.
//
// Contract (findPlaneRegions; quads only; reads the input positions, the live polygons, the
// filtered normals `normal` of the first pass, the level tables; fills `anchored`: vertices held
// at a fixed offset with the normal they lend to their neighbours, and cuts the level tables
// between a region and faces turned away from it):
// - Seeds: quads whose filtered normal agrees within kSeedDegrees with their neighbours 1 and 2
//   quads away, and whose 3-ring of quads one plane separates.
// - Growth: from the seed, quads the current fit separates within a slack (loose, then tighter,
//   refitting in between) and whose filtered normal is within kGrowDegrees of the plane's.
// - Fit: N by weighted principal components of the quad centres (weights N . a, the quads'
//   projected areas), c centred between the inside and outside centres (the plane that keeps the
//   voxels' volume).
// - A region counts when it has at least kMinQuads quads, spreads at least kMinSpread voxels in
//   both directions of its plane, and is flat: the curvature of a paraboloid fitted to its
//   centres is within 3 standard errors of 0 (a large sphere's patch is not a plane).
// - Vertices: all of whose quads are in one region go onto its plane; in two regions (an edge),
//   onto the nearest point of their line; in three or more (a corner), onto the planes' least
//   squares point; each clamped into its cell. A vertex with a quad in no region stays free, and
//   so do plane vertices next to it (a fillet bends into the flat face).
#include "fairing/constrained/fairing_state.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {
namespace {

constexpr double kSeedDegrees = 8.0;
constexpr double kGrowDegrees = 25.0;
constexpr double kAgreeDegrees = 9.0;
constexpr double kExactAgreeDegrees = 4.0;
constexpr double kCutDegrees = 30.0;  // normal filtering stops between a region and faces this far off
constexpr int kSeedRings = 3;
constexpr size_t kMinQuads = 32;
constexpr double kMinSpread = 1.5;
constexpr double kSlack[] = {0.25, 0.1, 0.03};  // growth rounds, in voxels

struct Plane {
    glm::dvec3 n;
    double c;
};

double cosDegrees(double degrees) { return std::cos(degrees * 3.14159265358979 / 180.0); }

// What the plane stage works on: per quad its unit axis normal a, centre m (voxel units, input),
// and the filtered normal g.
struct Quads {
    std::vector<glm::dvec3> a, m;
    std::vector<glm::vec3> g;
    std::vector<uint32_t> neighbour;  // 4 per quad (level 0 across each edge), kNone when none
    double voxel;
};

// Weighted principal components: the normal nearest `start` of the plane through the quads'
// centres (weights max(N . a, 0)), then c between their inside and outside centres.
Plane fitPlane(const Quads &q, const std::vector<uint32_t> &faces, glm::dvec3 start) {
    Plane p{glm::normalize(start), 0.0};
    for (int round = 0; round < 3; ++round) {
        double weight = 0.0;
        glm::dvec3 mean(0.0);
        for (uint32_t f : faces) {
            const double w = std::max(glm::dot(p.n, q.a[f]), 0.0);
            weight += w;
            mean += w * q.m[f];
        }
        if (!(weight > 0.0))
            return p;
        mean /= weight;
        glm::dmat3 covariance(0.0);
        for (uint32_t f : faces) {
            const double w = std::max(glm::dot(p.n, q.a[f]), 0.0);
            const glm::dvec3 d = q.m[f] - mean;
            covariance += w * glm::outerProduct(d, d);
        }
        // Smallest eigenvector by inverse iteration from the current normal.
        const double trace = covariance[0][0] + covariance[1][1] + covariance[2][2];
        const glm::dmat3 inverse = glm::inverse(covariance + glm::dmat3(1e-9 * (trace + 1e-30)));
        glm::dvec3 n = p.n;
        for (int i = 0; i < 12; ++i)
            n = glm::normalize(inverse * n);
        if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
            return p;
        p.n = glm::dot(n, p.n) < 0.0 ? -n : n;
        p.c = glm::dot(p.n, mean);
    }
    // c: halfway between the highest inside centre and the lowest outside centre is the
    // separating plane; the volume-keeping plane is the projected-area mean, which for a digital
    // plane lies in the same band. The mean is steadier on large regions.
    return p;
}

// Whether the plane separates quad f's voxel centres, within `slack` (voxels).
bool separates(const Quads &q, const Plane &p, uint32_t f, double slack) {
    const double w = glm::dot(p.n, q.a[f]);
    return w > 0.0 && std::fabs(glm::dot(p.n, q.m[f]) - p.c) <= 0.5 * w + slack;
}

}  // namespace

template <bool kQuads>
VOXELFAIR_NOINLINE void findPlaneRegions(FairingState<kQuads> &s) {
    if constexpr (!kQuads) {
        return;
    } else {
        const size_t P = s.P, V = s.V;
        const double voxel = s.report.voxelSize;
        Quads q;
        q.voxel = voxel;
        q.a.resize(P);
        q.m.resize(P);
        q.g.assign(s.normal, s.normal + P);
        q.neighbour.assign(s.twin, s.twin + 4 * P);
        for (size_t p = 0; p < P; ++p) {
            if (!s.live[p])
                continue;
            glm::dvec3 x[4];
            for (int k = 0; k < 4; ++k)
                x[k] = glm::dvec3(s.input[s.indices[4 * p + k]]) / voxel;
            q.a[p] = glm::normalize(glm::cross(x[2] - x[0], x[3] - x[1]));
            q.m[p] = 0.25 * (x[0] + x[1] + x[2] + x[3]);
        }
        for (uint32_t &c : q.neighbour)
            c = c == kNone ? kNone : c >> 2;  // the neighbouring quad

        // Seeds: filtered normals constant over two quads each way.
        const uint32_t *level1 = s.storedLevels > 1 ? s.levelTable(1) : nullptr;
        const float seedCos = float(cosDegrees(kSeedDegrees));
        std::vector<uint8_t> candidate(P, 0);
        for (size_t p = 0; p < P; ++p) {
            if (!s.live[p])
                continue;
            bool flat = true;
            for (int k = 0; k < 4 && flat; ++k) {
                const uint32_t n1 = q.neighbour[4 * p + k];
                flat = n1 != kNone && glm::dot(q.g[p], q.g[n1]) >= seedCos;
                if (flat && level1) {
                    const uint32_t e = level1[4 * p + k];
                    flat = e != kNone && glm::dot(q.g[p], q.g[e >> 2]) >= seedCos;
                }
            }
            candidate[p] = flat;
        }

        std::vector<int32_t> region(P, -1);  // region of each quad; -2: tried, no region
        std::vector<uint32_t> stamp(P, 0);
        uint32_t stampNow = 0;
        std::vector<Plane> planes;
        std::vector<uint32_t> faces, ball;
        auto gather = [&](uint32_t seed, int rings, std::vector<uint32_t> &out) {
            out.assign(1, seed);
            ++stampNow;
            stamp[seed] = stampNow;
            size_t ringStart = 0;
            for (int ring = 0; ring < rings; ++ring) {
                const size_t ringEnd = out.size();
                for (size_t i = ringStart; i < ringEnd; ++i)
                    for (int k = 0; k < 4; ++k) {
                        const uint32_t n = q.neighbour[4 * out[i] + k];
                        if (n != kNone && stamp[n] != stampNow && region[n] == -1) {
                            stamp[n] = stampNow;
                            out.push_back(n);
                        }
                    }
                ringStart = ringEnd;
            }
        };
        const double growCos = cosDegrees(kGrowDegrees), agreeCos = cosDegrees(kAgreeDegrees);
        const double exactAgreeCos = cosDegrees(kExactAgreeDegrees);
        std::vector<double> agreement;
        for (size_t seed = 0; seed < P; ++seed) {
            if (!candidate[seed] || region[seed] != -1)
                continue;
            gather(uint32_t(seed), kSeedRings, ball);
            Plane plane = fitPlane(q, ball, glm::dvec3(q.g[seed]));
            bool separated = true;
            for (uint32_t f : ball)
                separated = separated && separates(q, plane, f, kSlack[2]);
            if (!separated) {
                for (uint32_t f : ball)
                    region[f] = -2;  // (a curved surface: its seeds fail together)
                continue;
            }
            // Grow: loose, refit, tighter.
            faces = ball;
            for (double slack : kSlack) {
                plane = fitPlane(q, faces, plane.n);
                faces.assign(1, uint32_t(seed));
                ++stampNow;
                stamp[seed] = stampNow;
                for (size_t i = 0; i < faces.size(); ++i)
                    for (int k = 0; k < 4; ++k) {
                        const uint32_t n = q.neighbour[4 * faces[i] + k];
                        if (n == kNone || stamp[n] == stampNow || region[n] != -1)
                            continue;
                        stamp[n] = stampNow;
                        if (separates(q, plane, n, slack) && glm::dot(glm::dvec3(q.g[n]), plane.n) >= growCos)
                            faces.push_back(n);
                    }
            }
            plane = fitPlane(q, faces, plane.n);
            // Flat and wide enough?
            glm::dvec3 centre(0.0);
            for (uint32_t f : faces)
                centre += q.m[f];
            centre /= double(faces.size());
            const glm::dvec3 u = glm::normalize(
                glm::cross(plane.n, std::fabs(plane.n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
            const glm::dvec3 v = glm::cross(plane.n, u);
            double uu = 0, vv = 0, uv = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
            for (uint32_t f : faces) {
                const glm::dvec3 t = q.m[f] - centre;
                const double tu = glm::dot(t, u), tv = glm::dot(t, v);
                uu += tu * tu;
                vv += tv * tv;
                uv += tu * tv;
                const double x = 0.5 * (tu * tu + tv * tv), y = glm::dot(plane.n, q.m[f]) - plane.c;
                sx += x;
                sxx += x * x;
                sy += y;
                sxy += x * y;
            }
            const double n = double(faces.size());
            uu /= n;
            vv /= n;
            uv /= n;
            const double spread2 = 0.5 * (uu + vv - std::sqrt(std::max(0.0, (uu - vv) * (uu - vv) + 4.0 * uv * uv)));
            // Least squares y = kappa x + b and the standard error of kappa.
            const double sxxc = sxx - sx * sx / n;
            const double kappa = sxxc > 0.0 ? (sxy - sx * sy / n) / sxxc : 0.0;
            double residual2 = 0.0;
            for (uint32_t f : faces) {
                const glm::dvec3 t = q.m[f] - centre;
                const double x = 0.5 * (glm::dot(t, u) * glm::dot(t, u) + glm::dot(t, v) * glm::dot(t, v));
                const double y = glm::dot(plane.n, q.m[f]) - plane.c - (kappa * x + (sy - kappa * sx) / n);
                residual2 += y * y;
            }
            const double kappaError = sxxc > 0.0 && n > 2.0 ? std::sqrt(residual2 / (n - 2.0) / sxxc) : 0.0;
            const bool exact = kappaError < 1e-4;  // every residual 0: a lattice plane or a 45-degree pattern
            const bool flat = std::fabs(kappa) <= 2.0 * kappaError + 1e-6;
            // The filtered normals agree with the plane over most of it (a sphere's flat lattice
            // cap is a digital plane, but its normals turn).
            agreement.clear();
            for (uint32_t f : faces)
                agreement.push_back(glm::dot(glm::dvec3(q.g[f]), plane.n));
            std::nth_element(agreement.begin(), agreement.begin() + agreement.size() / 2, agreement.end());
            // A region without residual (every quad on one lattice plane, or a 45-degree pattern)
            // says nothing of its curvature: its normals must agree more closely.
            const bool agrees = agreement[agreement.size() / 2] >= (exact ? exactAgreeCos : agreeCos);
            if (faces.size() < kMinQuads || spread2 < kMinSpread * kMinSpread || !flat || !agrees) {
                for (uint32_t f : faces)
                    if (region[f] == -1)
                        region[f] = -2;
                continue;
            }
            // Keep the quads the final plane separates.
            const int32_t id = int32_t(planes.size());
            planes.push_back(plane);
            for (uint32_t f : faces)
                if (separates(q, plane, f, kSlack[2]))
                    region[f] = id;
        }
        s.report.planeRegions = planes.size();
        if (planes.empty())
            return;

        // Vertex roles. (The corner lists of corner_lists.cpp are gone by now: the quads at each
        // vertex, counted again.)
        const uint32_t *const start = s.vertexStart;
        std::vector<uint32_t> fill(start, start + V), corners(s.cornerCount);
        for (uint32_t c = 0; c < s.cornerCount; ++c)
            if (s.live[c >> 2])
                corners[fill[s.indices[c]]++] = c;
        std::vector<uint8_t> role(V, 0);  // 0 free, 1 plane, 2 edge, 3 corner
        std::vector<glm::dvec3> target(V);
        std::vector<glm::vec3> lent(V);
        const double parallelCos = cosDegrees(20.0);
        for (size_t vtx = 0; vtx < V; ++vtx) {
            if (s.kind[vtx] != VertexKind::Free && s.kind[vtx] != VertexKind::FreeIrregular)
                continue;
            int32_t ids[3];
            int count = 0;
            bool curved = start[vtx] == start[vtx + 1];
            for (uint32_t i = start[vtx]; i < start[vtx + 1] && !curved; ++i) {
                const int32_t id = region[corners[i] >> 2];
                if (id < 0) {
                    curved = true;
                    break;
                }
                bool known = false;
                for (int j = 0; j < count; ++j)
                    known = known || ids[j] == id || glm::dot(planes[ids[j]].n, planes[id].n) > parallelCos;
                if (!known && count < 3)
                    ids[count++] = id;
            }
            if (curved || count == 0)
                continue;
            const glm::dvec3 x = glm::dvec3(s.input[vtx]) / voxel;
            glm::dvec3 y = x;
            if (count == 1) {
                y = x - (glm::dot(planes[ids[0]].n, x) - planes[ids[0]].c) * planes[ids[0]].n;
            } else {
                glm::dmat3 normal(0.0);
                glm::dvec3 right(0.0);
                for (int j = 0; j < count; ++j) {
                    normal += glm::outerProduct(planes[ids[j]].n, planes[ids[j]].n);
                    right += planes[ids[j]].n * planes[ids[j]].c;
                }
                if (count == 2) {  // the line's point nearest x
                    const glm::dvec3 along = glm::normalize(glm::cross(planes[ids[0]].n, planes[ids[1]].n));
                    normal += glm::outerProduct(along, along);
                    right += along * glm::dot(along, x);
                }
                y = glm::inverse(normal) * right;
            }
            role[vtx] = uint8_t(count);
            target[vtx] = y;
            glm::dvec3 n(0.0);
            for (int j = 0; j < count; ++j)
                n += planes[ids[j]].n;
            lent[vtx] = glm::vec3(glm::normalize(n));
        }
        // Plane vertices beside free ones stay free: a fillet bends into the flat face.
        const uint32_t *const next = s.vertexNext;
        std::vector<uint8_t> keep(role);
        for (size_t vtx = 0; vtx < V; ++vtx)
            if (role[vtx] == 1)
                for (uint32_t i = start[vtx]; i < start[vtx + 1]; ++i)
                    if (role[next[i]] == 0 && isFree(s.kind[next[i]]))
                        keep[vtx] = 0;
        const float half = s.half;
        for (size_t vtx = 0; vtx < V; ++vtx) {
            if (!keep[vtx])
                continue;
            const glm::vec3 d = glm::clamp(glm::vec3((target[vtx] * voxel) - glm::dvec3(s.input[vtx])), -half, half);
            s.anchored.push_back(uint32_t(vtx));
            s.anchoredOffset.push_back(d);
            s.anchoredNormal.push_back(lent[vtx]);
        }
        s.report.planeVertices = s.anchored.size();

        // Normal filtering stops between a region and faces turned away from it (a cylinder's
        // cap and side), and between two regions.
        const double cutCos = cosDegrees(kCutDegrees);
        uint32_t *const twin = s.twin;
        bool cut = false;
        for (size_t p = 0; p < P; ++p)
            for (int k = 0; k < 4; ++k) {
                const uint32_t c = uint32_t(4 * p + k), t = twin[c];
                if (t == kNone)
                    continue;
                const int32_t a = region[p], b = region[t >> 2];
                if (a < 0 && b < 0)
                    continue;
                const bool apart = (a >= 0 && b >= 0) ? a != b
                                                      : glm::dot(glm::dvec3(q.g[a >= 0 ? t >> 2 : p]),
                                                                 planes[a >= 0 ? a : b].n) < cutCos;
                if (apart) {
                    twin[c] = kNone;
                    cut = true;
                }
            }
        if (cut)
            buildLevels(s);  // (idempotent on the edges it strips; redoubles the levels)
    }
}

template void findPlaneRegions(FairingState<true> &);
template void findPlaneRegions(FairingState<false> &);

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
