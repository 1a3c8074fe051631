// The source's triangles in the target's UV space; the contract is in source_cover.h.
#include "maps/source_cover.h"

#include "atlas/edge_adjacency.h"
#include "maps/surface_walk.h"
#include "maps/uv_face_index.h"
#include "base/simd_variant.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#if VOXELFAIR_SSE2
#include <emmintrin.h>
#endif

namespace voxelfair {

namespace {

constexpr int kCell = 16;        // the target's UV grid, texels a side
constexpr float kMinCos = 0.5f;  // a ray meets a target face at most 60 degrees off its normal
constexpr int kMaxSteps = 32;
constexpr float kMaxCoverArea = 128.0f;  // twice the largest UV area (texels) a face covers
constexpr float kOnEdge = 1e-5f;         // a weight this far below 0 still inside

// The target's faces by the grid cells their UV boxes meet, and the face holding a UV point.
class TargetUvGrid {
    // The cell of a finite texel-space coordinate (clamped to the side first: no overflow).
    static int cellOf(double t, int side, int cells) {
        return std::clamp(int(std::clamp(t, 0.0, double(side))) / kCell, 0, cells - 1);
    }

public:
    TargetUvGrid(const NormalBakeMesh &target, int width, int height)
        : target_(target), width_(width), height_(height), cellsX_((width + kCell - 1) / kCell),
          cellsY_((height + kCell - 1) / kCell), start_(size_t(cellsX_) * size_t(cellsY_) + 1, 0) {
        std::vector<int> box(4 * target.faceCount);
        for (size_t f = 0; f < target.faceCount; ++f) {
            glm::dvec2 q[3];
            loadUv(target, f, width, height, q);
            const glm::dvec2 lo = glm::min(q[0], glm::min(q[1], q[2])), hi = glm::max(q[0], glm::max(q[1], q[2]));
            int *const b = &box[4 * f];
            if (!std::isfinite(lo.x) || !std::isfinite(lo.y) || !std::isfinite(hi.x) || !std::isfinite(hi.y)) {
                b[0] = 1, b[1] = 0, b[2] = 1, b[3] = 0;
                continue;
            }
            b[0] = cellOf(lo.x, width, cellsX_), b[1] = cellOf(hi.x, width, cellsX_);
            b[2] = cellOf(lo.y, height, cellsY_), b[3] = cellOf(hi.y, height, cellsY_);
            for (int y = b[2]; y <= b[3]; ++y)
                for (int x = b[0]; x <= b[1]; ++x)
                    ++start_[size_t(y) * size_t(cellsX_) + size_t(x) + 1];
        }
        for (size_t c = 1; c < start_.size(); ++c)
            start_[c] += start_[c - 1];
        faces_.resize(start_.back());
        std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
        for (size_t f = 0; f < target.faceCount; ++f) {
            const int *const b = &box[4 * f];
            for (int y = b[2]; y <= b[3]; ++y)
                for (int x = b[0]; x <= b[1]; ++x)
                    faces_[fill[size_t(y) * size_t(cellsX_) + size_t(x)]++] = uint32_t(f);
        }
    }
    // The first face of p's cell whose UV triangle holds texel-space point p, else the one with
    // the nearest UV centroid; UINT32_MAX when none meets the cell.
    // Whether face f's UV triangle holds texel-space point p.
    bool holds(uint32_t f, glm::vec2 p) const {
        const glm::vec2 scale{float(width_), float(height_)};
        const glm::vec2 *uv = &target_.wedgeUv[3 * size_t(f)];
        const glm::vec2 a = uv[0] * scale, b = uv[1] * scale, d = uv[2] * scale;
        const float area = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
        const float s = area > 0.0f ? 1.0f : -1.0f;
        const float e0 = s * ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x));
        const float e1 = s * ((d.x - b.x) * (p.y - b.y) - (d.y - b.y) * (p.x - b.x));
        const float e2 = s * ((a.x - d.x) * (p.y - d.y) - (a.y - d.y) * (p.x - d.x));
        return area != 0.0f && e0 >= 0.0f && e1 >= 0.0f && e2 >= 0.0f;
    }
    uint32_t find(glm::vec2 p) const {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            return UINT32_MAX;
        const int cx = cellOf(p.x, width_, cellsX_), cy = cellOf(p.y, height_, cellsY_);
        const size_t c = size_t(cy) * size_t(cellsX_) + size_t(cx);
        uint32_t nearest = UINT32_MAX;
        float best = 0.0f;
        const glm::vec2 scale{float(width_), float(height_)};
        for (uint32_t i = start_[c]; i < start_[c + 1]; ++i) {
            const uint32_t f = faces_[i];
            const glm::vec2 *uv = &target_.wedgeUv[3 * size_t(f)];
            const glm::vec2 a = uv[0] * scale, b = uv[1] * scale, d = uv[2] * scale;
            const float area = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
            const float s = area > 0.0f ? 1.0f : -1.0f;
            const float e0 = s * ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x));
            const float e1 = s * ((d.x - b.x) * (p.y - b.y) - (d.y - b.y) * (p.x - b.x));
            const float e2 = s * ((a.x - d.x) * (p.y - d.y) - (a.y - d.y) * (p.x - d.x));
            if (area != 0.0f && e0 >= 0.0f && e1 >= 0.0f && e2 >= 0.0f)
                return f;
            const glm::vec2 centroid = (a + b + d) / 3.0f;
            const float distance = glm::dot(centroid - p, centroid - p);
            if (nearest == UINT32_MAX || distance < best)
                nearest = f, best = distance;
        }
        return nearest;
    }

