// Tangent-space normal map baking through the shared atlas; the contract is in normal_bake.h.
#include "maps/normal_bake.h"

#include "atlas/texel_raster.h"
#include "maps/mikktspace.h"
#include "maps/surface_walk.h"
#include "maps/texel_dilation.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace voxelfair {

namespace {

enum : uint8_t { kEmpty = 0, kCentre = 1, kEdge = 2 };
constexpr double kMargin = -1.0 / 256;  // the base colour bake's overlap rule (atlas/bake.cpp)

bool validate(const NormalBakeMesh &m, const char *what, std::string &message) {
    if (m.faceCount == 0) {
        message = std::string("the ") + what + " mesh has no faces";
        return false;
    }
    if (!m.positions || !m.normals || !m.triangles || !m.wedgeUv) {
        message = std::string("the ") + what + " mesh lacks positions, normals, triangles or texture coordinates";
        return false;
    }
    for (size_t i = 0; i < 3 * m.faceCount; ++i)
        if (m.triangles[i] >= m.vertexCount) {
            message = std::string("the ") + what + " mesh has a vertex index out of range";
            return false;
        }
    return true;
}

void loadUv(const NormalBakeMesh &m, size_t f, double side, glm::dvec2 q[3]) {
    for (int k = 0; k < 3; ++k)
        q[k] = glm::dvec2(m.wedgeUv[3 * f + size_t(k)]) * side;
}

uint8_t encode(float c) { return uint8_t(std::clamp(std::lround((c * 0.5f + 0.5f) * 255.0f), 0L, 255L)); }
float decode(uint8_t c) { return float(c) / 255.0f * 2.0f - 1.0f; }

}  // namespace

std::vector<glm::vec4> targetTangents(const NormalBakeMesh &target) {
    std::vector<glm::vec3> positions(3 * target.faceCount), normals(3 * target.faceCount);
    for (size_t c = 0; c < 3 * target.faceCount; ++c) {
        positions[c] = target.positions[target.triangles[c]];
        const glm::vec3 n = target.normals[target.triangles[c]];
        const float length = glm::length(n);
        normals[c] = length > 0.0f ? n / length : n;
    }
    TangentInput input;
    input.positions = positions.data();
    input.normals = normals.data();
    input.uvs = target.wedgeUv;
    input.triangleCount = target.faceCount;
    return computeMikkTSpaceTangents(input);
}

glm::vec3 applyNormalMapTexel(glm::vec3 texel, glm::vec3 n, glm::vec4 t) {
    const glm::vec3 N = glm::normalize(n), T = glm::normalize(glm::vec3(t));
    const glm::vec3 B = (t.w < 0.0f ? -1.0f : 1.0f) * glm::cross(N, T);
    return glm::normalize(texel.x * T + texel.y * B + texel.z * N);
}

