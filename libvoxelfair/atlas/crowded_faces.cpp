#include "atlas/crowded_faces.h"

#include "atlas/seed_plane.h"
#include "atlas/texel_raster.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace voxelfair {
namespace {

// sqrt(2) texels, the reach of one texel's diagonal, plus a margin for the float rounding of
// the final UVs (about 1e-3 texel in a 16384 texture): the bake's own threshold is exactly
// sqrt(2), so every face it treats as thin is thin here too.
constexpr double kReach = 1.41421356237309505 + 0.01;

// Thin faces' interior points, bucketed by (chart, cell) in cells of 2 * kReach texels: each
// point goes into every cell its kReach box meets (at most 4), so the points near a query point
// are all in the query point's own cell.
class ThinPointGrid {
public:
    explicit ThinPointGrid(size_t points) {
        size_t slots = 64;
        while (slots < 8 * points)
            slots *= 2;
        slots_.assign(slots, Slot{});
        mask_ = slots - 1;
    }

    void insert(uint32_t chart, glm::dvec2 p, uint32_t owner) {
        const int x0 = cell(p.x - kReach), x1 = cell(p.x + kReach);
        const int y0 = cell(p.y - kReach), y1 = cell(p.y + kReach);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                Slot &s = slots_[find(chart, x, y)];
                s.chart = chart, s.x = x, s.y = y;
                entries_.push_back({p, owner, s.head});
                s.head = uint32_t(entries_.size() - 1);
            }
    }

    // Calls visit(owner) for every thin point within kReach of p in `chart`.
    template <class Visit>
    void near(uint32_t chart, glm::dvec2 p, Visit &&visit) const {
        const Slot &s = slots_[find(chart, cell(p.x), cell(p.y))];
        for (uint32_t e = s.head; e != kNone; e = entries_[e].next) {
            const glm::dvec2 d = entries_[e].p - p;
            if (glm::dot(d, d) < kReach * kReach)
                visit(entries_[e].owner);
        }
    }

private:
    static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
    struct Slot {
        uint32_t chart = kNone;
        int x = 0, y = 0;
        uint32_t head = kNone;
    };
    struct Entry {
        glm::dvec2 p;
        uint32_t owner, next;
    };
    static int cell(double v) { return int(std::floor(v / (2 * kReach))); }

    // The slot of (chart, x, y), or the empty slot where it would go.
    size_t find(uint32_t chart, int x, int y) const {
        uint64_t h = (uint64_t(chart) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(uint32_t(x)) * 0xC2B2AE3D27D4EB4Full) ^
                     (uint64_t(uint32_t(y)) * 0x165667B19E3779F9ull);
        h ^= h >> 29;
        for (size_t i = size_t(h) & mask_;; i = (i + 1) & mask_) {
            const Slot &s = slots_[i];
            if (s.chart == kNone || (s.chart == chart && s.x == x && s.y == y))
                return i;
        }
    }

    std::vector<Slot> slots_;
    std::vector<Entry> entries_;
    size_t mask_ = 0;
};

// Face f's UV triangle in texels, projected onto its own plane and boxed at the origin.
void projectAlone(const AtlasMesh &mesh, uint32_t f, glm::vec2 uv[3], glm::vec3 &axis, glm::vec2 &size) {
    const uint32_t *t = mesh.triangles + 3 * size_t(f);
    const glm::dvec3 p0 = mesh.positions[t[0]], p1 = mesh.positions[t[1]], p2 = mesh.positions[t[2]];
    const glm::dvec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    const SeedPlane plane = seedPlane(n);
    const glm::dvec3 d[3] = {glm::dvec3(0.0), p1 - p0, p2 - p0};
    glm::dvec2 q[3], lo(std::numeric_limits<double>::max());
    for (int k = 0; k < 3; ++k) {
        q[k] = {glm::dot(d[k], plane.t1), glm::dot(d[k], plane.t2)};
        lo = glm::min(lo, q[k]);
    }
    glm::dvec2 hi(0.0);
    for (int k = 0; k < 3; ++k) {
        uv[k] = glm::vec2(q[k] - lo);
        hi = glm::max(hi, q[k] - lo);
    }
    axis = glm::vec3(n);
    size = glm::vec2(hi);
}

}  // namespace