private:
    const NormalBakeMesh &target_;
    int width_, height_, cellsX_, cellsY_;
    std::vector<uint32_t> start_, faces_;
};

// The target's charts: faces joined across the edges whose two sides have the same UVs.
std::vector<uint32_t> targetCharts(const NormalBakeMesh &target, const std::vector<uint32_t> &opposite) {
    std::vector<uint32_t> parent(target.faceCount);
    for (size_t f = 0; f < target.faceCount; ++f)
        parent[f] = uint32_t(f);
    auto root = [&](uint32_t f) {
        while (parent[f] != f)
            f = parent[f] = parent[parent[f]];
        return f;
    };
    for (size_t h = 0; h < 3 * target.faceCount; ++h) {
        const uint32_t o = opposite[h];
        if (o == kNoOpposite || o < h)
            continue;
        const size_t f = h / 3, g = o / 3;
        const glm::vec2 *a = &target.wedgeUv[3 * f], *b = &target.wedgeUv[3 * g];
        // Half-edge h runs from corner h % 3 to the next; o runs the other way.
        if (a[h % 3] == b[(o % 3 + 1) % 3] && a[(h % 3 + 1) % 3] == b[o % 3]) {
            const uint32_t r = root(uint32_t(f)), s = root(uint32_t(g));
            parent[std::max(r, s)] = std::min(r, s);
        }
    }
    for (size_t f = 0; f < target.faceCount; ++f)
        parent[f] = root(uint32_t(f));
    return parent;
}

// The target point where the ray from v along n meets the target, walking from face `face`
// (each step across the edge past which the ray's crossing of the face's plane lies): false
// where the ray leaves the surface, meets a face more than 60 degrees off its way, lies farther
// from the face than the walk's near-plane bound, or runs out of steps.
bool carry(const SurfaceWalk &walk, const glm::vec3 &v, const glm::vec3 &n, uint32_t &face, glm::vec3 &w) {
    uint32_t previous = UINT32_MAX;
    for (int step = 0; step < kMaxSteps; ++step) {
        const SurfaceWalk::Face &r = walk.record(face);
        const float c = glm::dot(n, r.normal);
        if (!(c > kMinCos))
            return false;
        const float height = glm::dot(r.origin - v, r.normal);
        const glm::vec3 d = v + (height / c) * n - r.origin;
        const float w1 = glm::dot(d, r.dual1), w2 = glm::dot(d, r.dual2);
        w = glm::vec3(1.0f - w1 - w2, w1, w2);
        const int k = SurfaceWalk::mostNegative(w);
        if (w[k] >= -kOnEdge)  // on an edge within rounding: taken, not walked back and forth
            return height * height <= r.nearPlane;
        const uint32_t across = r.opposite[(k + 1) % 3];
        if (across == UINT32_MAX || across / 3 == previous)
            return false;
        previous = face;
        face = across / 3;
    }
    return false;
}

}  // namespace

