// The paper's Table 1 (time per stage) and Table 2 (counts) on the shared real models, how each
// stage grows with the surface, and the whole chain on models of the paper's largest size.
//
//   Table1/<stage>/<model>        extraction, fairing, attributes, atlas (charts + packing + baked
//                                 texture) and its parts atlas_charts / atlas_pack / atlas_bake;
//                                 taubin10 = MeshLab's Taubin Smooth (vcglib, 10 steps) beside ours.
//                                 Counters (Table 2): voxels (bounding boxes), opaque voxels,
//                                 vertices and quads extracted, triangles, atlas vertices (seams
//                                 cloned), charts, texture side.
//   Scaling/<stage>/sphere_r<R>   the same stages on voxel spheres of radius 8 to 120.
//   Chain/<model>                 extraction to baked texture in one go. Goal: the paper's largest
//                                 model size (~63k opaque voxels; its Table 1: 7.1 s) within 100 ms.
//   Chain8TexelsPerVoxel/tank63k  the same at the filter's default density.
//   Parse/<model>                 the .vxl/.hva bytes (already in memory) to a scene.
//
// VXL sections are meshed in their own voxel units, as the authors did (testkit/pipeline/pipeline_stages.h).
// Our models against the paper's rows, by size: truckc ~ Demo Truck (7893 opaque voxels), cc ~
// Kirov (35841), legs ~ Yuri Head (42733), subapc (52095) and tank63k (synthetic) ~ Warhammer (63150).
#include "pipeline/pipeline_stages.h"
#include "shapes/synthetic_tank.h"
#include "smoothers/vcg_taubin.h"
#include "shapes/analytic_shapes.h"

#include <benchmark/benchmark.h>

#include <exception>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace voxelfair;

