// Normal map baking (libvoxelfair/maps): a voxel sphere of radius 70 (92,280 quads, 184,560
// triangles, the size of the paper's largest model), faired (paper 4.3), atlas at 8 texels per
// voxel (4.5), decimated to 10% of its faces with MeshLab's quadric decimation with texture
// (vcglib, tests/maps/vcg_quadric_tex.h), then the timed stage: the normal map of the faired mesh
// baked into the decimated mesh's atlas (tangents included). Target: at most 150 ms.
// MikkTSpace tangents of the decimated and of the full mesh are timed on their own too.
#include "pipeline/faired_models.h"
#include "maps/mikktspace.h"
#include "maps/normal_bake.h"
#include "shapes/analytic_shapes.h"

#include <benchmark/benchmark.h>

using namespace voxelfair;
using namespace voxelfair::mapstest;

namespace {

struct Prepared {
    FairedMesh hi;
    vcgdecimate::TexturedMesh lo;
};

const Prepared &prepared() {
    static const Prepared p = [] {
        const double r = 70;
        const shapes::Shape sphere = shapes::sphere(glm::dvec3(r + 2.31, r + 2.17, r + 2.43), r);
        Palette palette;
        palette.colours[1] = {214, 128, 64};
        const auto model = pipeline::volumeModel("sphere_r70",
                                                 shapes::voxelize(sphere,
                                                                  [](int, int, int) {
                                                                      return Voxel{1, 0};
                                                                  }),
                                                 palette);
        Prepared out;
        out.hi = fairedMesh(*model, 8.0f);
        out.lo = vcgdecimate::decimate(out.hi.positions, out.hi.triangles, out.hi.wedgeUv, 0.1);
        return out;
    }();
    return p;
}

void BM_BakeNormalMap(benchmark::State &state) {
    const Prepared &p = prepared();
    const NormalBakeMesh source = normalBakeMesh(p.hi.positions, p.hi.normals, p.hi.triangles, p.hi.wedgeUv);
    const NormalBakeMesh target = normalBakeMesh(p.lo.positions, p.lo.normals, p.lo.triangles, p.lo.wedgeUv);
    NormalBakeOptions options;
    options.width = p.hi.textureWidth;
    options.height = p.hi.textureHeight;
    options.threads = int(state.range(0));
    options.level = int(state.range(1));
    NormalMap map;
    for (auto _ : state) {
        map = bakeNormalMap(source, target, options);
        benchmark::DoNotOptimize(map.rgba.data());
    }
    state.counters["source_faces"] = double(p.hi.faceCount());
    state.counters["target_faces"] = double(p.lo.faceCount());
    state.counters["width"] = map.width;
    state.counters["height"] = map.height;
    state.counters["texels"] = double(map.texelsBaked);
}
// Args: threads (0 = one per hardware thread), the map's level (0: the atlas' size, the goal's
// 8 texels per voxel; 1: half each side, NormalBakeOptions::level). Wall time (the goal) and the
// process' CPU time of all threads.
BENCHMARK(BM_BakeNormalMap)
    ->ArgNames({"threads", "level"})
    ->Args({1, 0})
    ->Args({0, 0})
    ->Args({1, 1})
    ->Args({0, 1})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void BM_MikkTSpace(benchmark::State &state, bool decimated) {
    const Prepared &p = prepared();
    const NormalBakeMesh mesh = decimated ? normalBakeMesh(p.lo.positions, p.lo.normals, p.lo.triangles, p.lo.wedgeUv)
                                          : normalBakeMesh(p.hi.positions, p.hi.normals, p.hi.triangles, p.hi.wedgeUv);
    for (auto _ : state)
        benchmark::DoNotOptimize(targetTangents(mesh).data());
    state.counters["faces"] = double(mesh.faceCount);
}
BENCHMARK_CAPTURE(BM_MikkTSpace, Decimated, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MikkTSpace, Faired, false)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
