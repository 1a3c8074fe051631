#include "atlas/packing.h"

#include "atlas/pack_paper.h"
#include "atlas/pack_tight.h"
#include "atlas/texel_raster.h"

#include <algorithm>
#include <cmath>

namespace voxelfair {

const char *toString(PackMode mode) {
    return mode == PackMode::Paper ? "paper" : "tight";
}

namespace {

constexpr int kMaxSide = 16384;  // the packers keep texel rows and columns in int16

struct Packing {
    ChartMasks masks;
    std::vector<ChartPlacement> placements;
};

// Whether the charts fit, and what that says about the density that would just fit. The paper
// packer's square grows like the density: `grow` = side / square. For the tight packer, `demand`
// is the room its charts take over the square's area and `filled` the share it managed to fill
// (all of it on a fit; up to the first miss otherwise; 0 when it gave up at once).
struct Fit {
    bool fits = false;
    double grow = 0;
    double demand = 0, filled = 0;
};

// Places already rasterised masks in a side x side square.
Fit place(const ChartMasks &masks, PackMode mode, int side, bool turns, std::vector<ChartPlacement> &placements) {
    const double square = double(side) * side;
    if (mode == PackMode::Tight) {
        const TightPacking t = packTight(masks, side, turns, placements);
        return {t.fits, 0, double(t.room) / square, double(t.placedRoom) / square};
    }
    const int used = packPaper(masks, placements);
    const double grow = double(side) / std::max(used, 1);
    if (used > side)
        return {false, grow};
    const int shift = (side - used) / 2;  // the paper's square, centred in the texture
    for (ChartPlacement &p : placements)
        p.x += shift, p.y += shift;
    return {true, grow};
}

Fit attempt(const AtlasCharts &charts, const PackOptions &o, double density, int padding, int side, Packing &out,
            size_t &attempts) {
    ++attempts;
    if (!rasterizeChartMasks(charts, density, padding, side, out.masks))
        return {};  // a chart alone is wider than the texture
    return place(out.masks, o.mode, side, o.allowRotation, out.placements);
}

// The largest density (within 0.5%, below `ceiling`) whose packing fits a side x side square.
//
// Each packing predicts the density that would just fit: the paper packer from its square, the
// tight one from the room its charts take, which grows about like density squared, and the
// share of the square it can fill (seen at the last miss or the best fit; 90% until known). The
// prediction is kept inside the bracket of the best fit and the lowest miss so far; bisection
// takes over when it falls outside.
bool densestFit(const AtlasCharts &charts, const PackOptions &o, int padding, int side, double ceiling,
                Packing &best, double &density, size_t &attempts) {
    // Upper bound: the charts' projected area cannot exceed the texture, nor a chart its side.
    double area = 0, longest = 0;
    for (size_t c = 0; c < charts.chartCount(); ++c) {
        if (charts.isDegenerate(c))
            continue;
        longest = std::max<double>({longest, charts.chartSize[c].x, charts.chartSize[c].y});
        for (uint32_t i = charts.chartFirstFace[c]; i < charts.chartFirstFace[c + 1]; ++i) {
            const glm::vec2 *uv = &charts.wedgeUv[3 * size_t(i)];
            area += 0.5 * std::abs(doubleArea(uv[0], uv[1], uv[2]));
        }
    }
    double miss = area > 0 ? double(side) / std::sqrt(area) : 1.0;
    if (longest > 0)
        miss = std::min(miss, side / longest);
    miss = std::min(miss * 1.0001, ceiling);
    const double floor = miss * 1e-4;  // below this only the fixed-size parts (gutters) remain
    double fit = 0, d = miss * 0.85, reachable = 0.9, fitFilled = 0;
    Packing trial;
    for (int i = 0; i < 16 && d > floor; ++i) {
        const Fit f = attempt(charts, o, d, padding, side, trial, attempts);
        if (f.fits) {
            fit = d;
            fitFilled = f.filled;
            std::swap(best, trial);
        } else {
            miss = d;
            if (f.filled > 0)
                reachable = f.filled;
        }
        if (fit > 0 && miss <= fit * 1.005)
            break;
        reachable = std::max(reachable, fitFilled);
        double next = f.grow > 0 ? d * f.grow : f.demand > 0 ? d * std::sqrt(reachable / f.demand) : 0;
        next *= 0.998;  // aim just below
        if (!(next > std::max(fit, floor) * 1.001 && next < miss / 1.001))
            next = fit > 0 ? std::sqrt(fit * miss) : d * 0.7;
        d = next;
    }
    density = fit;
    return fit > 0;
}

int largestPowerOfTwoAtMost(int v) {
    int p = 1;
    while (p * 2 <= v)
        p *= 2;
    return p;
}

int nextPowerOfTwo(double v) {
    int p = 1;
    while (p < v && p < kMaxSide)
        p *= 2;
    return p;
}

}  // namespace

AtlasLayout packCharts(const AtlasCharts &charts, const PackOptions &options) {
    AtlasLayout out;
    out.mode = options.mode;
    out.status = charts.status;
    out.message = charts.message;
    if (charts.status != AtlasStatus::Ok)
        return out;
    const int maxSide = largestPowerOfTwoAtMost(std::clamp(options.maxTextureSize, 1, kMaxSide));
    out.gutter = std::max(2, options.gutter + (options.gutter & 1));
    const int padding = out.gutter / 2;
    auto fail = [&](std::string message) {
        out.status = AtlasStatus::InvalidInput;
        out.message = std::move(message);
        return out;
    };

    Packing packing;
    if (options.textureSize > 0) {
        out.size = std::min(options.textureSize, kMaxSide);
        if (!densestFit(charts, options, padding, out.size, INFINITY, packing, out.texelsPerUnit, out.packAttempts))
            return fail("the charts do not fit a " + std::to_string(out.size) + " texture at any density");
    } else {
        if (!(options.texelsPerUnit > 0) || !std::isfinite(options.texelsPerUnit))
            return fail("texelsPerUnit must be positive and finite");
        out.texelsPerUnit = options.texelsPerUnit;
        bool fits = false;
        ++out.packAttempts;
        if (rasterizeChartMasks(charts, out.texelsPerUnit, padding, maxSide, packing.masks)) {
            int longest = 1;
            for (const ChartMask &m : packing.masks.charts)
                longest = std::max({longest, m.width, m.height});
            for (out.size = nextPowerOfTwo(std::max<double>(longest, std::sqrt(double(packing.masks.totalMaskTexels))));
                 !fits && out.size <= maxSide; out.size *= 2) {
                fits = place(packing.masks, options.mode, out.size, options.allowRotation, packing.placements).fits;
                if (fits)
                    break;
                ++out.packAttempts;
            }
        }
        if (!fits) {
            out.size = maxSide;
            out.densityReduced = true;
            if (!densestFit(charts, options, padding, out.size, options.texelsPerUnit, packing, out.texelsPerUnit,
                            out.packAttempts))
                return fail("the charts do not fit a " + std::to_string(out.size) + " texture at any density");
            out.message = "texels per unit lowered from " + std::to_string(options.texelsPerUnit) + " to " +
                          std::to_string(out.texelsPerUnit) + " to fit " + std::to_string(out.size) + " x " +
                          std::to_string(out.size);
        }
    }

    // Final UVs: chart texels -> turned mask -> texture, over the side.
    out.placements = packing.placements;
    out.wedgeUv.resize(charts.wedgeUv.size());
    const double side = out.size;
    for (size_t c = 0; c < charts.chartCount(); ++c) {
        const ChartMask &m = packing.masks.charts[c];
        const ChartPlacement &p = packing.placements[c];
        for (uint32_t i = charts.chartFirstFace[c]; i < charts.chartFirstFace[c + 1]; ++i) {
            const uint32_t f = charts.chartFaces[i];
            for (int k = 0; k < 3; ++k) {
                const glm::dvec2 q = glm::dvec2(charts.wedgeUv[3 * size_t(i) + k]) * m.scale + m.offset;
                out.wedgeUv[3 * f + k] = glm::vec2((turnInMask(q, m.width, m.height, p.quarterTurns) +
                                                    glm::dvec2(p.x, p.y)) / side);
            }
        }
    }
    // A sliver thinner than float precision can come out flat or flipped; give it a tiny
    // right triangle (1/64 texel) at its first corner so every face keeps a positive UV area.
    for (size_t f = 0; f < charts.faceCount(); ++f) {
        glm::vec2 *uv = &out.wedgeUv[3 * f];
        if (doubleArea(glm::dvec2(uv[0]) * side, glm::dvec2(uv[1]) * side, glm::dvec2(uv[2]) * side) > 0)
            continue;
        const float e = float(1.0 / 64 / side);
        uv[1] = uv[0] + glm::vec2(e, 0);
        uv[2] = uv[0] + glm::vec2(0, e);
        ++out.nudgedFaces;
    }
    return out;
}

}  // namespace voxelfair
