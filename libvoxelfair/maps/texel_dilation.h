// Ring-by-ring growth of painted texels into unpainted ones (the gutter of paper section 4.5's
// baked texture, done here for other maps): each ring visits only the unpainted 8-neighbours of
// the previous ring, so the cost follows the charts' outlines, not the image area.
//
//   fill(x, y) -> bool  paints texel (x, y) from its painted neighbours (read them through the
//                       caller's buffers and `painted`); false leaves it unpainted.
// Texels painted in one ring are marked only after the whole ring, so every texel of a ring
// reads the previous rings alone, whatever the visiting order.
#pragma once

#include <cstdint>
#include <vector>

namespace voxelfair {

// `seeds` lists every painted texel (index y * size + x), or at least every one with an unpainted
// neighbour; only they are looked at to start.
template <class Fill>
void dilateTexels(int size, std::vector<uint8_t> &painted, const std::vector<uint32_t> &seeds, int rings, Fill &&fill) {
    std::vector<uint32_t> frontier, next;
    for (uint32_t seed : seeds) {
        {
            const int x = int(seed % uint32_t(size)), y = int(seed / uint32_t(size));
            bool edge = false;
            for (int dy = -1; dy <= 1 && !edge; ++dy)
                for (int dx = -1; dx <= 1 && !edge; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    edge = nx >= 0 && ny >= 0 && nx < size && ny < size &&
                           !painted[size_t(ny) * size_t(size) + size_t(nx)];
                }
            if (edge)
                frontier.push_back(seed);
        }
    }
    for (int ring = 0; ring < rings && !frontier.empty(); ++ring) {
        next.clear();
        for (uint32_t t : frontier) {
            const int x = int(t % uint32_t(size)), y = int(t / uint32_t(size));
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= size || ny >= size)
                        continue;
                    const size_t n = size_t(ny) * size_t(size) + size_t(nx);
                    if (painted[n])
                        continue;
                    painted[n] = 2;  // queued this ring
                    next.push_back(uint32_t(n));
                }
        }
        for (uint32_t n : next)
            painted[n] = 0;  // neighbours of this ring must not read it yet
        size_t kept = 0;
        for (uint32_t n : next)
            if (fill(int(n % uint32_t(size)), int(n / uint32_t(size))))
                next[kept++] = n;
        next.resize(kept);
        for (uint32_t n : next)
            painted[n] = 1;
        frontier.swap(next);
    }
}

}  // namespace voxelfair