namespace {

// Source faces by the texel-space boxes of their UV triangles, in cells of 16 x 16 texels: where
// a target face's walk starts (the source face under the same UV).
class UvFaceGrid {
public:
    UvFaceGrid(const NormalBakeMesh &m, int size) : mesh_(m), size_(size), cells_((size + kCell - 1) / kCell) {
        start_.assign(size_t(cells_) * size_t(cells_) + 1, 0);
        auto forCells = [&](size_t f, auto &&visit) {
            glm::dvec2 q[3];
            loadUv(m, f, size, q);
            const glm::dvec2 lo = glm::min(q[0], glm::min(q[1], q[2])), hi = glm::max(q[0], glm::max(q[1], q[2]));
            const int x0 = std::clamp(int(lo.x) / kCell, 0, cells_ - 1),
                      x1 = std::clamp(int(hi.x) / kCell, 0, cells_ - 1);
            const int y0 = std::clamp(int(lo.y) / kCell, 0, cells_ - 1),
                      y1 = std::clamp(int(hi.y) / kCell, 0, cells_ - 1);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    visit(size_t(y) * size_t(cells_) + size_t(x));
        };
        for (size_t f = 0; f < m.faceCount; ++f)
            forCells(f, [&](size_t c) { ++start_[c + 1]; });
        for (size_t c = 1; c < start_.size(); ++c)
            start_[c] += start_[c - 1];
        faces_.resize(start_.back());
        std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
        for (size_t f = 0; f < m.faceCount; ++f)
            forCells(f, [&](size_t c) { faces_[fill[c]++] = uint32_t(f); });
    }
    // The source face whose UV triangle holds texel-space point p, else the one whose UV centroid
    // is nearest among those of p's cell; UINT32_MAX when the cell is empty.
    uint32_t find(glm::dvec2 p) const {
        const int cx = std::clamp(int(p.x) / kCell, 0, cells_ - 1), cy = std::clamp(int(p.y) / kCell, 0, cells_ - 1);
        const size_t c = size_t(cy) * size_t(cells_) + size_t(cx);
        uint32_t nearest = UINT32_MAX;
        double best = 0;
        glm::dvec2 q[3];
        for (uint32_t i = start_[c]; i < start_[c + 1]; ++i) {
            loadUv(mesh_, faces_[i], size_, q);
            const double d = doubleArea(q[0], q[1], q[2]);
            const double a = doubleArea(p, q[1], q[2]) / d, b = doubleArea(q[0], p, q[2]) / d;
            if (d != 0 && a >= 0 && b >= 0 && a + b <= 1)
                return faces_[i];
            const glm::dvec2 centroid = (q[0] + q[1] + q[2]) / 3.0;
            const double distance = glm::dot(centroid - p, centroid - p);
            if (nearest == UINT32_MAX || distance < best)
                nearest = faces_[i], best = distance;
        }
        return nearest;
    }

private:
    static constexpr int kCell = 16;
    const NormalBakeMesh &mesh_;
    int size_, cells_;
    std::vector<uint32_t> start_, faces_;
};

inline uint8_t encodeFast(float c) { return uint8_t(std::clamp(int(c * 127.5f + 128.0f), 0, 255)); }

}  // namespace

