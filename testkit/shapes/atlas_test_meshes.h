// Test meshes for the texture atlas, built here so the atlas tests do not depend on the
// extraction stage: the exposed faces of a dense voxel solid as welded quads (counter-clockwise
// from outside), split along a-c (triangles 2k and 2k+1 come from quad k), one colour per voxel,
// optionally smoothed with Taubin's lambda|mu steps (MeshLab's defaults 0.5, -0.53).
// Header-only: the tests, tools/atlas_report and the benchmark share it.
#pragma once

#include "atlas/atlas_mesh.h"
#include "atlas/texture_atlas.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/type_precision.hpp>
#include <glm/vec3.hpp>

namespace voxelfair::atlastest {

struct TestMesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> triangles;
    std::vector<glm::u8vec3> faceColours;
    std::vector<glm::u8vec3> vertexColours;

    size_t faceCount() const { return triangles.size() / 3; }
    AtlasMesh view(bool withFaceColours = true, bool withVertexColours = true) const {
        AtlasMesh m;
        m.positions = positions.data();
        m.vertexCount = positions.size();
        m.triangles = triangles.data();
        m.faceCount = faceCount();
        m.faceColours = withFaceColours && !faceColours.empty() ? faceColours.data() : nullptr;
        m.vertexColours = withVertexColours && !vertexColours.empty() ? vertexColours.data() : nullptr;
        return m;
    }
};

// The atlas of `mesh` at `texelsPerUnit` (PackOptions::texelsPerUnit), the other options as given.
inline TextureAtlas atlasAt(const TestMesh &mesh, float texelsPerUnit, AtlasOptions options = {}) {
    options.pack.texelsPerUnit = texelsPerUnit;
    return buildTextureAtlas(mesh.view(), options);
}

// A pixel-art colour per voxel: neighbours almost always differ.
inline glm::u8vec3 voxelColour(int x, int y, int z) {
    uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(z) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return {uint8_t(h), uint8_t(h >> 8), uint8_t(h >> 16)};
}

// Mean of the adjacent faces' colours, per vertex (section 4.4).
inline void computeVertexColours(TestMesh &m) {
    std::vector<glm::uvec4> sum(m.positions.size(), glm::uvec4(0));
    for (size_t f = 0; f < m.faceCount(); ++f)
        for (int k = 0; k < 3; ++k)
            sum[m.triangles[3 * f + k]] += glm::uvec4(glm::uvec3(m.faceColours[f]), 1);
    m.vertexColours.resize(m.positions.size());
    for (size_t v = 0; v < sum.size(); ++v)
        m.vertexColours[v] = sum[v].w ? glm::u8vec3(glm::uvec3(sum[v]) / sum[v].w) : glm::u8vec3(0);
}

// The boundary quads of the solid voxels of an nx x ny x nz grid.
inline TestMesh voxelSurface(const std::string &name, int nx, int ny, int nz,
                             const std::function<bool(int, int, int)> &solid) {
    TestMesh m;
    m.name = name;
    std::vector<uint8_t> grid(size_t(nx) * ny * nz);
    for (int z = 0; z < nz; ++z)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x)
                grid[(size_t(z) * ny + y) * nx + x] = solid(x, y, z);
    auto at = [&](int x, int y, int z) {
        return x >= 0 && y >= 0 && z >= 0 && x < nx && y < ny && z < nz && grid[(size_t(z) * ny + y) * nx + x];
    };
    std::vector<int32_t> vertexOf(size_t(nx + 1) * (ny + 1) * (nz + 1), -1);
    auto vertex = [&](glm::ivec3 p) {
        int32_t &v = vertexOf[(size_t(p.z) * (ny + 1) + p.y) * (nx + 1) + p.x];
        if (v < 0) {
            v = int32_t(m.positions.size());
            m.positions.push_back(glm::vec3(p));
        }
        return uint32_t(v);
    };
    const glm::ivec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int z = 0; z < nz; ++z)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                if (!at(x, y, z))
                    continue;
                const glm::ivec3 p(x, y, z);
                for (int d = 0; d < 3; ++d)
                    for (int s = 0; s < 2; ++s) {
                        const glm::ivec3 n = s ? axes[d] : -axes[d];
                        if (at(x + n.x, y + n.y, z + n.z))
                            continue;
                        const glm::ivec3 u = axes[(d + 1) % 3], v = axes[(d + 2) % 3];
                        const glm::ivec3 base = p + (s ? axes[d] : glm::ivec3(0));
                        // u x v = +axis: (0, u, u+v, v) faces +axis, the reverse faces -axis.
                        glm::ivec3 c[4] = {base, base + u, base + u + v, base + v};
                        if (!s)
                            std::swap(c[1], c[3]);
                        const uint32_t q[4] = {vertex(c[0]), vertex(c[1]), vertex(c[2]), vertex(c[3])};
                        m.triangles.insert(m.triangles.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
                        m.faceColours.push_back(voxelColour(x, y, z));
                        m.faceColours.push_back(voxelColour(x, y, z));
                    }
            }
    computeVertexColours(m);
    return m;
}

