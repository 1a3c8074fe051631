// The gutter of a baked normal map; the contract is in normal_gutter.h.
#include "maps/normal_gutter.h"

#include "base/parallel_bands.h"
#include "maps/texel_dilation.h"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace voxelfair {

namespace {

inline uint8_t encodeFast(float c) { return uint8_t(std::clamp(int(c * 127.5f + 128.0f), 0, 255)); }

constexpr int kBlockBandRows = 32;  // even: bands hold whole blocks

constexpr int kMaxBlockSide = 8;  // a map up to 4 times the atlas' side (normal_bake.h)

// The block of rows x columns texels at (x, y): its unpainted texels take the renormalised mean
// of its painted ones. Rows, Columns > 0: the block's size known when compiled (unrolled).
template <int Rows, int Columns>
void fillBlockOf(int x, int y, int rows, int columns, int width, int height, uint8_t *state, uint8_t *image) {
    if (Rows > 0)
        rows = Rows, columns = Columns;
    int sum[3] = {0, 0, 0}, n = 0;
    for (int dy = 0; dy < rows; ++dy) {
        const uint8_t *const states = &state[size_t(y + dy) * size_t(width) + size_t(x)];
        const uint8_t *const colours = &image[(size_t(height - 1 - y - dy) * size_t(width) + size_t(x)) * 4];
        for (int dx = 0; dx < columns; ++dx) {
            const int m = states[dx] & kTexelPainted;  // 0 or 1: branch-free sums
            for (int c = 0; c < 3; ++c)
                sum[c] += m * (2 * colours[4 * dx + c] - 255);
            n += m;
        }
    }
    if (n == 0 || n == rows * columns)
        return;
    const glm::vec3 mean{float(sum[0]), float(sum[1]), float(sum[2])};
    const float length = glm::length(mean);
    if (!(length > 0.0f))
        return;
    const glm::vec3 c = mean / length;
    const uint8_t r = encodeFast(c.x), g = encodeFast(c.y), b = encodeFast(c.z);
    for (int dy = 0; dy < rows; ++dy) {
        uint8_t *const states = &state[size_t(y + dy) * size_t(width) + size_t(x)];
        uint8_t *const colours = &image[(size_t(height - 1 - y - dy) * size_t(width) + size_t(x)) * 4];
        for (int dx = 0; dx < columns; ++dx)
            if (!(states[dx] & kTexelPainted)) {
                colours[4 * dx] = r, colours[4 * dx + 1] = g, colours[4 * dx + 2] = b;
                states[dx] |= kTexelPainted;
            }
    }
}

// The side x side block at (x, y), cut by the image's edges; Side > 0: side is Side, and a block
// inside the image is done unrolled (2: the common block).
template <int Side>
void fillBlock(int x, int y, int side, int width, int height, uint8_t *state, uint8_t *image) {
    if (Side > 0 && x + Side <= width && y + Side <= height)
        fillBlockOf<Side, Side>(x, y, Side, Side, width, height, state, image);
    else
        fillBlockOf<0, 0>(x, y, std::min(side, height - y), std::min(side, width - x), width, height, state, image);
}

}  // namespace

void fillNormalGutter(int width, int height, uint8_t *state, uint8_t *rgba, int rings, int blockSide, int threads) {
    const uint8_t *const painted = state;
    uint8_t *const image = rgba;
    dilateTexels(width, height, state, rings, threads, [painted, image, width, height](int x, int y) {
        // The sums of the decoded neighbours, (2 c - 255) / 255 each, up to its scale: integers,
        // summed as bytes in the lanes of two words (red and blue in 16-bit halves of one, green
        // in the other: 9 x 255 fit), a neighbour masked out when unpainted (branch-free).
        uint32_t redBlue = 0, green = 0;
        int n = 0;
        auto add = [&](const uint8_t *row, const uint8_t *colours, int nx) {
            const uint32_t m = row[nx] & kTexelPainted;  // 0 or 1
            uint32_t rgba;
            std::memcpy(&rgba, colours + size_t(nx) * 4, 4);  // bytes r, g, b, a from the lowest
            rgba &= 0u - m;
            redBlue += rgba & 0x00FF00FFu, green += rgba & 0x0000FF00u, n += int(m);
        };
        const size_t w = size_t(width);
        if (x > 0 && y > 0 && x + 1 < width && y + 1 < height) {
            // Inside the image (most ring texels): 3 x 3 neighbours, unrolled.
            for (int dy = -1; dy <= 1; ++dy) {
                const uint8_t *const row = painted + size_t(y + dy) * w + size_t(x - 1);
                const uint8_t *const colours = image + (size_t(height - 1 - y - dy) * w + size_t(x - 1)) * 4;
                add(row, colours, 0), add(row, colours, 1), add(row, colours, 2);
            }
        } else {
            for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, height - 1); ++ny)
                for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width - 1); ++nx)
                    add(painted + size_t(ny) * w, image + size_t(height - 1 - ny) * w * 4, nx);
        }
        const int sx = int(redBlue & 0xFFFFu), sy = int(green >> 8), sz = int(redBlue >> 16);
        const glm::vec3 sum(float(2 * sx - 255 * n), float(2 * sy - 255 * n), float(2 * sz - 255 * n));
        const float length = glm::length(sum);
        if (!(length > 0.0f))
            return false;
        const glm::vec3 c = sum / length;
        uint8_t *p = image + (size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4;
        p[0] = encodeFast(c.x), p[1] = encodeFast(c.y), p[2] = encodeFast(c.z);
        return true;
    });
    if (blockSide <= 0)
        return;
    blockSide = std::min(blockSide, kMaxBlockSide);
    if (blockSide != 2) {
        // A finer map (2f x 2f blocks, few texels): block by block.
        const size_t side = size_t(blockSide), bands = (size_t(height) + side - 1) / side;
        runBands(bands, threads, [&](size_t band) {
            for (int x = 0; x < width; x += blockSide)
                fillBlock<0>(x, int(band * side), blockSide, width, height, state, image);
        });
        return;
    }
    // Every aligned 2 x 2 block with a painted texel belongs to one chart (the atlas' packing).
    // Most blocks are all painted or all empty: 4 blocks (8 texels of 2 rows) are tested at once
    // and skipped when so.
    const size_t bands = size_t((height + kBlockBandRows - 1) / kBlockBandRows);
    runBands(bands, threads, [&](size_t band) {
        const int r0 = int(band) * kBlockBandRows, r1 = std::min(height, r0 + kBlockBandRows);
        constexpr uint64_t kAll = kAllBytesOne * kTexelPainted;
        for (int y = r0; y < r1; y += 2) {
            const uint8_t *const row0 = &state[size_t(y) * size_t(width)];
            const uint8_t *const row1 = y + 1 < height ? row0 + width : nullptr;
            int x = 0;
            for (; row1 && x + 8 <= width; x += 8) {
                uint64_t a = 0, b = 0;
                std::memcpy(&a, row0 + x, 8);
                std::memcpy(&b, row1 + x, 8);
                a &= kAll, b &= kAll;
                if ((a | b) == 0 || (a & b) == kAll)
                    continue;
                for (int k = x; k < x + 8; k += 2)
                    fillBlock<2>(k, y, 2, width, height, state, image);
            }
            for (; x < width; x += 2)
                fillBlock<2>(x, y, 2, width, height, state, image);
        }
    });
}

}  // namespace voxelfair