namespace {

const std::string kModels = VOXELFAIR_MODELS_DIR;

std::unique_ptr<pipeline::Model> loadModel(const std::string &name) {
    if (name == "tank63k")
        return pipeline::syntheticTankModel();
    if (name.rfind("sphere_r", 0) == 0) {
        const double r = std::stod(name.substr(8));
        // A sub-voxel offset puts the surface in general position on the lattice.
        const shapes::Shape sphere = shapes::sphere(glm::dvec3(r + 2.31, r + 2.17, r + 2.43), r);
        Palette palette;
        palette.colours[1] = {214, 128, 64};
        palette.colours[2] = {72, 132, 190};
        return pipeline::volumeModel(name,
                                     shapes::voxelize(sphere,
                                                      [](int x, int y, int z) {
                                                          return Voxel{uint8_t(1 + (x / 4 + y / 4 + z / 4) % 2), 0};
                                                      }),
                                     palette);
    }
    return pipeline::loadVxl(kModels + "/vxl/" + name + ".vxl", kModels + "/pal");
}

// Every stage's output computed once, so each benchmark times one stage on its real input.
struct Prepared {
    std::unique_ptr<pipeline::Model> model;
    std::string error;  // why the model could not be loaded
    pipeline::QuadMesh raw, faired;
    pipeline::Attributes attributes;
    AtlasMesh atlasMesh;
    PackOptions pack;
    AtlasCharts charts;
    AtlasLayout layout;
    size_t atlasVertices = 0;
    int textureSize = 0;
    CrowdedFaces crowded;  // crisp colours: thin faces crowded by other colours (crowded_faces.h)
#ifdef VOXELFAIR_HAVE_VCGLIB
    // The raw surface as MeshLab holds it (a-c triangles); the Taubin benchmark smooths it in place.
    mutable vcgtaubin::Mesh taubinMesh;
#endif
};

const Prepared &prepared(const std::string &name) {
    static std::map<std::string, std::unique_ptr<Prepared>> cache;
    std::unique_ptr<Prepared> &slot = cache[name];
    if (slot)
        return *slot;
    slot = std::make_unique<Prepared>();
    Prepared &p = *slot;
    try {
        p.model = loadModel(name);
    } catch (const std::exception &e) {
        p.error = e.what();
        return p;
    }
    p.raw = pipeline::extract(p.model->scene);
    p.faired = p.raw;
    pipeline::fair(p.faired);
    p.attributes = pipeline::smoothAttributes(p.faired);
    p.atlasMesh = pipeline::atlasMesh(p.faired, p.attributes);
    p.pack.texelsPerUnit /= p.faired.voxelSize;  // as pipeline::buildAtlas
    p.charts = computeCharts(p.atlasMesh);
    p.layout = packCharts(p.charts, p.pack);
    const TextureAtlas atlas = pipeline::buildAtlas(p.faired, p.attributes);
    p.atlasVertices = pipeline::atlasVertexCount(atlas, p.attributes);
    p.textureSize = atlas.texture.size;
    p.crowded = atlas.crowded;
#ifdef VOXELFAIR_HAVE_VCGLIB
    vcgtaubin::build(p.taubinMesh, p.raw.positions, p.attributes.triangles);
#endif
    return p;
}

// Table 2's figures, on every benchmark of a model.
void setCounters(benchmark::State &state, const Prepared &p) {
    state.counters["voxels"] = double(p.model->boxVoxels());
    state.counters["opaque"] = double(p.model->solidVoxels());
    state.counters["vertices"] = double(p.raw.vertexCount());
    state.counters["quads"] = double(p.raw.quadCount());
    state.counters["triangles"] = double(p.attributes.triangleCount());
    state.counters["atlas_vertices"] = double(p.atlasVertices);
    state.counters["charts"] = double(p.charts.chartCount());
    state.counters["texture"] = double(p.textureSize);
    state.counters["thin"] = double(p.crowded.thinFaces);
    state.counters["crowded"] = double(p.crowded.crowdedFaces);
    state.counters["separated"] = double(p.crowded.separatedFaces);
}

using Stage = void (*)(benchmark::State &, const Prepared &);

// Prepares the model (outside the timing), runs the stage, sets the counters; or skips.
void runStage(benchmark::State &state, const std::string &name, Stage stage) {
    const Prepared &p = prepared(name);
    if (!p.model) {
        state.SkipWithError(("cannot load " + name + ": " + p.error).c_str());
        return;
    }
    stage(state, p);
    setCounters(state, p);
}

void extraction(benchmark::State &state, const Prepared &p) {
    for (auto _ : state)
        benchmark::DoNotOptimize(pipeline::extract(p.model->scene).positions.data());
}

// One pass with adjacency and validation, as the filter calls it; the copy of the input is not timed.
void fairing(benchmark::State &state, const Prepared &p) {
    std::vector<glm::vec3> positions;
    LanczosFairingOptions options;
    options.voxelSize = p.raw.voxelSize;
    for (auto _ : state) {
        state.PauseTiming();
        positions = p.raw.positions;
        state.ResumeTiming();
        fairModifiedLanczos(
            {positions.data(), positions.size(), p.raw.offsets.data(), p.raw.quads.data(), p.raw.quadCount()}, nullptr,
            options);
        benchmark::DoNotOptimize(positions.data());
    }
}

void attributes(benchmark::State &state, const Prepared &p) {
    for (auto _ : state)
        benchmark::DoNotOptimize(pipeline::smoothAttributes(p.faired).triangles.data());
}

void atlas(benchmark::State &state, const Prepared &p) {
    for (auto _ : state)
        benchmark::DoNotOptimize(pipeline::buildAtlas(p.faired, p.attributes).texture.rgba.data());
}

void atlasCharts(benchmark::State &state, const Prepared &p) {
    for (auto _ : state)
        benchmark::DoNotOptimize(computeCharts(p.atlasMesh).wedgeUv.data());
}

void atlasPack(benchmark::State &state, const Prepared &p) {
    for (auto _ : state)
        benchmark::DoNotOptimize(packCharts(p.charts, p.pack).wedgeUv.data());
}

void atlasBake(benchmark::State &state, const Prepared &p) {
    for (auto _ : state)
        benchmark::DoNotOptimize(bakeTexture(p.atlasMesh, p.layout).rgba.data());
}

#ifdef VOXELFAIR_HAVE_VCGLIB
// The filter body on the mesh MeshLab already holds. Its speed does not depend on the shape, so
// iterating on the already smoothed mesh is fair (as in fairing_benchmark).
void taubin10(benchmark::State &state, const Prepared &p) {
    vcgtaubin::Mesh &mesh = p.taubinMesh;
    for (auto _ : state) {
        vcgtaubin::taubinLikeMeshLab(mesh, 10, 0.5f, -0.53f);
        benchmark::DoNotOptimize(mesh.vert.data());
    }
}
#endif

// Extraction to baked texture, every stage's output allocated afresh as a caller would, at
// `texelsPerVoxel` (4: the atlas unit's default; 8: the filter's).
void chainAt(benchmark::State &state, const Prepared &p, float texelsPerVoxel) {
    AtlasOptions options;
    options.pack.texelsPerUnit = texelsPerVoxel;
    TextureAtlas atlas;
    for (auto _ : state) {
        pipeline::QuadMesh mesh = pipeline::extract(p.model->scene);
        pipeline::fair(mesh);
        const pipeline::Attributes a = pipeline::smoothAttributes(mesh);
        atlas = pipeline::buildAtlas(mesh, a, options);
        benchmark::DoNotOptimize(atlas.texture.rgba.data());
    }
    state.counters["texture_at_density"] = atlas.texture.size;
    state.counters["separated_at_density"] = double(atlas.charts.separatedFaces);
}
void chain(benchmark::State &state, const Prepared &p) { chainAt(state, p, 4.0f); }
void chainAt8(benchmark::State &state, const Prepared &p) { chainAt(state, p, 8.0f); }

void parseVxl(benchmark::State &state, const std::string &name) {
    std::vector<uint8_t> vxlBytes, hvaBytes;
    try {
        vxlBytes = readFileBytes(kModels + "/vxl/" + name + ".vxl");
        hvaBytes = readFileBytes(kModels + "/vxl/" + name + ".hva");
    } catch (const std::exception &e) {
        state.SkipWithError(e.what());
        return;
    }
    for (auto _ : state) {
        const VxlModel model = readVxl(vxlBytes.data(), vxlBytes.size());
        const HvaAnimation hva = readHva(hvaBytes.data(), hvaBytes.size());
        VxlSceneOptions options;
        options.applyTransforms = false;
        benchmark::DoNotOptimize(vxlScene(model, &hva, options).parts.data());
    }
}

struct NamedStage {
    const char *name;
    Stage stage;
};

const std::vector<NamedStage> &stages() {
    static const std::vector<NamedStage> list = {
        {"extraction", extraction},    {"fairing", fairing},      {"attributes", attributes}, {"atlas", atlas},
        {"atlas_charts", atlasCharts}, {"atlas_pack", atlasPack}, {"atlas_bake", atlasBake},
#ifdef VOXELFAIR_HAVE_VCGLIB
        {"taubin10", taubin10},
#endif
    };
    return list;
}

void registerStages(const std::string &group, const std::string &model) {
    for (const NamedStage &s : stages())
        benchmark::RegisterBenchmark((group + "/" + s.name + "/" + model).c_str(), [model, stage = s.stage](
                                                                                       benchmark::State &state) {
            runStage(state, model, stage);
        })->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char **argv) {
    // Table 1 / Table 2: the shared models with more than a few hundred voxels, then the synthetic tank.
    const std::vector<std::string> table1 = {"truckc", "jeep", "3tnktur", "3tnk",   "yaggun", "hind",
                                             "hmec",   "cc",   "legs",    "subapc", "tank63k"};
    for (const std::string &model : table1)
        registerStages("Table1", model);
    for (int radius : {8, 16, 32, 64, 120})
        registerStages("Scaling", "sphere_r" + std::to_string(radius));
    for (const std::string model : {"truckc", "cc", "legs", "subapc", "tank63k"})
        benchmark::RegisterBenchmark(("Chain/" + model).c_str(), [model](benchmark::State &state) {
            runStage(state, model, chain);
        })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("Chain8TexelsPerVoxel/tank63k", [](benchmark::State &state) {
        runStage(state, "tank63k", chainAt8);
    })->Unit(benchmark::kMillisecond);
    for (const std::string model : {"subapc", "legs"})
        benchmark::RegisterBenchmark(("Parse/" + model).c_str(), [model](benchmark::State &state) {
            parseVxl(state, model);
        })->Unit(benchmark::kMillisecond);

    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
