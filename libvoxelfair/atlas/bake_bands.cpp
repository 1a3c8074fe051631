#include "atlas/bake_bands.h"

#include "atlas/texel_raster.h"
#include "base/parallel_bands.h"

#include <algorithm>

namespace voxelfair {

BakeBands bakeBands(const std::vector<glm::vec2> &wedgeUv, int height, size_t bands, int workers) {
    BakeBands out;
    out.faceCount = wedgeUv.size() / 3;
    bands = std::clamp<size_t>(bands, 1, size_t(std::max(height, 1)));
    out.start.assign(bands + 1, 0);
    out.start[bands] = height;
    if (bands == 1)
        return out;
    const size_t faceCount = out.faceCount, shares = size_t(std::max(workers, 1));
    out.shares = shares;
    const double h = height;
    auto rangeOf = [&](size_t f, double &minY, double &maxY) {  // in texels, as the bake loads them
        const glm::vec2 *uv = &wedgeUv[3 * f];
        const double y0 = double(uv[0].y) * h, y1 = double(uv[1].y) * h, y2 = double(uv[2].y) * h;
        minY = min3(y0, y1, y2), maxY = max3(y0, y1, y2);
    };
    auto facesOfShare = [&](size_t share, size_t &from, size_t &to) {
        from = faceCount * share / shares, to = faceCount * (share + 1) / shares;
    };

    // Faces by the lowest row they reach (clamped onto the texture), counted per share.
    std::vector<std::vector<uint32_t>> lowest(shares);
    runBands(shares, workers, [&](size_t share) {
        std::vector<uint32_t> &count = lowest[share];
        count.assign(size_t(height), 0);
        size_t from, to;
        facesOfShare(share, from, to);
        for (size_t f = from; f < to; ++f) {
            double minY, maxY;
            rangeOf(f, minY, maxY);
            ++count[minY >= 0 ? (minY < h ? size_t(minY) : size_t(height) - 1) : 0];
        }
    });
    // Band b starts at the first row with faces * b / bands faces below it, at least a row above
    // the band before and leaving a row to each band after.
    std::vector<size_t> below(size_t(height) + 1, 0);  // faces whose lowest row is under row y
    for (size_t y = 0; y < size_t(height); ++y) {
        below[y + 1] = below[y];
        for (const std::vector<uint32_t> &count : lowest)
            below[y + 1] += count[y];
    }
    for (size_t band = 1; band < bands; ++band) {
        const int cut = int(std::lower_bound(below.begin(), below.end(), faceCount * band / bands) - below.begin());
        out.start[band] = std::clamp(cut, out.start[band - 1] + 1, height - int(bands - band));
    }

    // Each share's faces into the bands they reach.
    out.faces.resize(shares * bands);
    runBands(shares, workers, [&](size_t share) {
        size_t from, to;
        facesOfShare(share, from, to);
        for (size_t band = 0; band < bands; ++band)
            out.faces[share * bands + band].reserve((to - from) / bands * 5 / 4 + 16);
        for (size_t f = from; f < to; ++f) {
            double minY, maxY;
            rangeOf(f, minY, maxY);
            for (size_t band = 0; band < bands; ++band) {
                const int rowFrom = out.rowFrom(band), rowTo = out.rowTo(band);
                if (!(rowFrom > 0 && maxY < rowFrom - 1.0) && !(rowTo < height - 1 && minY > rowTo + 2.0))
                    out.faces[share * bands + band].push_back(uint32_t(f));
            }
        }
    });
    return out;
}

}  // namespace voxelfair