CrowdedFaces separateCrowdedFaces(const AtlasMesh &mesh, AtlasCharts &charts, const CrowdedFaceOptions &options) {
    CrowdedFaces out;
    const double d = options.texelsPerUnit;
    if (mesh.faceColours == nullptr || charts.status != AtlasStatus::Ok || charts.faceCount() != mesh.faceCount ||
        !(d > 0) || !std::isfinite(d))
        return out;
    const size_t entries = charts.chartFaces.size();
    auto colour = [&](size_t i) { return mesh.faceColours[charts.chartFaces[i]]; };
    auto points = [&](size_t i, glm::dvec2 p[4]) {
        glm::dvec2 q[3];
        for (int k = 0; k < 3; ++k)
            q[k] = glm::dvec2(charts.wedgeUv[3 * i + k]) * d;
        return faceInteriorPoints(q, p);
    };

    // Thin faces (by position in chartFaces) of the charts that hold one and more than one colour.
    std::vector<double> inradius(entries, 0.0);
    std::vector<uint32_t> searched;  // charts to search
    std::vector<uint32_t> thin;
    for (uint32_t c = 0; c < charts.chartCount(); ++c) {
        if (charts.isDegenerate(c))
            continue;
        const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
        bool mixed = false;
        const size_t thinBefore = thin.size();
        glm::dvec2 p[4];
        for (uint32_t i = first; i < end; ++i) {
            mixed = mixed || colour(i) != colour(first);
            inradius[i] = points(i, p);
            if (inradius[i] < kReach)
                thin.push_back(i);
        }
        out.thinFaces += thin.size() - thinBefore;
        if (mixed && thin.size() > thinBefore)
            searched.push_back(c);
        else
            thin.resize(thinBefore);
    }
    if (thin.empty())
        return out;

    // Pairs (thin face, face of another colour) with interior points closer than kReach.
    ThinPointGrid grid(4 * thin.size());
    for (uint32_t i : thin) {
        glm::dvec2 p[4];
        points(i, p);
        for (const glm::dvec2 &q : p)
            grid.insert(charts.faceChart[charts.chartFaces[i]], q, i);
    }
    std::vector<std::pair<uint32_t, uint32_t>> crowded;
    for (uint32_t c : searched)
        for (uint32_t i = charts.chartFirstFace[c]; i < charts.chartFirstFace[c + 1]; ++i) {
            glm::dvec2 p[4];
            points(i, p);
            for (const glm::dvec2 &q : p)
                grid.near(c, q, [&](uint32_t owner) {
                    if (owner != i && colour(owner) != colour(i))
                        crowded.emplace_back(owner, i);
                });
        }
    std::sort(crowded.begin(), crowded.end());
    crowded.erase(std::unique(crowded.begin(), crowded.end()), crowded.end());

    // Thinnest first: a thin face leaves its chart while any partner is still in it.
    std::sort(thin.begin(), thin.end(), [&](uint32_t a, uint32_t b) {
        return inradius[a] != inradius[b] ? inradius[a] < inradius[b] : a < b;
    });
    std::vector<uint8_t> separated(entries, 0);
    for (uint32_t i : thin) {
        auto pair = std::lower_bound(crowded.begin(), crowded.end(), std::make_pair(i, uint32_t(0)));
        for (; pair != crowded.end() && pair->first == i; ++pair)
            if (!separated[pair->second]) {
                separated[i] = 1;
                ++out.crowdedFaces;
                break;
            }
    }
    if (out.crowdedFaces == 0 || double(out.crowdedFaces) > options.maxSeparatedShare * double(mesh.faceCount))
        return out;
    out.separatedFaces = out.crowdedFaces;

    // Rebuild the charts: the remaining faces of each chart (re-boxed where faces left), then one
    // chart per separated face, then the degenerate faces' charts, which stay last.
    AtlasCharts rebuilt;
    rebuilt.chartFaces.reserve(entries);
    rebuilt.wedgeUv.reserve(3 * entries);
    rebuilt.faceChart.assign(charts.faceCount(), 0);
    auto addChart = [&](glm::vec3 axis, glm::vec2 size) {
        rebuilt.chartFirstFace.push_back(uint32_t(rebuilt.chartFaces.size()));
        rebuilt.chartAxis.push_back(axis);
        rebuilt.chartSize.push_back(size);
    };
    auto addFace = [&](uint32_t f, const glm::vec2 *uv) {
        rebuilt.faceChart[f] = uint32_t(rebuilt.chartAxis.size() - 1);
        rebuilt.chartFaces.push_back(f);
        rebuilt.wedgeUv.insert(rebuilt.wedgeUv.end(), uv, uv + 3);
    };
    for (uint32_t c = 0; c < charts.chartCount(); ++c) {
        if (charts.isDegenerate(c))
            continue;
        const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
        glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        bool left = false;
        for (uint32_t i = first; i < end; ++i) {
            left = left || separated[i];
            if (!separated[i])
                for (int k = 0; k < 3; ++k) {
                    lo = glm::min(lo, charts.wedgeUv[3 * i + k]);
                    hi = glm::max(hi, charts.wedgeUv[3 * i + k]);
                }
        }
        if (hi.x < lo.x)
            continue;  // every face of the chart left it
        if (!left)
            lo = glm::vec2(0.0f), hi = charts.chartSize[c];
        addChart(charts.chartAxis[c], hi - lo);
        for (uint32_t i = first; i < end; ++i)
            if (!separated[i]) {
                const glm::vec2 uv[3] = {charts.wedgeUv[3 * i] - lo, charts.wedgeUv[3 * i + 1] - lo,
                                         charts.wedgeUv[3 * i + 2] - lo};
                addFace(charts.chartFaces[i], uv);
            }
    }
    for (uint32_t i = 0; i < entries; ++i)
        if (separated[i]) {
            glm::vec2 uv[3], size;
            glm::vec3 axis;
            projectAlone(mesh, charts.chartFaces[i], uv, axis, size);
            addChart(axis, size);
            addFace(charts.chartFaces[i], uv);
        }
    for (uint32_t c = 0; c < charts.chartCount(); ++c)
        if (charts.isDegenerate(c)) {
            addChart(charts.chartAxis[c], charts.chartSize[c]);
            addFace(charts.chartFaces[charts.chartFirstFace[c]], &charts.wedgeUv[3 * size_t(charts.chartFirstFace[c])]);
        }
    rebuilt.chartFirstFace.push_back(uint32_t(rebuilt.chartFaces.size()));

    charts.chartFirstFace.swap(rebuilt.chartFirstFace);
    charts.chartFaces.swap(rebuilt.chartFaces);
    charts.faceChart.swap(rebuilt.faceChart);
    charts.chartAxis.swap(rebuilt.chartAxis);
    charts.chartSize.swap(rebuilt.chartSize);
    charts.wedgeUv.swap(rebuilt.wedgeUv);
    charts.separatedFaces += out.separatedFaces;
    return out;
}

}  // namespace voxelfair
