// Ring-by-ring growth of painted texels into unpainted ones (the gutter of paper section 4.5's
// baked texture, done here for other maps): each ring visits only the unpainted 8-neighbours of
// the previous ring, so the cost follows the charts' outlines, not the image area.
//
//   state[y * width + x] & kTexelPainted   marks painted texels (other bits are the caller's,
//                                          kTexelQueued excepted);
//   fill(x, y) -> bool                     paints texel (x, y) from its painted neighbours (read
//                                          them through the caller's buffers and kTexelPainted);
//                                          false leaves it unpainted. It writes texel (x, y) only.
// Texels painted in one ring are marked only after the whole ring, so every texel of a ring
// reads the previous rings alone, whatever the visiting order. Rows are split into bands run on
// `threads` threads (parallel_bands.h); each band touches the state of its own rows alone while
// others run, so the result does not depend on the thread count.
#pragma once

#include "maps/parallel_bands.h"

#include <cstdint>
#include <vector>

namespace voxelfair {

constexpr uint8_t kTexelPainted = 1, kTexelQueued = 0x80;

template <class Fill>
void dilateTexels(int width, int height, std::vector<uint8_t> &state, int rings, int threads, Fill &&fill) {
    constexpr int kBandRows = 64;
    const size_t bands = size_t((height + kBandRows - 1) / kBandRows);
    const size_t w = size_t(width);
    // Painted texels with an unpainted 8-neighbour, per band.
    std::vector<std::vector<uint32_t>> frontier(bands), next(bands);
    runBands(bands, threads, [&](size_t b) {
        const int y0 = int(b) * kBandRows, y1 = std::min(height, y0 + kBandRows);
        // Per row: column x is "full" when the 3 texels (x, y - 1..y + 1) inside the image are all
        // painted; a painted texel is on the frontier unless its 3 columns are full. Branch-free
        // byte loops (the compiler vectorises them).
        std::vector<uint8_t> full(w + 2, 1);
        for (int y = y0; y < y1; ++y) {
            const uint8_t *row = &state[size_t(y) * w];
            const uint8_t *below = y > 0 ? row - w : row, *above = y + 1 < height ? row + w : row;
            for (size_t x = 0; x < w; ++x)
                full[x + 1] = uint8_t(below[x] & row[x] & above[x] & kTexelPainted);
            for (size_t x = 0; x < w; ++x)
                if ((row[x] & kTexelPainted) && !(full[x] & full[x + 1] & full[x + 2]))
                    frontier[b].push_back(uint32_t(size_t(y) * w + x));
        }
    });
    for (int ring = 0; ring < rings; ++ring) {
        // The unpainted neighbours of the frontier in each band's own rows (a band's rows are next
        // to the frontiers of the bands before and after it only).
        runBands(bands, threads, [&](size_t b) {
            const int y0 = int(b) * kBandRows, y1 = std::min(height, y0 + kBandRows);
            next[b].clear();
            for (size_t source = b > 0 ? b - 1 : 0; source <= b + 1 && source < bands; ++source)
                for (uint32_t t : frontier[source]) {
                    const int x = int(t % uint32_t(width)), y = int(t / uint32_t(width));
                    for (int ny = std::max(y - 1, y0); ny <= std::min(y + 1, y1 - 1); ++ny)
                        for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width - 1); ++nx) {
                            uint8_t &s = state[size_t(ny) * w + size_t(nx)];
                            if (s & (kTexelPainted | kTexelQueued))
                                continue;
                            s |= kTexelQueued;
                            next[b].push_back(uint32_t(size_t(ny) * w + size_t(nx)));
                        }
                }
        });
        bool any = false;
        for (const auto &n : next)
            any = any || !n.empty();
        if (!any)
            break;
        // Fill: reads painted neighbours (not written this ring), writes its own texels.
        std::vector<std::vector<uint8_t>> filled(bands);
        runBands(bands, threads, [&](size_t b) {
            filled[b].resize(next[b].size());
            for (size_t i = 0; i < next[b].size(); ++i)
                filled[b][i] = fill(int(next[b][i] % uint32_t(width)), int(next[b][i] / uint32_t(width))) ? 1 : 0;
        });
        // Mark, and the filled texels are the next frontier.
        runBands(bands, threads, [&](size_t b) {
            frontier[b].clear();
            for (size_t i = 0; i < next[b].size(); ++i) {
                uint8_t &s = state[next[b][i]];
                s = uint8_t(s & ~kTexelQueued);
                if (filled[b][i]) {
                    s |= kTexelPainted;
                    frontier[b].push_back(next[b][i]);
                }
            }
        });
    }
}

}  // namespace voxelfair