NormalMap bakeNormalMap(const NormalBakeMesh &source, const NormalBakeMesh &target, const NormalBakeOptions &options) {
    NormalMap out;
    if (!validate(source, "source", out.message) || !validate(target, "target", out.message))
        return out;
    if (options.size < 1 || options.size > 16384) {
        out.message = "the texture size must be between 1 and 16384 texels";
        return out;
    }
    const int size = options.size;
    const size_t texels = size_t(size) * size_t(size);
    out.size = size;
    out.cornerTangents = targetTangents(target);

    const UvFaceGrid grid(source, size);
    const SurfaceWalk walk(source.positions, source.triangles, source.faceCount, source.vertexCount);

    // Flat normal (128, 128, 255) everywhere, then the target's texels.
    out.rgba.resize(texels * 4);
    {
        const uint32_t flat = 0xFFFF8080u;  // bytes 128, 128, 255, 255 in memory order
        uint32_t *p = reinterpret_cast<uint32_t *>(out.rgba.data());
        std::fill(p, p + texels, flat);
    }
    std::vector<uint8_t> state(texels, kEmpty);
    std::vector<uint32_t> painted;
    painted.reserve(texels / 4);
    enum : uint8_t { kFromSource = 4 };

    glm::dvec2 q[3];
    for (size_t f = 0; f < target.faceCount; ++f) {
        loadUv(target, f, size, q);
        const double d = doubleArea(q[0], q[1], q[2]);
        if (!(d != 0) || !std::isfinite(d))
            continue;
        // Barycentric weights as affine functions of the texel centre: l = l0 + lx x + ly y.
        const double a1 = (q[2].y - q[0].y) / d, b1 = -(q[2].x - q[0].x) / d;
        const double a2 = -(q[1].y - q[0].y) / d, b2 = (q[1].x - q[0].x) / d;
        glm::vec3 tp[3], tn[3], tt[3];
        float w = 0.0f;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = target.triangles[3 * f + size_t(k)];
            tp[k] = target.positions[v];
            tn[k] = target.normals[v];
            tt[k] = glm::vec3(out.cornerTangents[3 * f + size_t(k)]);
            w += out.cornerTangents[3 * f + size_t(k)].w;
        }
        const float sign = w < 0.0f ? -1.0f : 1.0f;
        uint32_t hitFace = grid.find((q[0] + q[1] + q[2]) / 3.0);
        auto bake = [&](int x, int y, uint8_t kind) {
            const size_t i = size_t(y) * size_t(size) + size_t(x);
            if (state[i] == kEmpty)
                painted.push_back(uint32_t(i));
            state[i] = kind;
            if (hitFace == UINT32_MAX)
                return;
            const double px = x + 0.5 - q[0].x, py = y + 0.5 - q[0].y;
            float l1 = float(a1 * px + b1 * py), l2 = float(a2 * px + b2 * py), l0 = 1.0f - l1 - l2;
            if (l0 < 0 || l1 < 0 || l2 < 0) {
                l0 = std::max(l0, 0.0f), l1 = std::max(l1, 0.0f), l2 = std::max(l2, 0.0f);
                const float sum = l0 + l1 + l2;
                if (sum > 0)
                    l0 /= sum, l1 /= sum, l2 /= sum;
            }
            glm::vec3 N = l0 * tn[0] + l1 * tn[1] + l2 * tn[2];
            const SurfaceWalk::Hit hit = walk.project(l0 * tp[0] + l1 * tp[1] + l2 * tp[2], hitFace, N, 64);
            hitFace = hit.face;
            const uint32_t *sv = &source.triangles[3 * size_t(hit.face)];
            const glm::vec3 n = hit.weights.x * source.normals[sv[0]] + hit.weights.y * source.normals[sv[1]] +
                                hit.weights.z * source.normals[sv[2]];
            glm::vec3 T = l0 * tt[0] + l1 * tt[1] + l2 * tt[2];
            const float nl = glm::dot(N, N), tl = glm::dot(T, T);
            if (!(nl > 0.0f && tl > 0.0f))
                return;
            N *= 1.0f / std::sqrt(nl), T *= 1.0f / std::sqrt(tl);
            const glm::vec3 B = sign * glm::cross(N, T);
            // Rows of the inverse of the column matrix [T B N]: cross products over its determinant.
            const glm::vec3 r0 = glm::cross(B, N), r1 = glm::cross(N, T), r2 = glm::cross(T, B);
            const glm::vec3 solved(glm::dot(r0, n), glm::dot(r1, n), glm::dot(r2, n));
            const float det = glm::dot(T, r0), length = glm::dot(solved, solved);
            if (!(std::fabs(det) > 1e-6f) || !(length > 0.0f))
                return;
            const glm::vec3 c = solved * ((det < 0.0f ? -1.0f : 1.0f) / std::sqrt(length));
            uint8_t *p = &out.rgba[(size_t(size - 1 - y) * size_t(size) + size_t(x)) * 4];
            p[0] = encodeFast(c.x), p[1] = encodeFast(c.y), p[2] = encodeFast(c.z);
            state[i] = kind | kFromSource;
        };
        rasterCentres(q[0], q[1], q[2], size, size, [&](int x, int y) { bake(x, y, kCentre); });
        rasterConservative(q[0], q[1], q[2], kMargin, size, size, [&](int x, int y) {
            if (state[size_t(y) * size_t(size) + size_t(x)] == kEmpty)
                bake(x, y, kEdge);
        });
    }
    for (uint32_t i : painted) {
        if (state[i] & kFromSource)
            ++out.texelsBaked;
        else
            ++out.texelsWithoutSource;
        state[i] = 1;
    }

    // The gutter: renormalised mean of the painted neighbours.
    dilateTexels(size, state, painted, options.dilation, [&](int x, int y) {
        glm::vec3 sum(0.0f);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= size || ny >= size || state[size_t(ny) * size_t(size) + size_t(nx)] != 1)
                    continue;
                const uint8_t *p = &out.rgba[(size_t(size - 1 - ny) * size_t(size) + size_t(nx)) * 4];
                sum += glm::vec3(decode(p[0]), decode(p[1]), decode(p[2]));
            }
        const float length = glm::length(sum);
        if (!(length > 0.0f))
            return false;
        sum /= length;
        uint8_t *p = &out.rgba[(size_t(size - 1 - y) * size_t(size) + size_t(x)) * 4];
        p[0] = encode(sum.x), p[1] = encode(sum.y), p[2] = encode(sum.z);
        return true;
    });
    out.ok = true;
    return out;
}

}  // namespace voxelfair
