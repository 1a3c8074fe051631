#include "atlas/atlas_measures.h"

#include "atlas/texel_raster.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace voxelfair {
namespace {

constexpr double kMargin = -1.0 / 256;  // the bake's coverage

struct SingularValues {
    double max, min;
};

// Of the linear map taking the 3D triangle p onto the UV triangle q.
SingularValues mapSingularValues(const glm::dvec3 p[3], const glm::dvec2 q[3]) {
    const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    const double l1 = glm::length(e1);
    const double a = glm::dot(e2, e1) / l1, b = glm::length(glm::cross(e1, e2)) / l1;
    // In the triangle's own frame P1 = (l1, 0), P2 = (a, b); J = [Q1 Q2] [P1 P2]^-1.
    const glm::dvec2 q1 = q[1] - q[0], q2 = q[2] - q[0];
    const glm::dvec2 c0 = q1 / l1, c1 = (q2 * l1 - q1 * a) / (l1 * b);
    const double e = glm::dot(c0, c0), g = glm::dot(c1, c1), f = glm::dot(c0, c1);
    const double root = std::sqrt((e - g) * (e - g) + 4 * f * f);
    return {std::sqrt(std::max(0.0, (e + g + root) / 2)), std::sqrt(std::max(0.0, (e + g - root) / 2))};
}

void loadUv(const AtlasLayout &layout, size_t f, glm::dvec2 q[3]) {
    for (int k = 0; k < 3; ++k)
        q[k] = glm::dvec2(layout.wedgeUv[3 * f + k]) * glm::dvec2(layout.width, layout.height);
}

}  // namespace

AtlasMeasures measureAtlas(const AtlasMesh &mesh, const AtlasCharts &charts, const AtlasLayout &layout) {
    AtlasMeasures m;
    if (layout.width <= 0 || layout.height <= 0)
        return m;
    const int size = layout.width, height = layout.height;
    const size_t texels = size_t(size) * size_t(height);
    constexpr uint32_t kShared = UINT32_MAX;
    std::vector<uint32_t> owner(texels, 0);  // chart + 1, or kShared
    std::vector<uint8_t> centres(texels, 0);
    size_t centreTexels = 0;
    m.charts.resize(charts.chartCount());
    double weighted = 0, weight = 0;
    glm::dvec2 q[3];
    for (size_t c = 0; c < charts.chartCount(); ++c) {
        const uint32_t tag = uint32_t(c) + 1;
        for (uint32_t i = charts.chartFirstFace[c]; i < charts.chartFirstFace[c + 1]; ++i) {
            const uint32_t f = charts.chartFaces[i];
            loadUv(layout, f, q);
            if (!(doubleArea(q[0], q[1], q[2]) > 0))
                ++m.facesWithoutUvArea;
            rasterConservative(q[0], q[1], q[2], kMargin, size, height, [&](int x, int y) {
                uint32_t &o = owner[size_t(y) * size + x];
                if (o == 0) {
                    o = tag;
                    ++m.coveredTexels;
                } else if (o != tag && o != kShared) {
                    o = kShared;
                    ++m.overlappingChartTexels;
                }
            });
            rasterCentres(q[0], q[1], q[2], size, height, [&](int x, int y) {
                uint8_t &n = centres[size_t(y) * size + x];
                if (n == 1)
                    ++m.overlappingCentres;
                centreTexels += n == 0;
                n = uint8_t(std::min(n + 1, 2));
            });
            if (charts.isDegenerate(c))
                continue;
            glm::dvec3 p[3];
            for (int k = 0; k < 3; ++k)
                p[k] = mesh.positions[mesh.triangles[3 * f + k]];
            const SingularValues s = mapSingularValues(p, q);
            const double density = layout.texelsPerUnit * (mesh.faceTexelScale ? mesh.faceTexelScale[f] : 1.0f);
            const double stretch = s.max / density, inverse = density / s.min;
            m.charts[c].maxStretch = std::max(m.charts[c].maxStretch, stretch);
            m.charts[c].maxInverseStretch = std::max(m.charts[c].maxInverseStretch, inverse);
            const double area = glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
            weighted += area * inverse;
            weight += area;
        }
        m.maxStretch = std::max(m.maxStretch, m.charts[c].maxStretch);
        m.maxInverseStretch = std::max(m.maxInverseStretch, m.charts[c].maxInverseStretch);
    }
    m.packingEfficiency = double(m.coveredTexels) / double(texels);
    m.centreEfficiency = double(centreTexels) / double(texels);
    m.meanInverseStretch = weight > 0 ? weighted / weight : 1.0;
    return m;
}

ColourFidelity measureColourFidelity(const AtlasMesh &mesh, const AtlasLayout &layout, const AtlasTexture &texture) {
    ColourFidelity r;
    if (!mesh.faceColours || texture.width <= 0 || texture.height <= 0 || layout.wedgeUv.size() != 3 * mesh.faceCount)
        return r;
    const int size = texture.width, height = texture.height;
    // Nearest: every texel within kUvRounding of p holds the colour, so the sample reads it
    // from the UVs as written to a file too.
    auto nearestIs = [&](glm::dvec2 p, glm::u8vec3 want) {
        auto texel = [](double v, int n) { return std::clamp(int(std::floor(v)), 0, n - 1); };
        for (int y = texel(p.y - kUvRounding, height); y <= texel(p.y + kUvRounding, height); ++y)
            for (int x = texel(p.x - kUvRounding, size); x <= texel(p.x + kUvRounding, size); ++x)
                if (glm::u8vec3(texture.texel(x, y)) != want)
                    return false;
        return true;
    };
    auto bilinear = [&](glm::dvec2 p) {
        const glm::dvec2 t = p - 0.5, base = glm::floor(t), w = t - base;
        glm::dvec3 sum(0.0);
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const int x = std::clamp(int(base.x) + dx, 0, size - 1),
                          y = std::clamp(int(base.y) + dy, 0, height - 1);
                const double k = (dx ? w.x : 1 - w.x) * (dy ? w.y : 1 - w.y);
                sum += glm::dvec3(glm::u8vec3(texture.texel(x, y))) * k;
            }
        return glm::u8vec3(glm::round(sum));
    };
    r.minInradius = INFINITY;
    glm::dvec2 q[3];
    for (size_t f = 0; f < mesh.faceCount; ++f) {
        loadUv(layout, f, q);
        glm::dvec2 samples[4];
        const double inradius = faceInteriorPoints(q, samples);
        if (!(inradius > 0))
            continue;
        r.minInradius = std::min(r.minInradius, inradius);
        const bool sureNearest = inradius >= std::sqrt(2.0), sureBilinear = inradius >= 2 * std::sqrt(2.0);
        const glm::u8vec3 want = mesh.faceColours[f];
        for (const glm::dvec2 &p : samples) {
            const bool n = nearestIs(p, want), l = bilinear(p) == want;
            ++r.samples;
            r.nearestMatches += n;
            r.bilinearMatches += l;
            r.guaranteedNearest += sureNearest;
            r.guaranteedNearestMatches += sureNearest && n;
            r.guaranteedBilinear += sureBilinear;
            r.guaranteedBilinearMatches += sureBilinear && l;
        }
    }
    if (r.samples == 0)
        r.minInradius = 0;
    return r;
}

}  // namespace voxelfair
