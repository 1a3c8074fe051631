// Tangent-space normal map baking through the shared atlas; the contract is in normal_bake.h.
#include "maps/normal_bake.h"

#include "atlas/texel_raster.h"
#include "maps/mikktspace.h"
#include "maps/parallel_bands.h"
#include "maps/surface_walk.h"
#include "maps/texel_dilation.h"
#include "maps/texel_frames.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <thread>

#include <glm/geometric.hpp>

namespace voxelfair {

namespace {

constexpr double kMargin = -1.0 / 256;  // the base colour bake's overlap rule (atlas/bake.cpp)

void validate(const NormalBakeMesh &m, const char *what) {
    if (m.faceCount == 0)
        throw MeshError(std::string("the ") + what + " mesh has no faces");
    if (!m.positions || !m.normals || !m.triangles || !m.wedgeUv)
        throw MeshError(std::string("the ") + what +
                        " mesh lacks positions, normals, triangles or texture coordinates");
    for (size_t i = 0; i < 3 * m.faceCount; ++i)
        if (m.triangles[i] >= m.vertexCount)
            throw MeshError(std::string("the ") + what + " mesh has a vertex index out of range (face " +
                            std::to_string(i / 3) + ")");
}

void loadUv(const NormalBakeMesh &m, size_t f, int width, int height, glm::dvec2 q[3]) {
    for (int k = 0; k < 3; ++k)
        q[k] = glm::dvec2(m.wedgeUv[3 * f + size_t(k)]) * glm::dvec2(width, height);
}

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
// a texel's walk starts (the source face under the same UV).
class UvFaceGrid {
public:
    UvFaceGrid(const NormalBakeMesh &m, int width, int height)
        : mesh_(m), width_(width), height_(height), cellsX_((width + kCell - 1) / kCell),
          cellsY_((height + kCell - 1) / kCell) {
        start_.assign(size_t(cellsX_) * size_t(cellsY_) + 1, 0);
        auto forCells = [&](size_t f, auto &&visit) {
            glm::dvec2 q[3];
            loadUv(m, f, width, height, q);
            const glm::dvec2 lo = glm::min(q[0], glm::min(q[1], q[2])), hi = glm::max(q[0], glm::max(q[1], q[2]));
            const int x0 = std::clamp(int(lo.x) / kCell, 0, cellsX_ - 1),
                      x1 = std::clamp(int(hi.x) / kCell, 0, cellsX_ - 1);
            const int y0 = std::clamp(int(lo.y) / kCell, 0, cellsY_ - 1),
                      y1 = std::clamp(int(hi.y) / kCell, 0, cellsY_ - 1);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    visit(size_t(y) * size_t(cellsX_) + size_t(x));
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
        const int cx = std::clamp(int(p.x) / kCell, 0, cellsX_ - 1), cy = std::clamp(int(p.y) / kCell, 0, cellsY_ - 1);
        const size_t c = size_t(cy) * size_t(cellsX_) + size_t(cx);
        uint32_t nearest = UINT32_MAX;
        double best = 0;
        glm::dvec2 q[3];
        for (uint32_t i = start_[c]; i < start_[c + 1]; ++i) {
            loadUv(mesh_, faces_[i], width_, height_, q);
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
    int width_, height_, cellsX_, cellsY_;
    std::vector<uint32_t> start_, faces_;
};

constexpr int kBandRows = 32;
constexpr uint8_t kFromSource = 2;  // a state bit beside kTexelPainted (texel_dilation.h)

inline uint8_t encodeFast(float c) { return uint8_t(std::clamp(int(c * 127.5f + 128.0f), 0, 255)); }

// Target faces by the bands of rows their UV triangles may touch (conservatively), in face order.
struct FaceBands {
    std::vector<uint32_t> start, faces;
};

FaceBands faceBands(const NormalBakeMesh &mesh, int width, int height) {
    const size_t bands = size_t((height + kBandRows - 1) / kBandRows);
    FaceBands out;
    out.start.assign(bands + 1, 0);
    auto range = [&](size_t f, size_t &b0, size_t &b1) {
        glm::dvec2 q[3];
        loadUv(mesh, f, width, height, q);
        const double lo = std::min({q[0].y, q[1].y, q[2].y}), hi = std::max({q[0].y, q[1].y, q[2].y});
        if (!std::isfinite(lo) || !std::isfinite(hi) || hi < -1 || lo > height + 1)
            return false;
        b0 = size_t(std::clamp(int(std::floor(lo)) - 1, 0, height - 1) / kBandRows);
        b1 = size_t(std::clamp(int(std::ceil(hi)) + 1, 0, height - 1) / kBandRows);
        return true;
    };
    size_t b0 = 0, b1 = 0;
    for (size_t f = 0; f < mesh.faceCount; ++f)
        if (range(f, b0, b1))
            for (size_t b = b0; b <= b1; ++b)
                ++out.start[b + 1];
    for (size_t b = 0; b < bands; ++b)
        out.start[b + 1] += out.start[b];
    out.faces.resize(out.start.back());
    std::vector<uint32_t> fill(out.start.begin(), out.start.end() - 1);
    for (size_t f = 0; f < mesh.faceCount; ++f)
        if (range(f, b0, b1))
            for (size_t b = b0; b <= b1; ++b)
                out.faces[fill[b]++] = uint32_t(f);
    // Each band's faces from left to right (by their UV boxes' left texel, then index): a band
    // sweeps its rows once, its texels and the source faces under them stay in cache.
    std::vector<uint64_t> keyed;
    for (size_t b = 0; b < bands; ++b) {
        keyed.clear();
        for (uint32_t i = out.start[b]; i < out.start[b + 1]; ++i) {
            const glm::vec2 *uv = &mesh.wedgeUv[3 * size_t(out.faces[i])];
            const float left = std::min({uv[0].x, uv[1].x, uv[2].x}) * float(width);
            const uint64_t x = std::isfinite(left) ? uint64_t(std::clamp(left, 0.0f, float(width))) : 0;
            keyed.push_back(x << 32 | out.faces[i]);
        }
        std::sort(keyed.begin(), keyed.end());
        for (uint32_t i = out.start[b]; i < out.start[b + 1]; ++i)
            out.faces[i] = uint32_t(keyed[i - out.start[b]]);
    }
    return out;
}

// Calls span(y, xl, xr) for the rows y in [r0, r1) with texel centres (x + 0.5, y + 0.5) in the
// UV triangle uv (scaled to texels), x in [xl, xr] within the image: a plain scanline fill in
// floats, for the walk's starting faces (where neighbouring triangles share an edge, a centre
// on it may be given to either; both are right starts).
template <class Span>
void underSpans(const glm::vec2 *uv, int width, int height, int r0, int r1, Span &&span) {
    const glm::vec2 q[3] = {uv[0] * glm::vec2(float(width), float(height)),
                            uv[1] * glm::vec2(float(width), float(height)),
                            uv[2] * glm::vec2(float(width), float(height))};
    const float area = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
    if (!(area != 0.0f) || !std::isfinite(area))
        return;
    const float lo = std::min({q[0].y, q[1].y, q[2].y}), hi = std::max({q[0].y, q[1].y, q[2].y});
    const int y0 = std::max(r0, int(std::ceil(lo - 0.5f))), y1 = std::min(r1 - 1, int(std::floor(hi - 0.5f)));
    // Edge a -> b bounds the inside where sign(area) * cross(b - a, c - a) >= 0: for a row, x
    // >= or <= its crossing a.x + (cy - a.y) ex / ey (left or right bound by the sign of
    // -sign(area) ey); a horizontal edge bounds the rows instead (cy on its inner side).
    float ax[3], ay[3], inverse[3];
    int side[3];  // 1: left bound, -1: right bound, 0: horizontal
    float rowSign[3];
    const float s = area > 0.0f ? 1.0f : -1.0f;
    for (int k = 0; k < 3; ++k) {
        const glm::vec2 a = q[k], b = q[(k + 1) % 3];
        const float ex = b.x - a.x, ey = b.y - a.y;
        ax[k] = a.x, ay[k] = a.y;
        side[k] = -s * ey > 0.0f ? 1 : (-s * ey < 0.0f ? -1 : 0);
        inverse[k] = ey != 0.0f ? ex / ey : 0.0f;
        rowSign[k] = s * ex;  // horizontal edge: inside where s ex (cy - a.y) >= 0
    }
    for (int y = y0; y <= y1; ++y) {
        const float cy = float(y) + 0.5f;
        float xl = -1.0f, xr = float(width);
        bool empty = false;
        for (int k = 0; k < 3; ++k) {
            const float crossing = ax[k] + (cy - ay[k]) * inverse[k];
            if (side[k] > 0)
                xl = std::max(xl, crossing);
            else if (side[k] < 0)
                xr = std::min(xr, crossing);
            else if (rowSign[k] * (cy - ay[k]) < 0.0f)
                empty = true;
        }
        // Texels whose centre x + 0.5 lies in [xl, xr].
        const int a = std::max(0, int(std::ceil(xl - 0.5f))), b = std::min(width - 1, int(std::floor(xr - 0.5f)));
        if (!empty && a <= b)
            span(y, a, b);
    }
}

// The source with its faces renumbered by the atlas cell (kSortCell texels square) of their UV
// centroid, cells row by row (a counting sort): faces near in the atlas are near in memory, and
// the source faces under a target face lie in a few runs the walk can fetch ahead.
struct SortedSource {
    static constexpr int kSortCell = 16;
    std::vector<uint32_t> triangles;
    std::vector<glm::vec2> wedgeUv;
    int cellsX = 0, cellsY = 0;
    std::vector<uint32_t> cellStart;  // the faces of cell c: [cellStart[c], cellStart[c + 1])
    NormalBakeMesh mesh;

    SortedSource(const NormalBakeMesh &source, int width, int height)
        : triangles(3 * source.faceCount), wedgeUv(3 * source.faceCount), cellsX((width + kSortCell - 1) / kSortCell),
          cellsY((height + kSortCell - 1) / kSortCell), cellStart(size_t(cellsX) * size_t(cellsY) + 1, 0),
          mesh(source) {
        std::vector<uint32_t> cellOf(source.faceCount);
        for (size_t f = 0; f < source.faceCount; ++f) {
            const glm::vec2 *uv = &source.wedgeUv[3 * f];
            const glm::vec2 c = (uv[0] + uv[1] + uv[2]) / 3.0f;
            cellOf[f] = cell(double(c.x) * width, double(c.y) * height);
            ++cellStart[cellOf[f] + 1];
        }
        for (size_t c = 1; c < cellStart.size(); ++c)
            cellStart[c] += cellStart[c - 1];
        std::vector<uint32_t> fill(cellStart.begin(), cellStart.end() - 1);
        for (size_t f = 0; f < source.faceCount; ++f) {
            const size_t to = fill[cellOf[f]]++;
            for (int k = 0; k < 3; ++k) {
                triangles[3 * to + size_t(k)] = source.triangles[3 * f + size_t(k)];
                wedgeUv[3 * to + size_t(k)] = source.wedgeUv[3 * f + size_t(k)];
            }
        }
        mesh.triangles = triangles.data();
        mesh.wedgeUv = wedgeUv.data();
    }
    uint32_t cell(double x, double y) const {
        const int cx = std::isfinite(x) ? std::clamp(int(x / kSortCell), 0, cellsX - 1) : 0;
        const int cy = std::isfinite(y) ? std::clamp(int(y / kSortCell), 0, cellsY - 1) : 0;
        return uint32_t(cy) * uint32_t(cellsX) + uint32_t(cx);
    }
    // Calls run(first, last) for the faces whose centroid lies in the cells of the texel box.
    template <class Run>
    void forRuns(glm::dvec2 lo, glm::dvec2 hi, Run &&run) const {
        const uint32_t a = cell(lo.x, lo.y), b = cell(hi.x, hi.y);
        const uint32_t x0 = a % uint32_t(cellsX), x1 = b % uint32_t(cellsX);
        for (uint32_t cy = a / uint32_t(cellsX); cy <= b / uint32_t(cellsX); ++cy)
            run(cellStart[cy * uint32_t(cellsX) + x0], cellStart[cy * uint32_t(cellsX) + x1 + 1]);
    }
};

}  // namespace

NormalMap bakeNormalMap(const NormalBakeMesh &source, const NormalBakeMesh &target, const NormalBakeOptions &options) {
    NormalMap out;
    validate(source, "source");
    validate(target, "target");
    if (options.width < 1 || options.width > 16384 || options.height < 0 || options.height > 16384)
        throw OptionError("the normal map's sides must be between 1 and 16384 texels");
    if (options.level < 0 || options.level > 1)
        throw OptionError("the normal map's level must be 0 (the atlas' size) or 1 (half each side)");
    // Level 1: one texel per 2 x 2 block (a side of odd length gets a last half block).
    const int width = (options.width + options.level) >> options.level,
              height = ((options.height > 0 ? options.height : options.width) + options.level) >> options.level;
    const size_t texels = size_t(width) * size_t(height);
    out.width = width;
    out.height = height;

    // The source's walk (its largest structure) on one thread, the rest on the other.
    const auto sorted = std::make_unique<SortedSource>(source, width, height);
    std::unique_ptr<UvFaceGrid> grid;
    std::unique_ptr<SurfaceWalk> walk;
    FaceBands bands, sourceBands;
    std::vector<uint8_t> state;
    {
        auto walkPart = [&] {
            walk = std::make_unique<SurfaceWalk>(source.positions, source.normals, sorted->triangles.data(),
                                                 source.faceCount, source.vertexCount);
            sourceBands = faceBands(sorted->mesh, width, height);
        };
        auto rest = [&] {
            out.cornerTangents = targetTangents(target);
            bands = faceBands(target, width, height);
            grid = std::make_unique<UvFaceGrid>(sorted->mesh, width, height);
            out.rgba.resize(texels * 4);
            state.assign(texels, 0);
        };
        if (bandThreads(options.threads, 2) > 1) {
            std::thread other(walkPart);
            rest();
            other.join();
        } else {
            walkPart();
            rest();
        }
    }
    const size_t bandCount = bands.start.size() - 1;
    std::vector<size_t> baked(bandCount, 0), flat(bandCount, 0);
    // Per thread: the band's source faces under the texel centres, the triangle's texels.
    struct Scratch {
        std::vector<uint32_t> under;
        TexelBatch batch;
    };
    std::vector<Scratch> scratch(size_t(bandThreads(options.threads, bandCount)));
    runWorkerBands(bandCount, options.threads, [&](size_t band, int worker) {
        const int r0 = int(band) * kBandRows, r1 = std::min(height, r0 + kBandRows);
        uint8_t *const rgba = out.rgba.data();
        uint8_t *const states = state.data();
        // Flat normal (128, 128, 255) on the band's rows (image rows height - r1 .. height - 1 - r0).
        std::fill(reinterpret_cast<uint32_t *>(rgba) + size_t(height - r1) * size_t(width),
                  reinterpret_cast<uint32_t *>(rgba) + size_t(height - r0) * size_t(width),
                  0xFFFF8080u);  // bytes 128, 128, 255, 255
        glm::dvec2 q[3];
        // The source face under each texel centre of the band (its UV triangle holds the centre).
        std::vector<uint32_t> &under = scratch[size_t(worker)].under;
        under.assign(size_t(r1 - r0) * size_t(width), UINT32_MAX);
        for (uint32_t i = sourceBands.start[band]; i < sourceBands.start[band + 1]; ++i)
            underSpans(sorted->mesh.wedgeUv + 3 * size_t(sourceBands.faces[i]), width, height, r0, r1,
                       [&](int y, int xl, int xr) {
                           std::fill_n(&under[size_t(y - r0) * size_t(width) + size_t(xl)], xr - xl + 1,
                                       sourceBands.faces[i]);
                       });
        TexelBatch &batch = scratch[size_t(worker)].batch;
        for (uint32_t i = bands.start[band]; i < bands.start[band + 1]; ++i) {
            const size_t f = bands.faces[i];
            loadUv(target, f, width, height, q);
            const double d = doubleArea(q[0], q[1], q[2]);
            if (!(d != 0) || !std::isfinite(d))
                continue;
            // Room for the texels of the triangle's box within the band (one ring wider: overlaps).
            {
                const glm::dvec2 lo = glm::min(q[0], glm::min(q[1], q[2])), hi = glm::max(q[0], glm::max(q[1], q[2]));
                const double rows = std::min(hi.y, double(r1)) - std::max(lo.y, double(r0)) + 3,
                             columns = std::min(hi.x, double(width)) - std::max(lo.x, 0.0) + 3;
                batch.reserve(size_t(std::max(rows, 0.0)) * size_t(std::max(columns, 0.0)));
            }
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
            const glm::vec3 e1 = tp[1] - tp[0], e2 = tp[2] - tp[0];
            const float sign = w < 0.0f ? -1.0f : 1.0f;
            TargetFrame targetFrame;
            for (int k = 0; k < 3; ++k)
                for (int a = 0; a < 3; ++a)
                    targetFrame.n[k][a] = tn[k][a], targetFrame.t[k][a] = tt[k][a];
            targetFrame.sign = sign;
            // The texels are visited row by row, left to right. A texel's source point is most
            // often on the face of the texel before it (checked first), else on the source face
            // under its UV (the atlas' correspondence); failing both, the walk starts from the
            // texel before it (a step or two away on the same sheet), or, for a row's first texel,
            // from the previous row's first answer, for the triangle's first texel from the face
            // under its UV (the UV grid's nearest where none is).
            uint32_t hitFace = UINT32_MAX, rowFace = UINT32_MAX;
            // The source normal at texel (x, y) with weights l1, l2; false when no source face is near.
            auto sourceNormal = [&](int x, int y, float l1, float l2, glm::vec3 &n) {
                const glm::vec3 p = tp[0] + l1 * e1 + l2 * e2;

                glm::vec3 weights;
                if (hitFace != UINT32_MAX && walk->holds(p, hitFace, weights)) {
                    n = walk->normalAt(hitFace, weights);
                    return true;
                }
                const uint32_t start = under[size_t(y - r0) * size_t(width) + size_t(x)];
                if (start != UINT32_MAX && start != hitFace && walk->holds(p, start, weights)) {
                    hitFace = start;
                    n = walk->normalAt(hitFace, weights);
                    return true;
                }
                uint32_t from = hitFace != UINT32_MAX ? hitFace : start;
                const float l0 = 1.0f - l1 - l2;
                if (from == UINT32_MAX &&
                    (from = grid->find(double(l0) * q[0] + double(l1) * q[1] + double(l2) * q[2])) == UINT32_MAX)
                    return false;
                const SurfaceWalk::Hit hit = walk->project(p, from, l0 * tn[0] + l1 * tn[1] + l2 * tn[2], 64);
                hitFace = hit.face;
                n = walk->normalAt(hit);
                return true;
            };
            batch.size = 0;
            rasterRows(q[0], q[1], q[2], kMargin, width, height, [&](int y, int cl, int cr, int zl, int zr) {
                if (y < r0 || y >= r1)
                    return;
                const uint32_t stateRow = uint32_t(y) * uint32_t(width),
                               imageRow = uint32_t(height - 1 - y) * uint32_t(width);
                const double py = y + 0.5 - q[0].y;
                hitFace = rowFace;
                bool first = true;
                auto visit = [&](int x, float l1, float l2) {
                    glm::vec3 n(0.0f);
                    if (!sourceNormal(x, y, l1, l2, n))
                        n = glm::vec3(0.0f);
                    if (first)
                        rowFace = hitFace, first = false;
                    batch.push(l1, l2, n, stateRow + uint32_t(x), imageRow + uint32_t(x));
                };
                // Texels the triangle only overlaps, if no centre claimed them (no centre of this
                // face lies among them, so gathering them with the centres keeps the order of
                // claims): weights clamped onto it.
                auto overlap = [&](int x) {
                    if (states[stateRow + uint32_t(x)] != 0)
                        return;
                    const double px = x + 0.5 - q[0].x;
                    float l1 = float(a1 * px + b1 * py), l2 = float(a2 * px + b2 * py), l0 = 1.0f - l1 - l2;
                    l0 = std::max(l0, 0.0f), l1 = std::max(l1, 0.0f), l2 = std::max(l2, 0.0f);
                    const float sum = l0 + l1 + l2;
                    if (sum > 0)
                        l1 /= sum, l2 /= sum;
                    visit(x, l1, l2);
                };
                const bool centres = zl <= zr;
                for (int x = cl; x <= (centres ? std::min(zl - 1, cr) : cr); ++x)
                    overlap(x);
                // Centres inside: the weights step along the row.
                if (centres) {
                    const double px = zl + 0.5 - q[0].x;
                    double l1 = a1 * px + b1 * py, l2 = a2 * px + b2 * py;
                    for (int x = zl; x <= zr; ++x, l1 += a1, l2 += a2)
                        visit(x, float(l1), float(l2));
                    for (int x = std::max(zr + 1, cl); x <= cr; ++x)
                        overlap(x);
                }
            });
            solveTexelBatch(targetFrame, batch);
            for (size_t t = 0; t < batch.size; ++t) {
                states[batch.stateIndex[t]] = uint8_t(kTexelPainted | (batch.solved[t] ? kFromSource : 0));
                if (batch.solved[t]) {
                    uint8_t *p = rgba + 4 * size_t(batch.imageIndex[t]);
                    const uint32_t c = batch.colour[t];
                    p[0] = uint8_t(c), p[1] = uint8_t(c >> 8), p[2] = uint8_t(c >> 16);
                }
            }
        }

        size_t fromSource = 0, painted = 0;  // local: the bands' counters share cache lines
        for (size_t t = size_t(r0) * size_t(width); t < size_t(r1) * size_t(width); ++t) {
            fromSource += states[t] >> 1;
            painted += states[t] & 1;
        }
        baked[band] = fromSource;
        flat[band] = painted - fromSource;
    });
    for (size_t b = 0; b < bandCount; ++b)
        out.texelsBaked += baked[b], out.texelsWithoutSource += flat[b];

    // The gutter: renormalised mean of the painted neighbours.
    const uint8_t *const painted = state.data();
    uint8_t *const image = out.rgba.data();
    dilateTexels(width, height, state, options.dilation, options.threads,
                 [painted, image, width, height](int x, int y) {
                     // The mean of the decoded neighbours, (2 c - 255) / 255 each, up to its scale: integers.
                     int sx = 0, sy = 0, sz = 0, n = 0;
                     for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, height - 1); ++ny) {
                         const uint8_t *const row = painted + size_t(ny) * size_t(width);
                         const uint8_t *const colours = image + size_t(height - 1 - ny) * size_t(width) * 4;
                         for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width - 1); ++nx) {
                             const int m = row[nx] & kTexelPainted;  // 0 or 1: branch-free sums
                             const uint8_t *p = colours + size_t(nx) * 4;
                             sx += m * p[0], sy += m * p[1], sz += m * p[2], n += m;
                         }
                     }
                     const glm::vec3 sum(float(2 * sx - 255 * n), float(2 * sy - 255 * n), float(2 * sz - 255 * n));
                     const float length = glm::length(sum);
                     if (!(length > 0.0f))
                         return false;
                     const glm::vec3 c = sum / length;
                     uint8_t *p = image + (size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4;
                     p[0] = encodeFast(c.x), p[1] = encodeFast(c.y), p[2] = encodeFast(c.z);
                     return true;
                 });
    // Blocks: every aligned 2 x 2 block with a painted texel belongs to one chart (the atlas'
    // packing); its other texels take the renormalised mean of its painted ones. Bands of an
    // even number of rows hold whole blocks.
    if (options.blocks && options.level == 0)
        runBands(bandCount, options.threads, [&](size_t band) {
            const int r0 = int(band) * kBandRows, r1 = std::min(height, r0 + kBandRows);
            static_assert(kBandRows % 2 == 0, "bands hold whole blocks");
            for (int y = r0; y < r1; y += 2)
                for (int x = 0; x < width; x += 2) {
                    int sum[3] = {0, 0, 0}, n = 0, texelCount = 0;
                    size_t at[4];
                    for (int dy = 0; dy < std::min(2, height - y); ++dy)
                        for (int dx = 0; dx < std::min(2, width - x); ++dx) {
                            const size_t t = size_t(y + dy) * size_t(width) + size_t(x + dx);
                            at[texelCount++] = t;
                            if (state[t] & kTexelPainted) {
                                const uint8_t *p =
                                    &image[(size_t(height - 1 - y - dy) * size_t(width) + size_t(x + dx)) * 4];
                                for (int c = 0; c < 3; ++c)
                                    sum[c] += 2 * p[c] - 255;
                                ++n;
                            }
                        }
                    if (n == 0 || n == texelCount)
                        continue;
                    const glm::vec3 mean{float(sum[0]), float(sum[1]), float(sum[2])};
                    const float length = glm::length(mean);
                    if (!(length > 0.0f))
                        continue;
                    const glm::vec3 c = mean / length;
                    for (int k = 0; k < texelCount; ++k)
                        if (!(state[at[k]] & kTexelPainted)) {
                            const size_t x1 = at[k] % size_t(width), y1 = at[k] / size_t(width);
                            uint8_t *p = &image[(size_t(height - 1) - y1) * size_t(width) * 4 + x1 * 4];
                            p[0] = encodeFast(c.x), p[1] = encodeFast(c.y), p[2] = encodeFast(c.z);
                            state[at[k]] |= kTexelPainted;
                        }
                }
        });
    return out;
}

}  // namespace voxelfair
