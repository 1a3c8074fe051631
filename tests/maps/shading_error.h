// The normal map's goal measure: how far, in angle, a decimated mesh's shading normal is from the
// undecimated faired surface's, with and without the baked map.
//
// Samples are spread uniformly by area over the decimated (target) mesh (fixed seed). At each,
// the reference is the faired (source) surface's interpolated vertex normal at the closest
// source point among the faces facing the same way (positive dot with the target's normal, so a
// thin plate's far side is never taken): geometry alone, independent of the UVs the bake goes
// through. Compared with it:
//   * the target's own shading normal: its vertex normals interpolated (what a renderer shows
//     without a map);
//   * the mapped normal: the map read with bilinear filtering at the sample's UV (a renderer's
//     linear sampler) and applied in the interpolated MikkTSpace frame (applyNormalMapTexel).
#pragma once

#include "maps/normal_bake.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>

namespace voxelfair::mapstest {

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5), as
// barycentric weights.
inline glm::dvec3 closestBarycentric(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
        return {1, 0, 0};
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
        return {0, 1, 0};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        return {1 - v, v, 0};
    }
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6)
        return {0, 0, 1};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        return {1 - w, 0, w};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0, 1 - w, w};
    }
    const double denom = 1 / (va + vb + vc);
    const double v = vb * denom, w = vc * denom;
    return {1 - v - w, v, w};
}

struct ShadingErrors {
    double vertexNormalDegrees = 0;  // mean angle, target's own normals
    double mappedDegrees = 0;        // mean angle, with the map
    size_t samples = 0, unmatched = 0;
    double ratio() const { return vertexNormalDegrees > 0 ? mappedDegrees / vertexNormalDegrees : 0; }
};

inline glm::vec3 sampleMapBilinear(const NormalMap &map, glm::vec2 uv) {
    const int width = map.width, height = map.height;
    const float x = uv.x * float(width) - 0.5f, y = uv.y * float(height) - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - float(x0), fy = y - float(y0);
    glm::vec3 sum(0.0f);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            const int tx = std::clamp(x0 + i, 0, width - 1), ty = std::clamp(y0 + j, 0, height - 1);
            const uint8_t *p = &map.rgba[(size_t(height - 1 - ty) * size_t(width) + size_t(tx)) * 4];
            const glm::vec3 t(p[0] / 255.0f * 2 - 1, p[1] / 255.0f * 2 - 1, p[2] / 255.0f * 2 - 1);
            sum += t * ((i ? fx : 1 - fx) * (j ? fy : 1 - fy));
        }
    return sum;
}

inline double angleDegrees(glm::vec3 a, glm::vec3 b) {
    const double c = std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0);
    return std::acos(c) * 180.0 / M_PI;
}

