// The .glb writer alone (export/glb_writer.h) on the atlas benchmark's mesh: a Taubin-smoothed
// voxel sphere of radius 70, ~185k triangles (the paper's largest model), with its atlas's
// per-corner UVs, smooth vertex normals and a 1 MB texture, as one node and split over 12 part
// nodes (each with 8 animation frames). Counters: triangles, bytes written, MB/s.
#include "shapes/atlas_test_meshes.h"
#include "atlas/texture_atlas.h"
#include "export/glb_writer.h"

#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>

using namespace voxelfair;
using namespace voxelfair::atlastest;

namespace {

struct Input {
    GlbMesh mesh;
    GlbTexture texture;
};

const Input &input() {
    static const Input in = [] {
        const TestMesh sphere = smoothed(voxelSphere(70), 10);
        Input in;
        in.mesh.positions = sphere.positions;
        in.mesh.triangles = sphere.triangles;
        const TextureAtlas atlas = buildTextureAtlas(sphere.view(), AtlasOptions{});
        in.mesh.cornerUvs = atlas.layout.wedgeUv;
        std::vector<glm::vec3> normals(sphere.positions.size(), glm::vec3(0.0f));
        for (size_t t = 0; t < sphere.triangles.size(); t += 3) {
            const glm::vec3 &a = sphere.positions[sphere.triangles[t]], &b = sphere.positions[sphere.triangles[t + 1]],
                            &c = sphere.positions[sphere.triangles[t + 2]];
            for (int k = 0; k < 3; ++k)
                normals[sphere.triangles[t + size_t(k)]] += glm::cross(b - a, c - a);
        }
        for (glm::vec3 &n : normals)
            n = glm::normalize(n);
        in.mesh.normals = normals;
        in.texture.png.assign(1 << 20, 0x55);  // embedded as is: its content does not matter here
        return in;
    }();
    return in;
}

void report(benchmark::State &state, const GlbMesh &mesh, size_t bytes) {
    state.counters["triangles"] = double(mesh.triangles.size() / 3);
    state.counters["bytes"] = double(bytes);
    state.counters["MB/s"] =
        benchmark::Counter(double(bytes) * double(state.iterations()) / 1e6, benchmark::Counter::kIsRate);
}

void BM_GlbWriterOneNode(benchmark::State &state) {
    const Input &in = input();
    size_t bytes = 0;
    for (auto _ : state) {
        const std::vector<uint8_t> glb = writeGlb(in.mesh, ExportScene{}, &in.texture);
        bytes = glb.size();
        benchmark::DoNotOptimize(glb.data());
    }
    report(state, in.mesh, bytes);
}
BENCHMARK(BM_GlbWriterOneNode)->Unit(benchmark::kMillisecond);

void BM_GlbWriterTwelveAnimatedParts(benchmark::State &state) {
    const Input &in = input();
    GlbMesh mesh = in.mesh;
    ExportScene scene;
    for (int i = 0; i < 12; ++i) {
        ExportNode node;
        node.name = "part" + std::to_string(i);
        node.parent = i == 0 ? -1 : 0;
        node.world = glm::translate(glm::mat4(1.0f), glm::vec3(float(i), 0.0f, 0.0f));
        for (int f = 0; f < 8; ++f)
            node.frames.push_back(glm::rotate(node.world, 0.1f * float(f), glm::vec3(0, 0, 1)));
        scene.nodes.push_back(node);
    }
    for (size_t t = 0; t < mesh.triangles.size() / 3; ++t)
        mesh.triangleNodes.push_back(int(t % 12));
    size_t bytes = 0;
    for (auto _ : state) {
        const std::vector<uint8_t> glb = writeGlb(mesh, scene, &in.texture);
        bytes = glb.size();
        benchmark::DoNotOptimize(glb.data());
    }
    report(state, mesh, bytes);
}
BENCHMARK(BM_GlbWriterTwelveAnimatedParts)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
