// Triangle rasterisation in texel space, shared by packing, baking and the measures so that all
// of them agree on which texels a triangle touches.
//
// Texel (x, y) is the unit square [x, x+1] x [y, y+1] with y growing along v (up). Coordinates
// are doubles: final UVs are floats in [0, 1] times a texture side, so every stage sees the same
// numbers up to ~1e-4 texel, far below the margins used here; files may round them further
// (kUvRounding).
#pragma once

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/vec2.hpp>

namespace voxelfair {

// Twice the signed area; positive when a, b, c run counter-clockwise.
inline double doubleArea(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// How far (texels) a final UV may move after the atlas: float UVs move ~1e-4 texel, and text
// files round them to 6 digits (MeshLab's ASCII PLY writes "%g", OBJ "%f": up to 5e-7 in UV,
// 0.004 texel in an 8192 texture). The bake keeps a thin face's colour on every texel within
// this of its interior points, so a sample that rounding moves across a texel border still
// reads its face (crowded_faces.h separates with a 0.01 texel margin, more than twice this).
constexpr double kUvRounding = 1.0 / 256;

// Where the colour of a face is judged (atlas_measures.h) and guaranteed (bake.h): the incentre
// of its UV triangle q (in texels) and the points halfway from it to each corner. Returns the
// inradius (0 for a degenerate triangle, whose points are then not written).
inline double faceInteriorPoints(const glm::dvec2 q[3], glm::dvec2 points[4]) {
    const double a = glm::length(q[1] - q[2]), b = glm::length(q[2] - q[0]), c = glm::length(q[0] - q[1]);
    const double perimeter = a + b + c;
    if (!(perimeter > 0))
        return 0;
    const glm::dvec2 incentre = (q[0] * a + q[1] * b + q[2] * c) / perimeter;
    points[0] = incentre;
    for (int k = 0; k < 3; ++k)
        points[k + 1] = (incentre + q[k]) / 2.0;
    return std::abs(doubleArea(q[0], q[1], q[2])) / perimeter;
}

// v clamped onto [lo, hi], then truncated (its floor there when lo >= 0).
inline int clampToInt(double v, int lo, int hi) { return int(std::clamp(v, double(lo), double(hi))); }

// std::min({a, b, c}) and std::max({a, b, c}), the same value in every case (NaN included: a
// later value replaces the kept one only when it compares less, or greater), without the
// initializer list's loop.
inline double min3(double a, double b, double c) {
    double m = a;
    m = b < m ? b : m;
    return c < m ? c : m;
}
inline double max3(double a, double b, double c) {
    double m = a;
    m = m < b ? b : m;
    return m < c ? c : m;
}

// floor and ceil of a float or double v with |v| < 2^31: truncation, then one step (exact: a
// float or double too large to have a fraction is a whole number, so the step is 0 there).
template <class Real>
inline int floorToInt(Real v) {
    const int i = int(v);
    return i - int(Real(i) > v);
}
template <class Real>
inline int ceilToInt(Real v) {
    const int i = int(v);
    return i + int(Real(i) < v);
}

namespace raster_detail {
struct Edge {
    double ax, ay, ex, ey;
    double at(double px, double py) const { return ex * (py - ay) - ey * (px - ax); }  // > 0 inside
    double reach(double h) const { return h * (std::abs(ex) + std::abs(ey)); }
    // Fill rule for points exactly on the edge: the top and left edges of a counter-clockwise
    // triangle own them, so a point on an edge shared by two triangles is counted once.
    bool topLeft() const { return ey < 0 || (ey == 0 && ex < 0); }
};
struct Setup {
    Edge e[3];
    double minX, minY, maxX, maxY;
};
// False for a triangle without area (nothing to rasterise).
inline bool setup(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, Setup &s) {
    const double area = doubleArea(a, b, c);
    if (!(area != 0) || !std::isfinite(area))
        return false;
    if (area < 0)
        std::swap(b, c);
    const glm::dvec2 p[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
        const glm::dvec2 &p0 = p[i], &p1 = p[(i + 1) % 3];
        s.e[i] = {p0.x, p0.y, p1.x - p0.x, p1.y - p0.y};
    }
    s.minX = min3(a.x, b.x, c.x);
    s.maxX = max3(a.x, b.x, c.x);
    s.minY = min3(a.y, b.y, c.y);
    s.maxY = max3(a.y, b.y, c.y);
    return true;
}
// A triangle's rows solved in closed form for one test (edge i's inequality at(x, y) + reach[i]
// >= 0, or the centre test's > 0 with its top-left rule on 0). For an edge with k = -ey != 0 the
// test changes sign at x = t(y) on row y; t is linear in y, so it is kept as its value on the
// first row (y0) and its step per row. Edges with k > 0 bound the span from below (ceil t), the
// others from above (floor t); a triangle has one or two of each (the e.y sum to 0), and only
// those 2 or 3 bounds are kept. A horizontal edge (k = 0) keeps or drops whole rows.
//
// Rounding: a texel whose centre lies further than `tolerance` (texels) from t is classified by
// t exactly as the per-texel test classifies it, whose value there is then far from 0: the
// tolerance is far above the few ulps that either computation loses on its largest term
// (coordinates, edges and texture sides below 2^24 texels).
struct RowSolver {
    // The bounds in use, one per non-horizontal edge (2 or 3): lower[k] for a lower bound.
    double base[3], step[3], tolerance[3];
    bool lower[3];
    int count = 0;
    int horizontal = -1;  // the edge with k = 0, if any
    int x0, x1, y0;
    __attribute__((always_inline))
    RowSolver(const Setup &s, const double reach[3], const double inverse[3], int x0, int x1, int y0)
        : x0(x0), x1(x1), y0(y0) {
        const double c = std::max({std::abs(s.minX), std::abs(s.maxX), std::abs(s.minY), std::abs(s.maxY)}) + 2;
        for (int i = 0; i < 3; ++i) {
            const Edge &e = s.e[i];
            if (e.ey == 0) {
                horizontal = i;
                continue;
            }
            const int slot = count++;
            lower[slot] = e.ey < 0;  // k = -ey
            const double m = e.at(0.0, y0 + 0.5) + reach[i];
            base[slot] = -m * inverse[i] - 0.5;
            step[slot] = -e.ex * inverse[i];
            tolerance[slot] =
                1e-12 * ((std::abs(e.ex) + std::abs(e.ey)) * 2 * c + std::abs(reach[i])) * std::abs(inverse[i]);
        }
    }
};
// Per edge, 1 / k (0 for a horizontal edge), shared by a triangle's solvers.
inline void edgeInverses(const Setup &s, double inverse[3]) {
    for (int i = 0; i < 3; ++i)
        inverse[i] = s.e[i].ey != 0 ? -1 / s.e[i].ey : 0;
}

// Row y of texels x0..x1: the texels whose point (x + 0.5, y + 0.5) passes the test form one
// interval (each edge's inequality is a half-line in x), [xl, xr] (xl > xr: none). It is solved
// for (RowSolver); where a solved end lies so near a texel that rounding could decide that
// texel either way, the ends are settled with `inside`, the exact per-texel test, from one
// texel further out. Either way the span is exactly the texels that test accepts.
template <class Inside>
__attribute__((always_inline)) inline void rowSpan(const Setup &s, const double reach[3], const RowSolver &r, int y,
                                                   Inside &&inside, int &xl, int &xr) {
    const double j = y - r.y0;
    int lo = r.x0, hi = r.x1;
    bool clear = true;
    for (int slot = 0; slot < r.count; ++slot) {
        const double t = std::clamp(r.base[slot] + j * r.step[slot], r.x0 - 1.5, r.x1 + 1.5);
        const int below = floorToInt(t);  // t in [below, below + 1)
        clear = clear & (t - below > r.tolerance[slot]) & (below + 1 - t > r.tolerance[slot]);
        if (r.lower[slot])
            lo = std::max(lo, below + int(t > below));  // ceil
        else
            hi = std::min(hi, below);
    }
    if (r.horizontal >= 0) {  // its test's value is the same on the whole row, and exact
        const double m = s.e[r.horizontal].at(0.0, y + 0.5) + reach[r.horizontal];
        clear = clear & (m != 0);
        if (m < 0)
            hi = lo - 1;
    }
    xl = std::min(lo, r.x1 + 1), xr = std::max(hi, r.x0 - 1);
    if (clear)
        return;
    xl = std::max(r.x0, xl - 1), xr = std::min(r.x1, xr + 1);
    while (xl <= xr && !inside(xl, y))
        ++xl;
    while (xr >= xl && !inside(xr, y))
        --xr;
    if (xl > xr)  // an empty start: look next to where it was
        xr = xl - 1;
    while (xl > r.x0 && inside(xl - 1, y))
        --xl;
    while (xr < r.x1 && inside(xr + 1, y))
        ++xr;
}

// Rows y0..y1 of texels x0..x1, each row's span (rowSpan) visited when not empty; only rows
// rowFrom..rowTo of them (the solver still starts at y0: the same spans as without the limits).
template <class Inside, class VisitSpan>
void spans(const Setup &s, const double reach[3], int x0, int x1, int y0, int y1, Inside &&inside,
           VisitSpan &&visitSpan, int rowFrom = 0, int rowTo = INT32_MAX) {
    double inverse[3];
    edgeInverses(s, inverse);
    const RowSolver solver(s, reach, inverse, x0, x1, y0);
    for (int y = std::max(y0, rowFrom); y <= std::min(y1, rowTo); ++y) {
        int xl, xr;
        rowSpan(s, reach, solver, y, inside, xl, xr);
        if (xl <= xr)
            visitSpan(y, xl, xr);
    }
}

// The texels x0..x1, y0..y1 within [0, width) x [0, height) whose square, grown by `margin`, can
// meet a triangle with this bounding box: the conservative test's range (empty: x0 > x1 or
// y0 > y1). Exact integer floors and ceilings where the box is within 2^30 of the origin.
struct TexelBox {
    int x0, x1, y0, y1;
};
constexpr double kSafe = 1 << 30;  // boxes within this of the origin take the integer floors
inline TexelBox conservativeBox(double minX, double maxX, double minY, double maxY, double margin, int width,
                                int height) {
    if (minX > -kSafe && maxX < kSafe && minY > -kSafe && maxY < kSafe)
        return {
            std::clamp(ceilToInt(minX - 1 - margin), 0, width), std::clamp(floorToInt(maxX + margin), -1, width - 1),
            std::clamp(ceilToInt(minY - 1 - margin), 0, height), std::clamp(floorToInt(maxY + margin), -1, height - 1)};
    return {clampToInt(std::ceil(minX - 1 - margin), 0, width), clampToInt(std::floor(maxX + margin), -1, width - 1),
            clampToInt(std::ceil(minY - 1 - margin), 0, height), clampToInt(std::floor(maxY + margin), -1, height - 1)};
}
// The texels whose centre can lie in a triangle with this bounding box: the centre test's range.
inline TexelBox centreBox(double minX, double maxX, double minY, double maxY, int width, int height) {
    if (minX > -kSafe && maxX < kSafe && minY > -kSafe && maxY < kSafe)
        return {std::clamp(ceilToInt(minX - 0.5), 0, width), std::clamp(floorToInt(maxX - 0.5), -1, width - 1),
                std::clamp(ceilToInt(minY - 0.5), 0, height), std::clamp(floorToInt(maxY - 0.5), -1, height - 1)};
    return {clampToInt(std::ceil(minX - 0.5), 0, width), clampToInt(std::floor(maxX - 0.5), -1, width - 1),
            clampToInt(std::ceil(minY - 0.5), 0, height), clampToInt(std::floor(maxY - 0.5), -1, height - 1)};
}

// The conservative test (texel square grown by `margin` meets the triangle, by three
// half-planes) and the centre test (top-left rule) of one triangle, with their texel ranges.
struct ConservativeTest {
    const Setup &s;
    double reach[3];
    int x0, x1, y0, y1;
    ConservativeTest(const Setup &setup, double margin, int width, int height) : s(setup) {
        const TexelBox box = conservativeBox(s.minX, s.maxX, s.minY, s.maxY, margin, width, height);
        x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
        const double h = 0.5 + margin;
        for (int i = 0; i < 3; ++i)
            reach[i] = s.e[i].reach(h);
    }
    bool operator()(int x, int y) const {
        const double cx = x + 0.5, cy = y + 0.5;
        return s.e[0].at(cx, cy) + reach[0] >= 0 && s.e[1].at(cx, cy) + reach[1] >= 0 &&
               s.e[2].at(cx, cy) + reach[2] >= 0;
    }
};
struct CentreTest {
    const Setup &s;
    bool tl[3];
    int x0, x1, y0, y1;
    CentreTest(const Setup &setup, int width, int height) : s(setup) {
        const TexelBox box = centreBox(s.minX, s.maxX, s.minY, s.maxY, width, height);
        x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
        for (int i = 0; i < 3; ++i)
            tl[i] = s.e[i].topLeft();
    }
    bool operator()(int x, int y) const {
        const double cx = x + 0.5, cy = y + 0.5;
        for (int i = 0; i < 3; ++i) {
            const double v = s.e[i].at(cx, cy);
            if (!(v > 0 || (v == 0 && tl[i])))
                return false;
        }
        return true;
    }
};

// The texels x of [x0, x1] on row y that `inside` accepts, as xl..xr (empty: xl > xr), found by
// testing from both ends. The same span as the row solver's: each test is monotonic in x along a
// row (rounding keeps the order), so the texels it accepts are one interval. Cheaper than solving
// the rows of a triangle under kNarrowRows texels wide.
template <class Inside>
inline void testedSpan(const Inside &inside, int x0, int x1, int y, int &xl, int &xr) {
    xl = x0, xr = x1;
    while (xl <= xr && !inside(xl, y))
        ++xl;
    while (xr > xl && !inside(xr, y))  // xl, when found, is not tested again
        --xr;
}
// testedSpan on each row of `test`'s box within rowFrom..rowTo, visitSpan(y, xl, xr) where not empty.
template <class Test, class VisitSpan>
void testedSpans(const Test &test, int rowFrom, int rowTo, VisitSpan &&visitSpan) {
    for (int y = std::max(test.y0, rowFrom); y <= std::min(test.y1, rowTo); ++y) {
        int xl, xr;
        testedSpan(test, test.x0, test.x1, y, xl, xr);
        if (xl <= xr)
            visitSpan(y, xl, xr);
    }
}
}  // namespace raster_detail

// Triangles whose conservative span is under this many columns have their rows found texel by
// texel (raster_detail::testedSpan) instead of solved.
constexpr int kNarrowRows = 4;

// Calls visitSpan(y, x0, x1) for every row y with texels inside [0, width) x [0, height) whose
// square, grown by `margin` on every side, meets the closed triangle: those are x0..x1. margin < 0
// asks for an overlap of positive size (a square that only touches an edge is left out); margin
// > 0 gives a safe superset. Near sharp corners the three half-plane tests keep a few squares
// that only meet the bounding box: conservative, never missing a touched texel.
// Only rows rowFrom..rowTo are visited (the same spans: a band of rows of a larger raster).
template <class VisitSpan>
void rasterConservativeSpans(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double margin, int width, int height,
                             VisitSpan &&visitSpan, int rowFrom = 0, int rowTo = INT32_MAX) {
    raster_detail::Setup s;
    if (!raster_detail::setup(a, b, c, s))
        return;
    const raster_detail::ConservativeTest test(s, margin, width, height);
    if (test.x0 > test.x1)
        return;
    if (test.x1 - test.x0 < kNarrowRows) {
        raster_detail::testedSpans(test, rowFrom, rowTo, visitSpan);
        return;
    }
    raster_detail::spans(s, test.reach, test.x0, test.x1, test.y0, test.y1, test, visitSpan, rowFrom, rowTo);
}

// The same texels one by one: visit(x, y).
template <class Visit>
void rasterConservative(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double margin, int width, int height, Visit &&visit) {
    rasterConservativeSpans(a, b, c, margin, width, height, [&](int y, int xl, int xr) {
        for (int x = xl; x <= xr; ++x)
            visit(x, y);
    });
}

// Calls visit(x, y) for every texel inside [0, width) x [0, height) whose centre lies inside the
// triangle; centres exactly on an edge follow the top-left rule, so the triangles of a planar,
// non-overlapping mesh cover every centre at most once.
// Calls visitSpan(y, x0, x1) for every row y of [0, width) x [0, height) with texels whose centre
// lies inside the triangle: those are x0..x1. Centres exactly on an edge follow the top-left
// rule, so the triangles of a planar, non-overlapping mesh cover every centre at most once.
// Only rows rowFrom..rowTo are visited (the same spans: a band of rows of a larger raster).
template <class VisitSpan>
void rasterCentreSpans(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, int width, int height, VisitSpan &&visitSpan,
                       int rowFrom = 0, int rowTo = INT32_MAX) {
    raster_detail::Setup s;
    if (!raster_detail::setup(a, b, c, s))
        return;
    const raster_detail::CentreTest test(s, width, height);
    if (test.x0 > test.x1)
        return;
    if (test.x1 - test.x0 < kNarrowRows) {  // as rasterConservativeSpans
        raster_detail::testedSpans(test, rowFrom, rowTo, visitSpan);
        return;
    }
    const double reach[3] = {0, 0, 0};
    raster_detail::spans(s, reach, test.x0, test.x1, test.y0, test.y1, test, visitSpan, rowFrom, rowTo);
}

// The same texels one by one: visit(x, y).
template <class Visit>
void rasterCentres(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, int width, int height, Visit &&visit) {
    rasterCentreSpans(a, b, c, width, height, [&](int y, int xl, int xr) {
        for (int x = xl; x <= xr; ++x)
            visit(x, y);
    });
}

// Both at once, row by row, for a bake: visitRow(y, cl, cr, zl, zr) for every row with
// conservative texels cl..cr (rasterConservativeSpans, margin > -0.5), of which zl..zr
// (rasterCentres; zl > zr: none) hold their centre inside the triangle.
// Only rows rowFrom..rowTo are visited (the same spans: a band of rows of a larger raster).
template <class VisitRow>
void rasterRows(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double margin, int width, int height, VisitRow &&visitRow,
                int rowFrom = 0, int rowTo = INT32_MAX) {
    raster_detail::Setup s;
    if (!raster_detail::setup(a, b, c, s))
        return;
    const raster_detail::ConservativeTest conservative(s, margin, width, height);
    const raster_detail::CentreTest centre(s, width, height);
    if (conservative.x0 > conservative.x1)
        return;
    const bool centres = centre.x0 <= centre.x1;
    if (conservative.x1 - conservative.x0 < kNarrowRows) {
        // A narrow triangle (most of them at a few texels per voxel): each row's texels tested one
        // by one (testedSpan: the same spans as solving its rows, for less).
        for (int y = std::max(conservative.y0, rowFrom); y <= std::min(conservative.y1, rowTo); ++y) {
            int cl, cr, zl = 0, zr = -1;
            raster_detail::testedSpan(conservative, conservative.x0, conservative.x1, y, cl, cr);
            if (centres && y >= centre.y0 && y <= centre.y1) {
                raster_detail::testedSpan(centre, centre.x0, centre.x1, y, zl, zr);
                if (zl > zr)
                    zl = 0, zr = -1;
            }
            if (cl <= cr || zl <= zr)
                visitRow(y, cl, cr, zl, zr);
        }
        return;
    }
    const double zero[3] = {0, 0, 0};
    double inverse[3];
    raster_detail::edgeInverses(s, inverse);
    const raster_detail::RowSolver conservativeRows(s, conservative.reach, inverse, conservative.x0, conservative.x1,
                                                    conservative.y0);
    const raster_detail::RowSolver centreRows(s, zero, inverse, centre.x0, centre.x1, centre.y0);
    for (int y = std::max(conservative.y0, rowFrom); y <= std::min(conservative.y1, rowTo); ++y) {
        int cl, cr, zl = 0, zr = -1;
        raster_detail::rowSpan(s, conservative.reach, conservativeRows, y, conservative, cl, cr);
        if (centres && y >= centre.y0 && y <= centre.y1)
            raster_detail::rowSpan(s, zero, centreRows, y, centre, zl, zr);
        if (cl <= cr || zl <= zr)
            visitRow(y, cl, cr, zl, zr);
    }
}

}  // namespace voxelfair
