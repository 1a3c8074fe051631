// Section 4.4 speed on a ~100k-vertex voxel sphere after one fairing pass: quads to triangles,
// face normals, vertex normals (distinct directions) and vertex colours.
#include "attributes/face_normals.h"
#include "attributes/triangulate.h"
#include "attributes/vertex_colours.h"
#include "attributes/vertex_normals.h"
#include "extraction/boundary_surface.h"
#include "fairing/lanczos_fairing.h"
#include "shapes/analytic_shapes.h"

#include <benchmark/benchmark.h>

#include <vector>

#include <glm/vec4.hpp>

namespace {

using namespace voxelfair;

struct FairedSphere {
    std::vector<glm::vec3> positions, quadNormals;
    std::vector<uint32_t> offsets, quads;
    std::vector<glm::vec4> quadColours;

    FairedSphere() {
        const double r = 72.3;
        BoundarySurface s = extractBoundarySurface(
            shapes::voxelize(shapes::sphere(glm::dvec3(r + 2.31, r + 2.17, r + 2.43), r), [](int x, int y, int z) {
                return Voxel{uint8_t((x ^ y ^ z) & 0xff), 0};
            }));
        positions = std::move(s.positions);
        quads = std::move(s.quads);
        offsets.resize(quadCount() + 1);
        for (size_t q = 0; q < offsets.size(); ++q)
            offsets[q] = uint32_t(4 * q);
        fairModifiedLanczos({positions.data(), positions.size(), offsets.data(), quads.data(), quadCount()}, nullptr);
        quadNormals.resize(quadCount());
        computePolygonNormals({positions.data(), positions.size(), offsets.data(), quads.data(), quadCount()},
                              quadNormals.data());
        for (const Voxel &v : s.quadVoxels)
            quadColours.emplace_back(v.colour / 255.0f, 0.5f, 1.0f - v.colour / 255.0f, 1.0f);
    }
    size_t quadCount() const { return quads.size() / 4; }
};

const FairedSphere &mesh() {
    static const FairedSphere m;
    return m;
}

void setCounters(benchmark::State &state) {
    state.counters["vertices"] = double(mesh().positions.size());
    state.counters["quads"] = double(mesh().quadCount());
}

void BM_TriangulateQuads(benchmark::State &state) {
    const FairedSphere &m = mesh();
    std::vector<uint32_t> triangles(3 * countFanTriangles({nullptr, 0, m.offsets.data(), nullptr, m.quadCount()})),
        toQuad(triangles.size() / 3);
    for (auto _ : state) {
        triangulatePolygons({nullptr, m.positions.size(), m.offsets.data(), m.quads.data(), m.quadCount()},
                            triangles.data(), toQuad.data());
        benchmark::DoNotOptimize(triangles.data());
    }
    setCounters(state);
}
BENCHMARK(BM_TriangulateQuads)->Unit(benchmark::kMillisecond);

void BM_QuadNormals(benchmark::State &state) {
    const FairedSphere &m = mesh();
    std::vector<glm::vec3> normals(m.quadCount());
    for (auto _ : state) {
        computePolygonNormals({m.positions.data(), m.positions.size(), m.offsets.data(), m.quads.data(), m.quadCount()},
                              normals.data());
        benchmark::DoNotOptimize(normals.data());
    }
    setCounters(state);
}
BENCHMARK(BM_QuadNormals)->Unit(benchmark::kMillisecond);

void BM_VertexNormals(benchmark::State &state) {
    const FairedSphere &m = mesh();
    std::vector<glm::vec3> normals(m.positions.size());
    for (auto _ : state) {
        computeVertexNormals({nullptr, m.positions.size(), m.offsets.data(), m.quads.data(), m.quadCount()},
                             m.quadNormals.data(), normals.data());
        benchmark::DoNotOptimize(normals.data());
    }
    setCounters(state);
}
BENCHMARK(BM_VertexNormals)->Unit(benchmark::kMillisecond);

void BM_VertexColours(benchmark::State &state) {
    const FairedSphere &m = mesh();
    std::vector<glm::vec4> colours(m.positions.size());
    for (auto _ : state) {
        computeVertexColours(
            {nullptr, m.positions.size(), m.offsets.data(), m.quads.data(), m.quadCount(), m.quadColours.data()},
            colours.data());
        benchmark::DoNotOptimize(colours.data());
    }
    setCounters(state);
}
BENCHMARK(BM_VertexColours)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
