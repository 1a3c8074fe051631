#include "atlas/bake.h"

#include "atlas/bake_bands.h"

#include "atlas/chart_runs.h"
#include "atlas/texel_raster.h"
#include "base/byte_words.h"
#include "base/parallel_bands.h"
#include "base/short_fill.h"
#include "base/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include <glm/common.hpp>

namespace voxelfair {

const char *toString(BakeSource source) {
    switch (source) {
    case BakeSource::FaceColours: return "face colours";
    case BakeSource::VertexColours: return "vertex colours";
    case BakeSource::FlatColour: return "flat colour";
    }
    return "unknown";
}

namespace {

// Slightly strict coverage (see kMaskMargin in chart_masks.cpp): the bake never paints outside
// the packed masks.
constexpr double kBakeMargin = -1.0 / 256;

// The image being baked: RGBA rows from the top, as AtlasTexture::rgba, and per texel whether
// it is painted (a face's texel or a dilation ring's).
//
// Its memory is not written when made: clear() sets layout rows rowFrom..rowTo to the background,
// unpainted, so that each band of the bake clears its own rows on the thread that paints them
// (the pages' first touch there, once, in parallel: 20 MB for the tank at 8 texels per voxel).
// Every row must be cleared before anything reads it.
struct Canvas {
    int width, height;
    glm::u8vec4 background;
    ByteBuffer &rgba;
    ByteBuffer filled;
    Canvas(int width, int height, glm::u8vec4 background, ByteBuffer &rgba)
        : width(width), height(height), background(background), rgba(rgba) {
        const size_t texels = size_t(width) * size_t(height);
        rgba.resize(4 * texels);  // written by clear()
        filled.resize(texels);
    }
    void clear(int rowFrom, int rowTo) {
        const size_t from = index(0, rowTo), to = index(0, rowFrom) + size_t(width);
        std::memset(filled.data() + from, 0, to - from);
        if (background == glm::u8vec4(0)) {
            std::memset(rgba.data() + 4 * from, 0, 4 * (to - from));
        } else {
            for (size_t i = from; i < to; ++i)
                std::memcpy(&rgba[4 * i], &background, 4);
        }
    }
    // Layout texel (x, y), y up.
    size_t index(int x, int y) const { return size_t(height - 1 - y) * size_t(width) + size_t(x); }
    void paint(size_t i, glm::u8vec3 c) {
        const uint8_t texel[4] = {c.r, c.g, c.b, 255};
        std::memcpy(&rgba[4 * i], texel, 4);
        filled[i] = 1;
    }
};

BakeSource chooseSource(const AtlasMesh &mesh, BakeSource wanted, std::string &note) {
    const bool face = mesh.faceColours != nullptr, vertex = mesh.vertexColours != nullptr;
    if ((wanted == BakeSource::FaceColours && face) || (wanted == BakeSource::VertexColours && vertex) ||
        wanted == BakeSource::FlatColour)
        return wanted;
    if (wanted == BakeSource::FaceColours && vertex) {
        note = "no face colours: baked the vertex colours instead";
        return BakeSource::VertexColours;
    }
    if (wanted == BakeSource::VertexColours && face) {
        note = "no vertex colours: baked the face colours instead";
        return BakeSource::FaceColours;
    }
    note = "the mesh has no colours: baked a flat colour";
    return BakeSource::FlatColour;
}

// Fills `rings` rings of empty texels around the painted ones, each with the mean of its
// already painted 8-neighbours; charts grow into the gutter from both sides at the same pace.
// The first ring is the empty texels with a filled 8-neighbour, found a row at a time (the rows
// above, at and below or-ed, then each texel's left and right); each later ring, the empty
// neighbours of the ring before.
void dilate(Canvas &canvas, int rings, int threads) {
    const int width = canvas.width, height = canvas.height;
    ByteBuffer &filled = canvas.filled;  // 1 filled, 2 in the ring being found
    std::vector<uint32_t> frontier, next;
    if (rings <= 0)
        return;
    // The first ring in bands of rows (on up to `threads` threads), joined in row order.
    const size_t bands = threads > 1 ? size_t(std::min(height, 4 * threads)) : 1;
    std::vector<std::vector<uint32_t>> found(bands);
    // Eight texels at a time (0/1 bytes in a little-endian word): a texel is near when its
    // column (the rows above, at and below or-ed) or a neighbouring column is filled and it is
    // not; the neighbouring columns are the word shifted by a byte, with the adjacent words'
    // end bytes carried in. Rows are padded with empty columns to whole words.
    const size_t words = (size_t(width) + 7) / 8;
    runBands(bands, threads, [&](size_t band) {
        std::vector<uint64_t> column(words + 2, 0), mids(words, 0);
        const int from = int(size_t(height) * band / bands), to = int(size_t(height) * (band + 1) / bands);
        const size_t whole = size_t(width) / 8;  // words without padding
        auto load = [&](const uint8_t *p, size_t w) {
            uint64_t v = 0;
            if (w < whole)
                std::memcpy(&v, p + 8 * w, 8);
            else
                std::memcpy(&v, p + 8 * w, size_t(width) % 8);
            return v;
        };
        for (int row = from; row < to; ++row) {
            const uint8_t *mid = &filled[size_t(row) * size_t(width)];
            const uint8_t *up = row > 0 ? mid - width : mid, *down = row + 1 < height ? mid + width : mid;
            for (size_t w = 0; w < words; ++w) {
                mids[w] = load(mid, w);
                column[w + 1] = load(up, w) | mids[w] | load(down, w);
            }
            for (size_t w = 0; w < words; ++w) {
                const uint64_t c = column[w + 1];
                uint64_t word = (c | c << 8 | column[w] >> 56 | c >> 8 | column[w + 2] << 56) & ~mids[w];
                if (8 * w + 8 > size_t(width))  // the padding columns are never near
                    word &= ~uint64_t(0) >> (8 * (8 * w + 8 - size_t(width)));
                for (int k = 0; word != 0; ++k, word >>= 8)
                    if (word & 0xFF)
                        found[band].push_back(uint32_t(size_t(row) * size_t(width) + 8 * w + size_t(k)));
            }
        }
    });
    for (const std::vector<uint32_t> &f : found)
        frontier.insert(frontier.end(), f.begin(), f.end());
    for (int ring = 0; ring < rings && !frontier.empty(); ++ring) {
        // Each ring texel's colour from its painted neighbours, written at once: the ring's texels
        // are not painted yet (filled 0 or 2), so no other ring texel reads them; then all marked
        // painted.
        const size_t chunks = threads > 1 && frontier.size() >= 4096 ? size_t(4 * threads) : 1;
        runBands(chunks, threads, [&](size_t chunk) {
            for (size_t k = frontier.size() * chunk / chunks; k < frontier.size() * (chunk + 1) / chunks; ++k) {
                const int row = int(frontier[k] / uint32_t(width)), x = int(frontier[k] % uint32_t(width));
                unsigned sum[3] = {0, 0, 0}, count = 0;
                if (row > 0 && row + 1 < height && x > 0 && x + 1 < width) {
                    // Inside the image: the nine texels without bounds, each added times whether
                    // it is painted (no branch to mispredict; the same sums).
                    for (int dy = -1; dy <= 1; ++dy) {
                        const size_t j = size_t(row + dy) * size_t(width) + size_t(x - 1);
                        const uint8_t *f = &filled[j], *c = &canvas.rgba[4 * j];
                        for (int dx = 0; dx < 3; ++dx) {
                            const unsigned painted = f[dx] == 1;
                            for (int ch = 0; ch < 3; ++ch)
                                sum[ch] += painted * c[4 * dx + ch];
                            count += painted;
                        }
                    }
                } else {
                    for (int ny = std::max(0, row - 1); ny <= std::min(height - 1, row + 1); ++ny)
                        for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx) {
                            const size_t j = size_t(ny) * size_t(width) + size_t(nx);
                            if (filled[j] == 1) {
                                for (int ch = 0; ch < 3; ++ch)
                                    sum[ch] += canvas.rgba[4 * j + size_t(ch)];
                                ++count;
                            }
                        }
                }
                uint8_t *texel = &canvas.rgba[4 * size_t(frontier[k])];
                for (int ch = 0; ch < 3; ++ch)
                    texel[ch] = uint8_t((sum[ch] + count / 2) / count);
                texel[3] = 255;
            }
        });
        for (const uint32_t i : frontier)
            filled[i] = 1;
        next.clear();
        if (ring + 1 < rings)
            for (uint32_t i : frontier) {
                const int row = int(i / uint32_t(width)), x = int(i % uint32_t(width));
                for (int ny = std::max(0, row - 1); ny <= std::min(height - 1, row + 1); ++ny)
                    for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx) {
                        const size_t j = size_t(ny) * size_t(width) + size_t(nx);
                        if (filled[j] == 0) {
                            filled[j] = 2;
                            next.push_back(uint32_t(j));
                        }
                    }
            }
        frontier.swap(next);
    }
}

