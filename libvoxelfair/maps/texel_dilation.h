// Ring-by-ring growth of painted texels into unpainted ones (the gutter of paper section 4.5's
// baked texture, done here for other maps): each ring is the unpainted texels with a painted
// 8-neighbour, found by a vectorised scan of the state rows (a few ms for a 4096 x 2048 map), then
// filled one by one.
//
//   state[y * width + x] & kTexelPainted   marks painted texels (other bits are the caller's);
//   fill(x, y) -> bool                     paints texel (x, y) from its painted neighbours (read
//                                          them through the caller's buffers and kTexelPainted);
//                                          false leaves it unpainted. It writes texel (x, y) only.
// Texels painted in one ring are marked only after the whole ring, so every texel of a ring
// reads the previous rings alone, whatever the visiting order. Rows are split into bands run on
// `threads` threads (base/parallel_bands.h); each band touches the state of its own rows alone while
// others run, so the result does not depend on the thread count.
#pragma once

#include "base/byte_words.h"
#include "base/parallel_bands.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace voxelfair {

constexpr uint8_t kTexelPainted = 1;

template <class Fill>
void dilateTexels(int width, int height, uint8_t *state, int rings, int threads, Fill &&fill) {
    constexpr int kBandRows = 64;
    const size_t bands = size_t((height + kBandRows - 1) / kBandRows);
    const size_t w = size_t(width);
    std::vector<std::vector<uint32_t>> ring(bands);  // per band: the ring's texels, y << 16 | x (sides <= 65536)
    std::vector<std::vector<uint8_t>> filled(bands);
    for (int r = 0; r < rings; ++r) {
        // The ring: unpainted texels with a painted 8-neighbour, found row by row with branch-free
        // byte loops the compiler vectorises (column x "touches" when one of the 3 texels
        // (x, y - 1..y + 1) inside the image is painted).
        runBands(bands, threads, [&](size_t b) {
            const int y0 = int(b) * kBandRows, y1 = std::min(height, y0 + kBandRows);
            std::vector<uint8_t> touch(w + 2, 0), candidate(w);
            ring[b].clear();
            uint8_t *__restrict const touched = touch.data(), *__restrict const candidates = candidate.data();
            const size_t n = w;  // a local: the byte stores may not alias the captured one
            for (int y = y0; y < y1; ++y) {
                const uint8_t *__restrict const row = &state[size_t(y) * w];
                const uint8_t *__restrict const below = y > 0 ? row - w : row;
                const uint8_t *__restrict const above = y + 1 < height ? row + w : row;
                for (size_t x = 0; x < n; ++x)
                    touched[x + 1] = uint8_t((below[x] | row[x] | above[x]) & kTexelPainted);
                for (size_t x = 0; x < n; ++x)
                    candidates[x] = uint8_t((touched[x] | touched[x + 1] | touched[x + 2]) & ~row[x] & kTexelPainted);
                // 8 candidates (bytes 0 or 1) at a time, the set ones in order (their lowest bit
                // first: byte i of the little-endian word is texel x + i).
                size_t x = 0;
                for (; x + 8 <= w; x += 8) {
                    uint64_t eight;
                    std::memcpy(&eight, &candidate[x], 8);
                    for (; eight != 0; eight &= eight - 1)
                        ring[b].push_back(uint32_t(y) << 16 | uint32_t(x + size_t(lowestSetBit(eight) / 8)));
                }
                for (; x < w; ++x)
                    if (candidate[x])
                        ring[b].push_back(uint32_t(y) << 16 | uint32_t(x));
            }
        });
        bool any = false;
        for (const auto &texels : ring)
            any = any || !texels.empty();
        if (!any)
            break;
        // Fill: reads painted neighbours (none painted this ring), writes its own texels.
        runBands(bands, threads, [&](size_t b) {
            filled[b].resize(ring[b].size());
            for (size_t i = 0; i < ring[b].size(); ++i)
                filled[b][i] = fill(int(ring[b][i] & 0xFFFFu), int(ring[b][i] >> 16)) ? 1 : 0;
        });
        // Mark.
        runBands(bands, threads, [&](size_t b) {
            for (size_t i = 0; i < ring[b].size(); ++i)
                if (filled[b][i])
                    state[size_t(ring[b][i] >> 16) * w + (ring[b][i] & 0xFFFFu)] |= kTexelPainted;
        });
    }
}

}  // namespace voxelfair
