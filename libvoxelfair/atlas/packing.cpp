#include "atlas/packing.h"

#include "atlas/chart_outline.h"
#include "atlas/chart_runs.h"
#include "atlas/pack_paper.h"
#include "atlas/pack_tight.h"
#include "atlas/texel_raster.h"
#include "base/error.h"
#include "base/parallel_bands.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace voxelfair {

const char *toString(PackMode mode) { return mode == PackMode::Paper ? "paper" : "tight"; }

namespace {

constexpr int kMaxSide = 16384;  // the packers keep texel rows and columns in int16

// Charts of at least this many blocks (4 x 4) get a bitmap (chart_bitmaps.h) and are packed by
// their shape, not their box: on legs 64 -> 16 halves the texture (2048^2 -> 2048 x 1024).
constexpr int64_t kLeastBitmapBlocks = 16;

// Masks in texels or, with mipBlocks, on 2 x 2 blocks (what the packer then sees); placements
// in texels either way.
struct Packing {
    int block = 1;
    // With blocks: the basis of the charts' outlines (chart_outline.h), once per packCharts.
    const ChartOutlineBasis *outlines = nullptr;
    ChartMasks masks, blocks;
    ChartBitmaps bitmaps;  // of the larger charts, with blocks
    std::vector<ChartPlacement> placements;
    const ChartMasks &packed() const { return block > 1 ? blocks : masks; }
};

bool rasterize(const AtlasCharts &charts, double density, int padding, int maxSide, int threads, Packing &out) {
    if (out.block == 1)
        return rasterizeChartMasks(charts, density, padding, maxSide, out.masks, threads);
    if (!rasterizeChartMasks(charts, density, padding, maxSide, out.blocks, threads, true, out.outlines))
        return false;
    takeChartBitmaps(charts, out.blocks, kLeastBitmapBlocks, out.bitmaps);
    return true;
}

// Whether the charts fit, and what that says about the density that would just fit. The paper
// packer's square grows like the density: `grow` = side / square. For the tight packer, `demand`
// is the room its charts take over the square's area and `filled` the share it managed to fill
// (all of it on a fit; up to the first miss otherwise; 0 when it gave up at once).
struct Fit {
    bool fits = false;
    double grow = 0;
    double demand = 0, filled = 0;
    double reached = 0;  // tight packer, on a fit: the share of the height its charts reach
};

// Places already rasterised masks in a side x height rectangle (the paper packer: a square).
Fit place(Packing &packing, PackMode mode, int side, int height, bool turns, int threads) {
    const ChartMasks &masks = packing.packed();
    std::vector<ChartPlacement> &placements = packing.placements;
    if (mode == PackMode::Tight) {
        const int b = packing.block, units = side / b, rows = height / b;  // in blocks
        const double square = double(units) * rows;
        const TightPacking t =
            packTight(masks, units, rows, turns, placements, packing.block > 1 ? &packing.bitmaps : nullptr, threads);
        for (ChartPlacement &p : placements)
            p.x *= b, p.y *= b;
        return {t.fits, 0, double(t.room) / square, double(t.placedRoom) / square, double(t.top) / rows};
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

Fit attempt(const AtlasCharts &charts, const PackOptions &o, double density, int padding, int side, int height,
            Packing &out, size_t &attempts) {
    ++attempts;
    if (!rasterize(charts, density, padding, side, o.threads, out))
        return {};  // a chart alone is wider than the texture
    return place(out, o.mode, side, height, o.allowRotation, o.threads);
}

// The largest density (within 0.5%, below `ceiling`) whose packing fits a side x height
// rectangle; `known` (> 0), a density already known to fit, with its packing in `best`.
//
// Each packing predicts the density that would just fit: the paper packer from its square, the
// tight one from the room its charts take, which grows about like density squared, and the
// share of the square it can fill (seen at the last miss or the best fit; 90% until known). The
// prediction is kept inside the bracket of the best fit and the lowest miss so far; bisection
// takes over when it falls outside.
// The share of the texture the tight packer's charts (boxes, row spans) are first aimed at when
// filling: it reaches 0.9 to 0.96 on voxel models' charts.
constexpr double kFillAim = 0.92;
// Better, from the first fit's packing: charts packed bottom-up to a share of the height reach
// about that share times (density ratio)^2 once denser (the gutters grow less), so the fill aims
// at this share of the height.
constexpr double kFillHeightAim = 0.97;
// A fill that would raise the density by less than this is skipped (it costs a packing).
constexpr double kLeastFillGain = 1.04;
// A larger model's first fill aim this close above its fallback (below) is not tried first.
constexpr double kCloseFillAims = 1.03;
// The share of the first texture shape a larger model's masks are first packed to fill by their
// room (packCharts), below what the tight packer fills of the rows it reaches on any larger model
// seen: 0.71 on the synthetic tank (large charts), 0.76 on the 185k sphere, 0.90 to 0.99 on the
// larger shared models.
constexpr double kFirstFillShare = 0.68;

// The factor on the density of `masks` (packed with the tight packer, fitting) at which the
// charts' room, estimated from the masks (each mask's core scaled, its padding and conservative
// rim kept), fills `efficiency` of a side x height rectangle: the packing's room per texel of
// the rows it reached, which a denser packing of the same charts matches or beats. At most
// `ceiling`.
double fillScale(const Packing &packing, int side, int height, double efficiency, double ceiling) {
    const ChartMasks &masks = packing.packed();
    const int b = packing.block;
    side /= b, height /= b;  // in mask units
    const double rim = (2.0 * masks.padding + b) / b;
    // Each chart's room now: its box when packed as one (small, no bitmap), else its bitmap's blocks or its rows' spans.
    std::vector<double> now(masks.charts.size());
    for (size_t c = 0; c < masks.charts.size(); ++c) {
        const ChartMask &m = masks.charts[c];
        now[c] = double(m.width) * m.height;
        if (packedAsBox(int64_t(m.width) * m.height, side, height, b > 1 && packing.bitmaps.has(c)))
            continue;
        now[c] = 0;
        if (b > 1 && packing.bitmaps.has(c)) {
            now[c] = double(packing.bitmaps.setBlocks[c]);
            continue;
        }
        const int16_t *l = m.rowLeft(masks.profiles), *r = m.rowRight(masks.profiles);
        for (int y = 0; y < m.height; ++y)
            now[c] += std::max(0, r[y] - l[y] + 1);
    }
    auto room = [&](double scale) {
        double total = 0;
        for (size_t c = 0; c < masks.charts.size(); ++c) {
            const double w = masks.charts[c].width, h = masks.charts[c].height;
            total += now[c] * (std::max(0.0, w - rim) * scale + rim) * (std::max(0.0, h - rim) * scale + rim) / (w * h);
        }
        return total;
    };
    const double target = efficiency * side * height;
    double lo = 1, hi = std::max(1.0, ceiling);
    if (room(hi) <= target)
        return hi;
    for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (room(mid) <= target ? lo : hi) = mid;
    }
    return lo;
}

// The charts' projected area (AtlasCharts::projectedArea) and longest side, degenerate charts
// left out: measured once per packCharts.
struct ChartExtent {
    double area = 0, longest = 0;
};
ChartExtent chartExtent(const AtlasCharts &charts) {
    ChartExtent e;
    e.area = charts.projectedArea();
    for (size_t c = 0; c < charts.chartCount(); ++c)
        if (!charts.isDegenerate(c))
            e.longest = std::max<double>({e.longest, charts.chartSize[c].x, charts.chartSize[c].y});
    return e;
}

// Just above the densest the charts could take in a side x height rectangle: their projected area
// cannot exceed it, nor a chart its side.
double densityBound(const ChartExtent &extent, int side, int height) {
    double bound = extent.area > 0 ? std::sqrt(double(side) * height / extent.area) : 1.0;
    if (extent.longest > 0)
        bound = std::min(bound, side / extent.longest);
    return bound * 1.0001;
}

bool densestFit(const AtlasCharts &charts, const ChartExtent &extent, const PackOptions &o, int padding, int side,
                int height, double ceiling, Packing &best, double &density, size_t &attempts, double known = 0,
                double knownFilled = 0, double knownReached = 0, double start = 0) {
    double miss = std::min(densityBound(extent, side, height), ceiling);
    const double floor = miss * 1e-4;  // below this only the fixed-size parts (gutters) remain
    double fit = known, d = miss * 0.85, reachable = 0.9, fitFilled = knownFilled, fallback = 0;
    if (known > 0) {
        // Aim from the known fit: the charts' room estimated at a higher density, filling as well as they did; should
        // that miss, the packed height grown like the density squared (below it, usually).
        fallback = knownReached > 0 ? known * std::sqrt(kFillHeightAim / knownReached) : 0;
        d = knownReached > 0  ? known * fillScale(best, side, height, knownFilled / knownReached, miss / known)
            : knownFilled > 0 ? known * std::sqrt(kFillAim / knownFilled)
                              : miss * 0.85;
        d = std::max(d, fallback);
        if (d < known * kLeastFillGain) {  // nearly full already: not worth a packing
            density = known;
            return true;
        }
        d = std::clamp(d, known * 1.001, miss / 1.001);
    } else if (start > 0 && o.mode == PackMode::Tight) {
        d = std::clamp(start, floor, miss / 1.001);
    }
    Packing trial;
    trial.block = best.block;
    trial.outlines = best.outlines;
    // Small models pack in a few milliseconds: their fill tries more and goes on after a fit.
    const bool cheap = known > 0 && charts.faceCount() <= size_t(std::max(0, o.cheapFillFaces));
    // A larger model's fill stops at its first fit: where the aim is within kCloseFillAims of the
    // fallback, the surer fallback goes first (the aim would gain little, and tried first it missed
    // on the larger shared models and the tank, costing a packing).
    if (known > 0 && !cheap && fallback >= known * kLeastFillGain && fallback < miss / 1.001 &&
        d < fallback * kCloseFillAims) {
        d = fallback;
        fallback = 0;
    }
    const int tries = known > 0 ? o.fillAttempts + (cheap ? o.cheapFillExtra : 0) : 16;
    int misses = 0;
    for (int i = 0; i < tries && d > floor; ++i) {
        if (known > 0 && miss <= fit * 1.005)
            break;
        const Fit f = attempt(charts, o, d, padding, side, height, trial, attempts);
        if (f.fits) {
            fit = d;
            fitFilled = f.filled;
            std::swap(best, trial);
        } else {
            miss = d;
            ++misses;
            if (f.filled > 0)
                reachable = f.filled;
        }
        if ((fit > 0 && miss <= fit * 1.005) || (known > 0 && f.fits && !cheap))
            break;  // bracketed; or filled: a fill tries again only after a miss
        reachable = std::max(reachable, fitFilled);
        double next = f.grow > 0 ? d * f.grow : f.demand > 0 ? d * std::sqrt(reachable / f.demand) : 0;
        next *= 0.998;                  // aim just below
        if (!f.fits && fallback > 0) {  // the fill's second try
            if (fallback < known * kLeastFillGain)
                break;
            next = fallback;
            fallback = 0;
        }
        if (known > 0 && misses >= 2)  // a miss's partial packing aims too low: halve the bracket
            next = std::sqrt(fit * miss);
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

// The rectangles tried for the charts at a density, smallest first: with wide textures allowed,
// s x s/2 before s x s (width the longer side).
void nextShape(bool wide, int &width, int &height) {
    if (wide && width == height)
        width *= 2;
    else if (wide)
        height *= 2;
    else
        width *= 2, height *= 2;
}

}  // namespace

AtlasLayout packCharts(const AtlasCharts &charts, const PackOptions &options) {
    AtlasLayout out;
    out.mode = options.mode;
    if (charts.faceCount() == 0)
        return out;
    const int maxSide = largestPowerOfTwoAtMost(std::clamp(options.maxTextureSize, 1, kMaxSide));
    out.gutter = std::max(2, options.gutter + (options.gutter & 1));
    const int padding = out.gutter / 2;

    std::optional<ChartExtent> measured;  // when first needed
    auto extentOf = [&]() -> const ChartExtent & {
        if (!measured)
            measured = chartExtent(charts);
        return *measured;
    };
    Packing packing;
    packing.block = options.mipBlocks && options.mode == PackMode::Tight ? 2 : 1;
    out.block = packing.block;
    ChartOutlineBasis outlines;  // the same for every density tried
    if (packing.block > 1) {
        outlines = chartOutlineBasis(charts, options.threads);
        packing.outlines = &outlines;
    }
    int height = 0;
    if (options.textureSize > 0) {
        out.size = std::min(options.textureSize, kMaxSide);
        height = options.textureHeight > 0 ? std::min(options.textureHeight, kMaxSide) : out.size;
        if (options.mode == PackMode::Paper)
            height = out.size;  // the paper's square
        if (!densestFit(charts, extentOf(), options, padding, out.size, height, INFINITY, packing, out.texelsPerUnit,
                        out.packAttempts, 0, 0, 0, options.startDensity))
            throw OptionError("the charts do not fit a " + std::to_string(out.size) + " x " + std::to_string(height) +
                              " texture at any density");
    } else {
        if (!(options.texelsPerUnit > 0) || !std::isfinite(options.texelsPerUnit))
            throw OptionError("texelsPerUnit must be positive and finite");
        out.texelsPerUnit = options.texelsPerUnit;
        const bool wide = options.allowWide && options.mode == PackMode::Tight;
        bool fits = false;
        double filled = 0, reached = 0;
        int firstSide = 0, firstHeight = 0;  // the first shape tried
        double firstMiss = INFINITY;         // a density known to miss it
        if (!rasterize(charts, out.texelsPerUnit, padding, maxSide, options.threads, packing)) {
            ++out.packAttempts;  // a chart alone is larger than the largest texture
        } else {
            const int b = packing.block;
            int longest = 1, longestShort = 1;
            for (const ChartMask &m : packing.packed().charts) {
                longest = std::max({longest, b * m.width, b * m.height});
                longestShort = std::max(longestShort, b * std::min(m.width, m.height));
            }
            // The smallest square whose area holds the masks, or half of it when wide.
            const double room = double(packing.packed().totalRowTexels) * b * b;
            int side = nextPowerOfTwo(std::max<double>(longest, std::sqrt(room)));
            height = side;
            if (wide && side > 1 && double(side) * side / 2 >= room && side / 2 >= longestShort)
                height = side / 2;
            // A larger model (costly packings) whose masks take little of the first shape is packed
            // first where their room fills kFirstFillShare of it: a fit there also holds the
            // charts at the asked density, and skips packing them at it. A miss bounds the fill.
            firstSide = side, firstHeight = height;
            if (options.fillTexture && options.mode == PackMode::Tight && side <= maxSide && side >= longest &&
                height >= longestShort && charts.faceCount() > size_t(std::max(0, options.cheapFillFaces))) {
                const double asked = out.texelsPerUnit;
                const double aim = asked * fillScale(packing, side, height, kFirstFillShare,
                                                     densityBound(extentOf(), side, height) / asked);
                if (aim >= asked * kLeastFillGain) {
                    Packing trial;
                    trial.block = packing.block;
                    trial.outlines = packing.outlines;
                    const Fit f = attempt(charts, options, aim, padding, side, height, trial, out.packAttempts);
                    if (f.fits) {
                        out.size = side;
                        out.texelsPerUnit = aim;
                        fits = true;
                        filled = f.filled;
                        reached = f.reached;
                        std::swap(packing, trial);
                    } else {
                        firstMiss = aim;
                    }
                }
            }
            for (out.size = side; !fits && out.size <= maxSide; nextShape(wide, out.size, height)) {
                if (out.size >= longest && height >= longestShort) {
                    ++out.packAttempts;
                    const Fit f =
                        place(packing, options.mode, out.size, height, options.allowRotation, options.threads);
                    if (f.fits) {
                        fits = true;
                        filled = f.filled;
                        reached = f.reached;
                        break;
                    }
                }
            }
        }
        if (fits && options.fillTexture && options.mode == PackMode::Tight) {
            // The density is a minimum: raise it to fill the texture chosen.
            double density = out.texelsPerUnit;
            const double ceiling = out.size == firstSide && height == firstHeight ? firstMiss : INFINITY;
            if (densestFit(charts, extentOf(), options, padding, out.size, height, ceiling, packing, density,
                           out.packAttempts, out.texelsPerUnit, filled, reached))
                out.texelsPerUnit = density;
            // Small textures whose charts' rims leave the charts too little of them: the larger
            // sizes up to smallTexels, each at the density that fills it, the best share kept
            // (a long chart can cap the density of one shape and not of the next).
            const double area = extentOf().area;
            auto share = [&](double d, int w, int h) { return area * d * d / (double(w) * h); };
            double best = share(out.texelsPerUnit, out.size, height);
            for (int width = out.size, taller = height; best < options.leastChartShare;) {
                nextShape(wide, width, taller);
                if (width > maxSide || int64_t(width) * taller > options.smallTexels)
                    break;
                Packing larger;
                larger.block = packing.block;
                larger.outlines = packing.outlines;
                double denser = 0;
                if (densestFit(charts, extentOf(), options, padding, width, taller, INFINITY, larger, denser,
                               out.packAttempts) &&
                    share(denser, width, taller) > best) {
                    best = share(denser, width, taller);
                    out.size = width, height = taller, out.texelsPerUnit = denser;
                    packing = std::move(larger);
                }
            }
        }
        if (!fits) {
            out.size = height = maxSide;
            out.densityReduced = true;
            if (!densestFit(charts, extentOf(), options, padding, out.size, height, options.texelsPerUnit, packing,
                            out.texelsPerUnit, out.packAttempts, 0, 0, 0, options.startDensity))
                throw OptionError("the charts do not fit a " + std::to_string(out.size) + " texture at any density");
            out.note = "texels per unit lowered from " + std::to_string(options.texelsPerUnit) + " to " +
                       std::to_string(out.texelsPerUnit) + " to fit " + std::to_string(out.size) + " x " +
                       std::to_string(out.size);
        }
    }
    out.width = out.size;
    out.height = height;

    // Final UVs: chart texels -> turned mask -> texture, over the side. A sliver thinner than
    // float precision can come out flat or flipped; it gets a tiny right triangle (1/64 texel) at
    // its first corner so every face keeps a positive UV area. Each face's UVs depend on its
    // chart alone: runs of charts (atlas/chart_runs.h) on up to `threads` threads.
    out.placements = packing.placements;
    out.wedgeUv.resize(charts.wedgeUv.size());
    const glm::dvec2 extent(out.width, out.height);
    const ChartRuns runs = chartRuns(charts, options.threads);
    const int workers = runs.workers;
    const size_t bands = runs.count();
    const std::vector<size_t> &from = runs.from;
    std::vector<size_t> nudged(bands, 0);
    // Texel positions to UVs: a division, or for powers of two (always, but for a size given
    // otherwise) the product with the exact reciprocal, the same bits without the divisions.
    auto place = [&](size_t band, auto toUv) {
        for (size_t c = from[band]; c < from[band + 1]; ++c) {
            const ChartMask &m = packing.packed().charts[c];
            const int b = packing.block;  // the packed mask's size in texels: even with blocks
            const int maskWidth = b * m.width, maskHeight = b * m.height;
            const ChartPlacement &p = packing.placements[c];
            for (uint32_t i = charts.chartFirstFace[c]; i < charts.chartFirstFace[c + 1]; ++i) {
                const uint32_t f = charts.chartFaces[i];
                glm::vec2 *uv = &out.wedgeUv[3 * size_t(f)];
                for (int k = 0; k < 3; ++k) {
                    const glm::dvec2 q = glm::dvec2(charts.wedgeUv[3 * size_t(i) + k]) * m.scale + m.offset;
                    uv[k] =
                        glm::vec2(toUv(turnInMask(q, maskWidth, maskHeight, p.quarterTurns) + glm::dvec2(p.x, p.y)));
                }
                if (doubleArea(glm::dvec2(uv[0]) * extent, glm::dvec2(uv[1]) * extent, glm::dvec2(uv[2]) * extent) > 0)
                    continue;
                uv[1] = uv[0] + glm::vec2(float(1.0 / 64 / extent.x), 0);
                uv[2] = uv[0] + glm::vec2(0, float(1.0 / 64 / extent.y));
                ++nudged[band];
            }
        }
    };
    const bool powersOfTwo = (out.width & (out.width - 1)) == 0 && (out.height & (out.height - 1)) == 0;
    const glm::dvec2 perTexel = 1.0 / extent;
    runBands(bands, workers, [&](size_t band) {
        if (powersOfTwo)
            place(band, [&](glm::dvec2 t) { return t * perTexel; });
        else
            place(band, [&](glm::dvec2 t) { return t / extent; });
    });
    for (size_t n : nudged)
        out.nudgedFaces += n;
    return out;
}

}  // namespace voxelfair