SourceCover coverSource(const NormalBakeMesh &source, const NormalBakeMesh &target, int width, int height) {
    const std::vector<uint32_t> opposite =
        buildEdgeAdjacency(target.triangles, target.faceCount, target.vertexCount).opposite;
    const std::vector<uint32_t> chart = targetCharts(target, opposite);
    const SurfaceWalk walk(target.positions, nullptr, target.triangles, target.faceCount, target.vertexCount,
                           opposite.data());
    const TargetUvGrid grid(target, width, height);
    const glm::vec2 scale{float(width), float(height)};

    // Each source vertex carried once, from the UV of the first corner that names it.
    constexpr uint32_t kNotYet = UINT32_MAX, kMissed = UINT32_MAX - 1;
    std::vector<uint32_t> vertexFace(source.vertexCount, kNotYet);
    std::vector<glm::vec2> vertexUv(source.vertexCount);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    SourceCover out;
    out.uv.resize(3 * source.faceCount);
    uint32_t lastStart = UINT32_MAX;
    for (size_t f = 0; f < source.faceCount; ++f) {
        uint32_t faces[3];
        for (int k = 0; k < 3; ++k) {
            const size_t c = 3 * f + size_t(k);
            const uint32_t v = source.triangles[c];
            if (vertexFace[v] == kNotYet) {
                // The face under the corner's UV: most often the last start's (faces come in UV
                // order), else the grid's.
                const glm::vec2 at = source.wedgeUv[c] * scale;
                uint32_t face = lastStart != UINT32_MAX && grid.holds(lastStart, at) ? lastStart : grid.find(at);
                lastStart = face;
                glm::vec3 w;
                const float length = glm::length(source.normals[v]);
                if (face != UINT32_MAX && length > 0.0f &&
                    carry(walk, source.positions[v], source.normals[v] / length, face, w)) {
                    vertexFace[v] = face;
                    const glm::vec2 *uv = &target.wedgeUv[3 * size_t(face)];
                    vertexUv[v] = w.x * uv[0] + w.y * uv[1] + w.z * uv[2];
                } else {
                    vertexFace[v] = kMissed;
                }
            }
            faces[k] = vertexFace[v];
        }
        glm::vec2 *const to = &out.uv[3 * f];
        bool covers = faces[0] < kMissed && faces[1] < kMissed && faces[2] < kMissed &&
                      chart[faces[0]] == chart[faces[1]] && chart[faces[0]] == chart[faces[2]];
        if (covers) {
            const glm::vec2 *s = &source.wedgeUv[3 * f];
            for (int k = 0; k < 3; ++k)
                to[k] = vertexUv[source.triangles[3 * f + size_t(k)]];
            auto area = [&](const glm::vec2 *q) {
                return ((q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x)) * scale.x *
                       scale.y;
            };
            const float a = area(to), b = area(s);
            covers = a * b > 0.0f && std::abs(a) > 0.25f * std::abs(b) && std::abs(a) < 4.0f * std::abs(b) &&
                     std::abs(b) <= kMaxCoverArea;
        }
        if (covers)
            ++out.coveringFaces;
        else
            to[0] = to[1] = to[2] = glm::vec2(nan);
    }
    out.mesh = source;
    out.mesh.wedgeUv = out.uv.data();
    return out;
}

