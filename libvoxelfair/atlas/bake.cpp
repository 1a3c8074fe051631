#include "atlas/bake.h"

#include "atlas/texel_raster.h"
#include "base/error.h"

#include <algorithm>
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

// Texel states while baking; kWall marks the canvas's one-texel frame.
enum : uint8_t { kEmpty, kCentre, kEdge, kRing, kQueued, kWall };

// Slightly strict coverage (see kMaskMargin in chart_masks.cpp): the bake never paints outside
// the packed masks.
constexpr double kBakeMargin = -1.0 / 256;

struct Texel {
    uint8_t r, g, b, a;
};

// The image with a one-texel frame, rows from the top, so neighbours are fixed offsets and the
// rows copy straight into AtlasTexture::rgba.
struct Canvas {
    int height, pitch;
    std::vector<Texel> texels;
    std::vector<uint8_t> state;
    Canvas(int width, int height, Texel background)
        : height(height), pitch(width + 2), texels(size_t(pitch) * size_t(height + 2), background),
          state(texels.size(), kEmpty) {
        for (int i = 0; i < pitch; ++i)
            state[size_t(i)] = state[size_t(height + 1) * pitch + i] = kWall;
        for (int j = 0; j < height + 2; ++j)
            state[size_t(j) * pitch] = state[size_t(j) * pitch + pitch - 1] = kWall;
    }
    // Layout texel (x, y), y up.
    size_t index(int x, int y) const { return size_t(height - y) * pitch + size_t(x + 1); }
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
void dilate(Canvas &canvas, int rings) {
    const std::ptrdiff_t p = canvas.pitch;
    const std::ptrdiff_t around[8] = {-p - 1, -p, -p + 1, -1, 1, p - 1, p, p + 1};
    std::vector<uint8_t> &state = canvas.state;
    std::vector<uint32_t> frontier, next;
    auto enqueueEmptyNeighbours = [&](size_t i, std::vector<uint32_t> &queue) {
        for (std::ptrdiff_t d : around) {
            const size_t j = size_t(std::ptrdiff_t(i) + d);
            if (state[j] == kEmpty) {
                state[j] = kQueued;
                queue.push_back(uint32_t(j));
            }
        }
    };
    for (size_t i = 0; i < state.size(); ++i)
        if (state[i] == kCentre || state[i] == kEdge)
            enqueueEmptyNeighbours(i, frontier);
    std::vector<Texel> colours;
    for (int ring = 0; ring < rings && !frontier.empty(); ++ring) {
        colours.resize(frontier.size());
        for (size_t k = 0; k < frontier.size(); ++k) {
            unsigned r = 0, g = 0, b = 0, count = 0;
            for (std::ptrdiff_t d : around) {
                const size_t j = size_t(std::ptrdiff_t(frontier[k]) + d);
                if (state[j] == kCentre || state[j] == kEdge || state[j] == kRing) {
                    const Texel &t = canvas.texels[j];
                    r += t.r, g += t.g, b += t.b, ++count;
                }
            }
            colours[k] = {uint8_t((r + count / 2) / count), uint8_t((g + count / 2) / count),
                          uint8_t((b + count / 2) / count), 255};
        }
        for (size_t k = 0; k < frontier.size(); ++k) {
            canvas.texels[frontier[k]] = colours[k];
            state[frontier[k]] = kRing;
        }
        next.clear();
        if (ring + 1 < rings)
            for (uint32_t i : frontier)
                enqueueEmptyNeighbours(i, next);
        frontier.swap(next);
    }
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
    const glm::u8vec4 bg = options.background;
    Canvas canvas(width, height, Texel{bg.r, bg.g, bg.b, bg.a});

    auto paint = [&](int x, int y, glm::u8vec3 c, uint8_t how) {
        const size_t i = canvas.index(x, y);
        canvas.texels[i] = {c.r, c.g, c.b, 255};
        canvas.state[i] = how;
    };
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
    glm::dvec2 q[3];
    auto load = [&](size_t f) {
        for (int k = 0; k < 3; ++k)
            q[k] = glm::dvec2(layout.wedgeUv[3 * f + k]) * extent;
    };
    // One pass: a face paints the texels whose centre it holds (no other face holds them), then
    // those it only overlaps that nothing painted yet; a later face's centre texels overwrite
    // such edge texels. Crisp bakes also note the faces too thin for the centre rule (below).
    const bool crisp = out.source == BakeSource::FaceColours;
    std::vector<uint32_t> thin;
    glm::dvec2 points[4] = {};
    for (size_t f = 0; f < mesh.faceCount; ++f) {
        load(f);
        if (crisp) {
            const double inradius = faceInteriorPoints(q, points);
            if (inradius > 0 && inradius < std::sqrt(2.0))
                thin.push_back(uint32_t(f));
        }
        rasterCentres(q[0], q[1], q[2], width, height,
                      [&](int x, int y) { paint(x, y, colourAt(f, q, x + 0.5, y + 0.5), kCentre); });
        rasterConservative(q[0], q[1], q[2], kBakeMargin, width, height, [&](int x, int y) {
            if (canvas.state[canvas.index(x, y)] == kEmpty)
                paint(x, y, colourAt(f, q, x + 0.5, y + 0.5), kEdge);
        });
    }
    // Faces too thin for the centre rule to guarantee their interior (UV inradius under sqrt(2)
    // texels: a texel holding one of their interior points may have its centre in a neighbour)
    // paint the texels under their interior points with their own colour. Faces at least that
    // thick are untouched: their interior points lie over their own centre texels. Where two
    // thin faces of different colours would share such a texel, the atlas gave one of them a
    // chart of its own beforehand (crowded_faces.h), so the order does not matter.
    for (uint32_t f : thin) {
        load(f);
        faceInteriorPoints(q, points);
        for (const glm::dvec2 &p : points)
            paint(std::clamp(int(std::floor(p.x)), 0, width - 1), std::clamp(int(std::floor(p.y)), 0, height - 1),
                  mesh.faceColours[f], kCentre);
    }
    out.dilation = options.dilation < 0 ? layout.gutter / 2 : std::min(options.dilation, width);
    dilate(canvas, out.dilation);
    out.rgba.resize(size_t(width) * size_t(height) * 4);
    for (int row = 0; row < height; ++row)
        std::memcpy(&out.rgba[size_t(row) * size_t(width) * 4], &canvas.texels[size_t(row + 1) * canvas.pitch + 1],
                    size_t(width) * sizeof(Texel));
    return out;
}

}  // namespace voxelfair