// `reach`: how far (model units) a source point may be from the sample.
inline ShadingErrors measureShading(const NormalBakeMesh &source, const NormalBakeMesh &target, const NormalMap &map,
                                    size_t sampleCount, double reach, uint32_t seed = 13) {
    ShadingErrors out;
    // Uniform grid of the source faces, cells of `reach` (at least 1/512 of the source's extent).
    glm::vec3 boxLo(INFINITY), boxHi(-INFINITY);
    for (size_t v = 0; v < source.vertexCount; ++v)
        boxLo = glm::min(boxLo, source.positions[v]), boxHi = glm::max(boxHi, source.positions[v]);
    const double cell = std::max(reach, double(glm::length(boxHi - boxLo)) / 512.0);
    auto key = [](int64_t x, int64_t y, int64_t z) {
        return uint64_t((x & 0x1FFFFF) | ((y & 0x1FFFFF) << 21) | ((z & 0x1FFFFF) << 42));
    };
    std::unordered_map<uint64_t, std::vector<uint32_t>> grid;
    std::vector<glm::vec3> faceNormal(source.faceCount);
    for (size_t f = 0; f < source.faceCount; ++f) {
        const glm::vec3 a = source.positions[source.triangles[3 * f]],
                        b = source.positions[source.triangles[3 * f + 1]],
                        c = source.positions[source.triangles[3 * f + 2]];
        faceNormal[f] = glm::cross(b - a, c - a);
        const glm::vec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
        for (int64_t z = int64_t(std::floor(lo.z / cell)); z <= int64_t(std::floor(hi.z / cell)); ++z)
            for (int64_t y = int64_t(std::floor(lo.y / cell)); y <= int64_t(std::floor(hi.y / cell)); ++y)
                for (int64_t x = int64_t(std::floor(lo.x / cell)); x <= int64_t(std::floor(hi.x / cell)); ++x)
                    grid[key(x, y, z)].push_back(uint32_t(f));
    }
    // Area-weighted face choice.
    std::vector<double> cumulative(target.faceCount);
    double total = 0;
    for (size_t f = 0; f < target.faceCount; ++f) {
        const glm::vec3 a = target.positions[target.triangles[3 * f]],
                        b = target.positions[target.triangles[3 * f + 1]],
                        c = target.positions[target.triangles[3 * f + 2]];
        total += 0.5 * glm::length(glm::cross(b - a, c - a));
        cumulative[f] = total;
    }
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double sumVertex = 0, sumMapped = 0;
    for (size_t s = 0; s < sampleCount; ++s) {
        const size_t f =
            size_t(std::lower_bound(cumulative.begin(), cumulative.end(), unit(rng) * total) - cumulative.begin());
        if (f >= target.faceCount)
            continue;
        double r1 = unit(rng), r2 = unit(rng);
        if (r1 + r2 > 1)
            r1 = 1 - r1, r2 = 1 - r2;
        const float l[3] = {float(1 - r1 - r2), float(r1), float(r2)};
        glm::vec3 p(0.0f), n(0.0f), t(0.0f);
        glm::vec2 uv(0.0f);
        float w = 0.0f;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = target.triangles[3 * f + size_t(k)];
            p += l[k] * target.positions[v];
            n += l[k] * glm::normalize(target.normals[v]);
            const glm::vec4 tk = map.cornerTangents[3 * f + size_t(k)];
            t += l[k] * glm::vec3(tk);
            w += l[k] * tk.w;
            uv += l[k] * target.wedgeUv[3 * f + size_t(k)];
        }
        // Closest facing source point.
        double best = reach * reach;
        glm::vec3 reference(0.0f);
        const int64_t cx = int64_t(std::floor(p.x / cell)), cy = int64_t(std::floor(p.y / cell)),
                      cz = int64_t(std::floor(p.z / cell));
        for (int64_t z = cz - 1; z <= cz + 1; ++z)
            for (int64_t y = cy - 1; y <= cy + 1; ++y)
                for (int64_t x = cx - 1; x <= cx + 1; ++x) {
                    const auto it = grid.find(key(x, y, z));
                    if (it == grid.end())
                        continue;
                    for (uint32_t g : it->second) {
                        if (glm::dot(faceNormal[g], n) <= 0.0f)
                            continue;
                        const uint32_t *sv = &source.triangles[3 * size_t(g)];
                        const glm::dvec3 a(source.positions[sv[0]]), b(source.positions[sv[1]]),
                            c(source.positions[sv[2]]);
                        const glm::dvec3 bary = closestBarycentric(glm::dvec3(p), a, b, c);
                        const glm::dvec3 q = bary.x * a + bary.y * b + bary.z * c;
                        const double d = glm::dot(q - glm::dvec3(p), q - glm::dvec3(p));
                        if (d < best) {
                            best = d;
                            reference = float(bary.x) * glm::normalize(source.normals[sv[0]]) +
                                        float(bary.y) * glm::normalize(source.normals[sv[1]]) +
                                        float(bary.z) * glm::normalize(source.normals[sv[2]]);
                        }
                    }
                }
        if (!(glm::length(reference) > 0.0f) || !(glm::length(t) > 0.0f) || !(glm::length(n) > 0.0f)) {
            ++out.unmatched;
            continue;
        }
        const glm::vec3 mapped = applyNormalMapTexel(sampleMapBilinear(map, uv), n, glm::vec4(t, w));
        sumVertex += angleDegrees(n, reference);
        sumMapped += angleDegrees(mapped, reference);
        ++out.samples;
    }
    if (out.samples > 0) {
        out.vertexNormalDegrees = sumVertex / double(out.samples);
        out.mappedDegrees = sumMapped / double(out.samples);
    }
    return out;
}

}  // namespace voxelfair::mapstest