void coverFaces(const SourceCover &cover, const glm::vec3 *cornerNormals, const uint32_t *faces, size_t count,
                int width, int height, int r0, int r1, CoverRows &rows) {
    const size_t n = size_t(r1 - r0) * size_t(width);
    rows.face.assign(n + 4, UINT32_MAX);
    if (rows.nx.size() < n + 4)  // 4 lanes past the end (the spans' last 4, TexelBatch::setRun)
        rows.nx.resize(n + 4), rows.ny.resize(n + 4), rows.nz.resize(n + 4);
    const glm::vec2 scale{float(width), float(height)};
    for (size_t i = 0; i < count; ++i) {
        const uint32_t f = faces[i];
        const glm::vec2 *uv = &cover.uv[3 * size_t(f)];
        const glm::vec2 q0 = uv[0] * scale, e1 = uv[1] * scale - q0, e2 = uv[2] * scale - q0;
        const float d = e1.x * e2.y - e1.y * e2.x;
        if (!(d != 0.0f) || !std::isfinite(d))
            continue;
        // w1 = cross(p - q0, e2) / d, w2 = cross(e1, p - q0) / d at texel centres p; the normal
        // n0 + w1 (n1 - n0) + w2 (n2 - n0), affine in p: c + p.x sx + p.y sy.
        const float ax = e2.y / d, ay = -e2.x / d, bx = -e1.y / d, by = e1.x / d;
        const glm::vec3 *cn = &cornerNormals[3 * size_t(f)];
        const glm::vec3 d1 = cn[1] - cn[0], d2 = cn[2] - cn[0];
        const glm::vec3 sx = ax * d1 + bx * d2, sy = ay * d1 + by * d2, c = cn[0] - q0.x * sx - q0.y * sy;
#if VOXELFAIR_SSE2
        const __m128 cx = _mm_set1_ps(c.x), cy = _mm_set1_ps(c.y), cz = _mm_set1_ps(c.z);
        const __m128 sxx = _mm_set1_ps(sx.x), sxy = _mm_set1_ps(sx.y), sxz = _mm_set1_ps(sx.z);
        const __m128 syx = _mm_set1_ps(sy.x), syy = _mm_set1_ps(sy.y), syz = _mm_set1_ps(sy.z);
        const __m128 iota = _mm_setr_ps(0.5f, 1.5f, 2.5f, 3.5f);
        const __m128i lane = _mm_setr_epi32(0, 1, 2, 3), fv = _mm_set1_epi32(int(f));
#endif
        underSpans(uv, width, height, r0, r1, [&](int y, int xl, int xr) {
            const size_t row = size_t(y - r0) * size_t(width) + size_t(xl);
            uint32_t *const to = &rows.face[row];
            float *const nx = &rows.nx[row], *const ny = &rows.ny[row], *const nz = &rows.nz[row];
            const int span = xr - xl + 1;
            const float py = float(y) + 0.5f;
#if VOXELFAIR_SSE2
            // 4 texels at a time, the last 4 blended into what lies past the span (the arrays
            // have 4 lanes past the rows' end): lane k of texel x + k at x + k + 0.5.
            const __m128 y4 = _mm_set1_ps(py);
            const __m128 bx4 = _mm_add_ps(cx, _mm_mul_ps(y4, syx)), by4 = _mm_add_ps(cy, _mm_mul_ps(y4, syy)),
                         bz4 = _mm_add_ps(cz, _mm_mul_ps(y4, syz));
            for (int j = 0; j < span; j += 4) {
                const __m128 t = _mm_add_ps(_mm_set1_ps(float(xl + j)), iota);
                const __m128 vx = _mm_add_ps(bx4, _mm_mul_ps(t, sxx)), vy = _mm_add_ps(by4, _mm_mul_ps(t, sxy)),
                             vz = _mm_add_ps(bz4, _mm_mul_ps(t, sxz));
                const size_t k = size_t(j);
                __m128i *const fp = reinterpret_cast<__m128i *>(to + k);
                if (j + 4 <= span) {
                    _mm_storeu_si128(fp, fv);
                    _mm_storeu_ps(nx + k, vx), _mm_storeu_ps(ny + k, vy), _mm_storeu_ps(nz + k, vz);
                } else {
                    const __m128i m = _mm_cmplt_epi32(lane, _mm_set1_epi32(span - j));
                    const __m128 mf = _mm_castsi128_ps(m);
                    auto blend = [&](float *p, __m128 v) {
                        _mm_storeu_ps(p, _mm_or_ps(_mm_and_ps(mf, v), _mm_andnot_ps(mf, _mm_loadu_ps(p))));
                    };
                    _mm_storeu_si128(fp, _mm_or_si128(_mm_and_si128(m, fv), _mm_andnot_si128(m, _mm_loadu_si128(fp))));
                    blend(nx + k, vx), blend(ny + k, vy), blend(nz + k, vz);
                }
            }
#else
            const glm::vec3 base = c + py * sy;
            for (int j = 0; j < span; ++j) {
                const float t = float(xl + j) + 0.5f;
                to[j] = f;
                nx[j] = base.x + t * sx.x, ny[j] = base.y + t * sx.y, nz[j] = base.z + t * sx.z;
            }
#endif
        });
    }
}

}  // namespace voxelfair
