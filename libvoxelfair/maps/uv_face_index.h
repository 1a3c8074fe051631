// Source faces by their place in the atlas, for the normal bake (normal_bake.h): where a
// target texel's search for its source point starts. The source shares the target's atlas
// (decimation with texture keeps the UVs), so the source face whose UV triangle holds a texel's
// centre is the natural start:
//   SortedSource     the source with its faces renumbered by UV cell (faces near in the atlas
//                    near in memory);
//   fillFacesUnder   per band of rows, the source face under each texel centre (a scanline fill);
//   UvFaceGrid       the fallback where no face is under a texel: the face holding a UV point,
//                    else the one with the nearest UV centroid in its cell;
//   faceBands        target faces by the bands of rows they touch.
// UVs are scaled to texel space: u * width, v * height (rows from v = 0 up).
#pragma once

#include "maps/normal_bake.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace voxelfair {

inline void loadUv(const NormalBakeMesh &m, size_t f, int width, int height, glm::dvec2 q[3]) {
    for (int k = 0; k < 3; ++k)
        q[k] = glm::dvec2(m.wedgeUv[3 * f + size_t(k)]) * glm::dvec2(width, height);
}

// Source faces by the texel-space boxes of their UV triangles, in cells of 16 x 16 texels: where
// a texel's walk starts (the source face under the same UV).
class UvFaceGrid {
public:
    UvFaceGrid(const NormalBakeMesh &m, int width, int height);
    // The source face whose UV triangle holds texel-space point p, else the one whose UV centroid
    // is nearest among those of p's cell; UINT32_MAX when the cell is empty.
    uint32_t find(glm::dvec2 p) const;

private:
    static constexpr int kCell = 16;
    const NormalBakeMesh &mesh_;
    int width_, height_, cellsX_, cellsY_;
    std::vector<uint32_t> start_, faces_;
};

// Target faces by the bands of rows their UV triangles may touch (conservatively), in face order.
struct FaceBands {
    std::vector<uint32_t> start, faces;
};

FaceBands faceBands(const NormalBakeMesh &mesh, int width, int height, int bandRows);

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

// The source face under each texel centre of rows [r0, r1): rows[(y - r0) * width + x] = face
// for the centres inside face `face`'s UV triangle (later faces overwrite earlier ones).
inline void fillFacesUnder(const NormalBakeMesh &mesh, uint32_t face, int width, int height, int r0, int r1,
                           uint32_t *rows) {
    underSpans(mesh.wedgeUv + 3 * size_t(face), width, height, r0, r1, [&](int y, int xl, int xr) {
        std::fill_n(&rows[size_t(y - r0) * size_t(width) + size_t(xl)], xr - xl + 1, face);
    });
}

// The source with its faces renumbered by the atlas cell (kSortCell texels square) of their UV
// centroid, cells row by row (a counting sort): faces near in the atlas are near in memory, and
// the source faces under a target face lie in a few runs the walk can fetch ahead.
struct SortedSource {
    static constexpr int kSortCell = 16;
    std::vector<uint32_t> triangles;
    std::vector<glm::vec2> wedgeUv;
    int cellsX = 0, cellsY = 0;
    std::vector<uint32_t> cellStart;   // the faces of cell c: [cellStart[c], cellStart[c + 1])
    std::vector<uint32_t> sortedFace;  // the source's face f is face sortedFace[f] here
    NormalBakeMesh mesh;

    SortedSource(const NormalBakeMesh &source, int width, int height);
    uint32_t cell(double x, double y) const {
        const int cx = std::isfinite(x) ? std::clamp(int(x / kSortCell), 0, cellsX - 1) : 0;
        const int cy = std::isfinite(y) ? std::clamp(int(y / kSortCell), 0, cellsY - 1) : 0;
        return uint32_t(cy) * uint32_t(cellsX) + uint32_t(cx);
    }
};

}  // namespace voxelfair