// Layouts on 2 x 2 blocks (AtlasLayout::block): each aligned block with a painted texel belongs
// to one chart (its texels, or its first ring, which lies inside its packed mask), so its empty
// texels take the mean of its painted ones; a box-filtered mip level 1 then never mixes charts.
// Here the blocks of rows y and y + 1.
void fillBlockRow(Canvas &canvas, int y) {
    for (int x = 0; x < canvas.width; x += 2) {
        if (x % 8 == 0 && x + 8 <= canvas.width && y + 1 < canvas.height) {  // four blocks at once, as below
            uint64_t low = 0, high = 0;
            std::memcpy(&low, &canvas.filled[canvas.index(x, y)], 8);
            std::memcpy(&high, &canvas.filled[canvas.index(x, y + 1)], 8);
            if ((low | high) == 0 || (low == kAllBytesOne && high == kAllBytesOne)) {
                x += 6;
                continue;
            }
        }
        if (y + 1 < canvas.height && x + 1 < canvas.width) {  // a whole block, all painted or none: as it is
            uint16_t low = 0, high = 0;
            std::memcpy(&low, &canvas.filled[canvas.index(x, y)], 2);
            std::memcpy(&high, &canvas.filled[canvas.index(x, y + 1)], 2);
            if ((low | high) == 0 || (low == 0x0101 && high == 0x0101))
                continue;
        }
        size_t at[4];
        int n = 0;
        for (int dy = 0; dy < std::min(2, canvas.height - y); ++dy)
            for (int dx = 0; dx < std::min(2, canvas.width - x); ++dx)
                at[n++] = canvas.index(x + dx, y + dy);
        unsigned sum[3] = {0, 0, 0}, count = 0;
        for (int k = 0; k < n; ++k)
            if (canvas.filled[at[k]] == 1) {
                for (int ch = 0; ch < 3; ++ch)
                    sum[ch] += canvas.rgba[4 * at[k] + size_t(ch)];
                ++count;
            }
        if (count == 0 || int(count) == n)
            continue;
        const glm::u8vec3 mean((sum[0] + count / 2) / count, (sum[1] + count / 2) / count,
                               (sum[2] + count / 2) / count);
        for (int k = 0; k < n; ++k)
            if (canvas.filled[at[k]] != 1)
                canvas.paint(at[k], mean);
    }
}