inline TestMesh voxelSphere(double radius) {
    const int n = int(std::ceil(2 * radius)) + 2;
    const double c = n / 2.0;
    return voxelSurface("sphere r" + std::to_string(int(radius)), n, n, n, [=](int x, int y, int z) {
        const double dx = x + 0.5 - c, dy = y + 0.5 - c, dz = z + 0.5 - c;
        return dx * dx + dy * dy + dz * dz <= radius * radius;
    });
}

inline TestMesh voxelBox(int sx, int sy, int sz) {
    return voxelSurface("box " + std::to_string(sx) + "x" + std::to_string(sy) + "x" + std::to_string(sz), sx, sy, sz,
                        [](int, int, int) { return true; });
}

// Ring around the z axis: major radius R, tube radius r.
inline TestMesh voxelTorus(double R, double r) {
    const int n = int(std::ceil(2 * (R + r))) + 2, h = int(std::ceil(2 * r)) + 2;
    const double c = n / 2.0, ch = h / 2.0;
    return voxelSurface("torus " + std::to_string(int(R)) + "/" + std::to_string(int(r)), n, n, h,
                        [=](int x, int y, int z) {
                            const double dx = x + 0.5 - c, dy = y + 0.5 - c, dz = z + 0.5 - ch;
                            const double q = std::sqrt(dx * dx + dy * dy) - R;
                            return q * q + dz * dz <= r * r;
                        });
}

// A sphere whose radius varies smoothly with direction (random low-frequency bumps).
inline TestMesh voxelBlob(double radius, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    struct Bump {
        glm::dvec3 dir;
        double height;
    };
    std::vector<Bump> bumps(6);
    for (Bump &b : bumps) {
        b.dir = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)) + 1e-9);
        b.height = 0.25 * unit(rng);
    }
    const int n = int(std::ceil(2.6 * radius)) + 2;
    const double c = n / 2.0;
    return voxelSurface("blob " + std::to_string(seed), n, n, n, [=](int x, int y, int z) {
        const glm::dvec3 d(x + 0.5 - c, y + 0.5 - c, z + 0.5 - c);
        const double len = glm::length(d);
        if (len == 0)
            return true;
        double rr = radius;
        for (const Bump &b : bumps)
            rr += radius * b.height * std::exp(4 * (glm::dot(d / len, b.dir) - 1));
        return len <= rr;
    });
}

// Taubin smoothing (lambda|mu), uniform weights over triangle edges, as MeshLab's filter.
inline void taubinSmooth(TestMesh &m, int steps = 10, float lambda = 0.5f, float mu = -0.53f) {
    std::vector<uint64_t> edges;
    edges.reserve(m.triangles.size() * 2);
    for (size_t f = 0; f < m.faceCount(); ++f)
        for (int k = 0; k < 3; ++k) {
            const uint64_t a = m.triangles[3 * f + k], b = m.triangles[3 * f + (k + 1) % 3];
            edges.push_back(a << 32 | b);
            edges.push_back(b << 32 | a);
        }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::vector<glm::vec3> sum(m.positions.size());
    std::vector<float> count(m.positions.size());
    for (int s = 0; s < 2 * steps; ++s) {
        std::fill(sum.begin(), sum.end(), glm::vec3(0));
        std::fill(count.begin(), count.end(), 0.0f);
        for (uint64_t e : edges) {
            sum[e >> 32] += m.positions[uint32_t(e)];
            count[e >> 32] += 1;
        }
        const float k = s % 2 ? mu : lambda;
        for (size_t v = 0; v < m.positions.size(); ++v)
            if (count[v] > 0)
                m.positions[v] += k * (sum[v] / count[v] - m.positions[v]);
    }
}

inline TestMesh smoothed(TestMesh m, int steps = 10) {
    taubinSmooth(m, steps);
    m.name += " taubin" + std::to_string(steps);
    return m;
}

}  // namespace voxelfair::atlastest