// Every block, rows of blocks in bands on up to `threads` threads (blocks are disjoint).
void fillBlocks(Canvas &canvas, int threads) {
    const int blockRows = (canvas.height + 1) / 2;
    const size_t bands = threads > 1 ? size_t(std::min(blockRows, 4 * threads)) : 1;
    runBands(bands, threads, [&](size_t band) {
        const int from = int(size_t(blockRows) * band / bands), to = int(size_t(blockRows) * (band + 1) / bands);
        for (int b = from; b < to; ++b)
            fillBlockRow(canvas, 2 * b);
    });
}

}  // namespace

AtlasTexture bakeTexture(const AtlasMesh &mesh, const AtlasLayout &layout, const BakeOptions &options) {
    AtlasTexture out;
    if (mesh.faceCount == 0 && layout.wedgeUv.empty())
        return out;  // nothing to bake
    if (layout.wedgeUv.size() != 3 * mesh.faceCount || layout.width <= 0 || layout.height <= 0)
        throw MeshError("the layout has " + std::to_string(layout.wedgeUv.size()) + " corner UVs on " +
                        std::to_string(layout.width) + " x " + std::to_string(layout.height) + " texels for " +
                        std::to_string(mesh.faceCount) + " faces: it was made for another mesh");
    out.source = chooseSource(mesh, options.source, out.note);
    out.size = out.width = layout.width;
    out.height = layout.height;
    const int width = layout.width, height = layout.height;
    Canvas canvas(width, height, options.background, out.rgba);

    auto colourAt = [&](size_t f, const glm::dvec2 *q, double x, double y) -> glm::u8vec3 {
        if (out.source == BakeSource::FaceColours)
            return mesh.faceColours[f];
        if (out.source == BakeSource::FlatColour)
            return options.flatColour;
        // Gouraud: barycentric weights at the texel centre, clamped onto the triangle for
        // edge texels whose centre lies just outside it.
        const glm::dvec2 p(x, y);
        double w[3] = {doubleArea(p, q[1], q[2]), doubleArea(q[0], p, q[2]), doubleArea(q[0], q[1], p)};
        const double area = w[0] + w[1] + w[2];
        double sum = 0;
        for (double &v : w)
            sum += (v = std::max(0.0, v / area));
        glm::dvec3 c(0.0);
        for (int k = 0; k < 3; ++k)
            c += glm::dvec3(mesh.vertexColours[mesh.triangles[3 * f + k]]) * (w[k] / (sum > 0 ? sum : 1));
        return glm::u8vec3(glm::clamp(glm::round(c), 0.0, 255.0));
    };

    const glm::dvec2 extent(width, height);
    auto load = [&](size_t f, glm::dvec2 *q) {
        for (int k = 0; k < 3; ++k)
            q[k] = glm::dvec2(layout.wedgeUv[3 * f + k]) * extent;
    };
    const bool crisp = out.source == BakeSource::FaceColours;
    const bool uniform = out.source != BakeSource::VertexColours;  // one colour per face
    // Face f (UVs q in texels) on rows rowFrom..rowTo: the texels whose centre it holds (no other
    // face holds them), then those it only overlaps that nothing painted yet.
    auto paintFace = [&](size_t f, const glm::dvec2 *q, int rowFrom, int rowTo) {
        auto paintEdges = [&](size_t row, int y, int from, int to) {
            for (int x = from; x <= to; ++x)
                if (!canvas.filled[row + size_t(x)])
                    canvas.paint(row + size_t(x), colourAt(f, q, x + 0.5, y + 0.5));
        };
        rasterRows(
            q[0], q[1], q[2], kBakeMargin, width, height,
            [&](int y, int cl, int cr, int zl, int zr) {
                const size_t row = canvas.index(0, y);
                for (int x = zl; x <= zr; ++x)
                    canvas.paint(row + size_t(x), colourAt(f, q, x + 0.5, y + 0.5));
                if (zl > zr) {
                    paintEdges(row, y, cl, cr);
                } else {
                    paintEdges(row, y, cl, std::min(cr, zl - 1));
                    paintEdges(row, y, std::max(cl, zr + 1), cr);
                }
            },
            rowFrom, rowTo);
    };
    // One colour per face: the same texels in two passes over the faces, whole spans at once
    // through raw pointers. A texel takes the colour of the last face holding its centre, else of
    // the first face overlapping it: the first pass paints the centres (later faces overwriting),
    // the second the overlapped texels still empty. A face whose overlapped texels (inside the
    // box of its conservative rows and columns) are all painted by then is skipped without
    // rasterising it: most faces inside a chart.
    // The painters copy the pointers and sizes they use into locals (Texels): a store through a
    // byte pointer may alias anything reached through a reference, so those would be loaded again
    // after every texel painted.
    struct Texels {
        uint8_t *rgba, *filled;
        size_t width;
        int top;  // height - 1
        size_t index(int x, int y) const { return size_t(top - y) * width + size_t(x); }
        void paint(size_t i, const uint8_t texel[4]) const {
            std::memcpy(rgba + 4 * i, texel, 4);
            filled[i] = 1;
        }
    };
    const Texels texels{canvas.rgba.data(), canvas.filled.data(), size_t(width), height - 1};
    // The painters below stay out of line: inlined into the bands' loop they were some 3% more
    // instructions (registers spilled around the three).
    auto texelOf = [&](size_t f) {
        const glm::u8vec3 c = colourAt(f, nullptr, 0, 0);
        return std::array<uint8_t, 4>{c.r, c.g, c.b, 255};
    };
    auto paintCentres = [&](size_t f, const glm::dvec2 *q, int rowFrom, int rowTo) __attribute__((noinline)) {
        const std::array<uint8_t, 4> texel = texelOf(f);
        const Texels t = texels;
        rasterCentreSpans(
            q[0], q[1], q[2], width, height,
            [&](int y, int zl, int zr) {
                const size_t row = t.index(0, y);
                for (size_t i = row + size_t(zl); i <= row + size_t(zr); ++i)
                    std::memcpy(t.rgba + 4 * i, texel.data(), 4);
                fillBytes(t.filled + row + size_t(zl), 1, size_t(zr) - size_t(zl) + 1);
            },
            rowFrom, rowTo);
    };
    // A face's UV box in texels, found once for its overlaps and thin points.
    struct Box {
        double minX, maxX, minY, maxY;
    };
    auto boxOf = [](const glm::dvec2 *q) {
        return Box{min3(q[0].x, q[1].x, q[2].x), max3(q[0].x, q[1].x, q[2].x), min3(q[0].y, q[1].y, q[2].y),
                   max3(q[0].y, q[1].y, q[2].y)};
    };
    auto paintOverlapped = [&](size_t f, const glm::dvec2 *q, const Box &b, int rowFrom, int rowTo)
        __attribute__((noinline)) {
        // The conservative raster's box (raster_detail::conservativeBox), within the rows asked.
        const raster_detail::TexelBox box =
            raster_detail::conservativeBox(b.minX, b.maxX, b.minY, b.maxY, kBakeMargin, width, height);
        if (box.x0 > box.x1)
            return;
        const int y0 = std::max(rowFrom, box.y0), y1 = std::min(rowTo, box.y1);
        const Texels t = texels;
        int first = 0, last = 0;  // the rows of the box with an empty texel
        unsetRowRange([&](int y) { return t.filled + t.index(box.x0, y); }, size_t(box.x1) - size_t(box.x0) + 1, y0, y1,
                      first, last);
        if (first > last)
            return;
        rowFrom = first, rowTo = last;
        const std::array<uint8_t, 4> texel = texelOf(f);
        rasterConservativeSpans(
            q[0], q[1], q[2], kBakeMargin, width, height,
            [&](int y, int cl, int cr) {
                const size_t row = t.index(0, y);
                for (size_t i = row + size_t(cl); i <= row + size_t(cr); ++i)
                    if (!t.filled[i])
                        t.paint(i, texel.data());
            },
            rowFrom, rowTo);
    };
    // Faces too thin for the centre rule to guarantee their interior (UV inradius under sqrt(2)
    // texels: a texel holding one of their interior points may have its centre in a neighbour)
    // paint the texels under their interior points with their own colour, and the texels
    // within kUvRounding of them (a point within that of a texel border paints both sides: the
    // UVs written to a text file may put it on either). Faces thicker than sqrt(2) + 2
    // kUvRounding are untouched: the texels within kUvRounding of their interior points have
    // their centres inside the face. Where two thin faces of different colours would share such
    // a texel, the atlas gave one of them a chart of its own beforehand (crowded_faces.h: points
    // closer than sqrt(2) + 0.01 texels), so the order does not matter; it is the faces' order
    // anyway (a texel under two thin faces, over the separation budget, takes the later one's
    // colour). Only rows rowFrom..rowTo; points off the texture paint its nearest texels.
    auto paintThin = [&](size_t f, const glm::dvec2 *q, const Box &b, int rowFrom, int rowTo)
        __attribute__((noinline)) {
        glm::dvec2 points[4] = {};
        const double inradius = faceInteriorPoints(q, points);
        if (!(inradius > 0 && inradius < std::sqrt(2.0) + 2 * kUvRounding))
            return;
        const glm::u8vec3 c = mesh.faceColours[f];
        const uint8_t texel[4] = {c.r, c.g, c.b, 255};
        const Texels t = texels;
        auto paintBox = [&](int x0, int x1, int y0, int y1) {
            for (int y = std::max(rowFrom, y0); y <= std::min(rowTo, y1); ++y)
                for (int x = x0; x <= x1; ++x)
                    t.paint(t.index(x, y), texel);
        };
        // The points lie in the corners' box: when it is well inside (-1, width) x (-1, height),
        // clamping onto the texture changes no texel and the texels are the truncations.
        if (b.minX > -0.5 && b.maxX < width - 0.5 && b.minY > -0.5 && b.maxY < height - 0.5) {
            for (const glm::dvec2 &p : points) {
                const int x0 = int(p.x - kUvRounding), x1 = int(p.x + kUvRounding);
                const int y0 = int(p.y - kUvRounding), y1 = int(p.y + kUvRounding);
                if (((x0 ^ x1) | (y0 ^ y1)) == 0) {  // most points: one texel
                    if (y0 >= rowFrom && y0 <= rowTo)
                        t.paint(t.index(x0, y0), texel);
                    continue;
                }
                paintBox(x0, x1, y0, y1);
            }
            return;
        }
        for (const glm::dvec2 &p : points)
            paintBox(clampToInt(p.x - kUvRounding, 0, width - 1), clampToInt(p.x + kUvRounding, 0, width - 1),
                     clampToInt(p.y - kUvRounding, 0, height - 1), clampToInt(p.y + kUvRounding, 0, height - 1));
    };
    // Bands of rows about as many faces each, and the faces each band takes (bake_bands.h).
    const int workers = bandThreads(options.threads, size_t(height));
    const BakeBands bands =
        bakeBands(layout.wedgeUv, height,
                  workers > 1 && mesh.faceCount >= kLeastParallelFaces ? size_t(2 * workers) : 1, workers);
    // Every face in order; a later face's centre texels overwrite earlier faces' edge texels.
    // Bands of rows run on their own threads, each taking every face in order on its rows only:
    // the same texels as one pass, for any thread count.
    // One colour per face: the centres first (every face), then the overlapped texels and, for
    // crisp bakes, the thin faces, face by face in one pass: both come after every centre, the
    // overlaps only fill empty texels and the thin faces paint over anything, so a texel ends
    // with the last thin face's colour where one holds it, else with the first overlapping
    // face's, as when the thin faces come after all the overlaps.
    runBands(bands.count(), workers, [&](size_t band) {
        const int rowFrom = bands.rowFrom(band), rowTo = bands.rowTo(band);
        canvas.clear(rowFrom, rowTo);  // the bands' rows cover the image
        glm::dvec2 q[3];
        bands.forEachFace(band, [&](size_t f) {
            load(f, q);
            if (uniform)
                paintCentres(f, q, rowFrom, rowTo);
            else
                paintFace(f, q, rowFrom, rowTo);
        });
        if (uniform)
            bands.forEachFace(band, [&](size_t f) {
                load(f, q);
                const Box b = boxOf(q);
                paintOverlapped(f, q, b, rowFrom, rowTo);
                if (crisp)
                    paintThin(f, q, b, rowFrom, rowTo);
            });
    });
    out.dilation = options.dilation < 0 ? layout.gutter / 2 : std::min(options.dilation, width);
    dilate(canvas, out.dilation, bands.count() > 1 ? workers : 1);
    if (layout.block == 2 && out.dilation > 0)
        fillBlocks(canvas, bands.count() > 1 ? workers : 1);
    return out;
}

}  // namespace voxelfair
