// The filters as MeshLab runs them: our plugin's applyFilter on a CMeshO (conversions included)
// against MeshLab's own "Taubin Smooth" code path (vcglib's VertexCoordTaubin on the same CMeshO,
// lambda 0.5, mu -0.53, 10 steps, then UpdateBoxAndNormals like the filter), in one run.
//
// The mesh: the manifold boundary of a voxel sphere of radius 73 (about 100k vertices), imported
// exactly as io_vxl does.
#include "filter_voxelfair_plugin.h"
#include "scene_to_meshlab.h"

#include "fairing/lanczos_fairing.h"
#include "scene/voxel_scene.h"

#include <benchmark/benchmark.h>
#include <common/meshmodel.h>
#include <vcg/complex/algorithms/smooth.h>

#include <QApplication>
#include <memory>

using namespace voxelfair;

namespace {

VoxelVolume voxelSphere(int radius) {
    const int side = 2 * radius + 2;
    VoxelVolumeBuilder builder(side, side, side);
    const float c = float(side) / 2.0f;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            for (int z = 0; z < side; ++z) {
                const float dx = x + 0.5f - c, dy = y + 0.5f - c, dz = z + 0.5f - c;
                if (dx * dx + dy * dy + dz * dz <= float(radius * radius))
                    builder.add(x, y, z, Voxel{1, 0});
            }
    return builder.finish();
}

struct Fixture {
    VoxelVolume volume = voxelSphere(73);
    SceneSurface surface;
    MeshDocument document;
    MeshModel *original = nullptr;  // imported once; every iteration smooths a fresh copy

    Fixture() {
        VoxelScene scene;
        scene.parts.push_back(PlacedVolume{&volume, glm::mat4(1.0f), 0, "sphere"});
        surface = extractSceneSurface(scene);
        original = document.addNewMesh("", "sphere");
        original->Enable(sceneImportMask());
        sceneToMeshLab(surface, PaletteKind::Westwood, *original);
    }

    // A copy of the imported mesh, current in the document (what the filters act on).
    MeshModel *freshCopy() {
        MeshModel *copy = document.addNewMesh("", "copy", true);
        copy->updateDataMask(original);
        vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(copy->cm, original->cm);
        return copy;
    }
};

Fixture &fixture() {
    static Fixture f;
    return f;
}

QAction *findFilter(FilterVoxelfairPlugin &plugin, const QString &name) {
    for (QAction *a : plugin.actions())
        if (a->text() == name)
            return a;
    return nullptr;
}

void BM_LanczosFairingUnit(benchmark::State &state) {
    Fixture &f = fixture();
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> offsets(f.surface.quadCount() + 1);
    for (size_t q = 0; q <= f.surface.quadCount(); ++q)
        offsets[q] = uint32_t(4 * q);
    for (auto _ : state) {
        state.PauseTiming();
        positions = f.surface.positions;
        state.ResumeTiming();
        fairModifiedLanczos(
            {positions.data(), positions.size(), offsets.data(), f.surface.quads.data(), f.surface.quadCount()},
            nullptr, LanczosFairingOptions{});
        benchmark::DoNotOptimize(positions.data());
    }
    state.counters["vertices"] = double(f.surface.positions.size());
}

void BM_LanczosFairingFilterInMeshLab(benchmark::State &state) {
    Fixture &f = fixture();
    FilterVoxelfairPlugin plugin;
    QAction *action = findFilter(plugin, "Voxel Fairing: Modified Lanczos");
    RichParameterList parameters;
    plugin.initParameterSet(action, *f.original, parameters);
    for (auto _ : state) {
        state.PauseTiming();
        MeshModel *copy = f.freshCopy();
        state.ResumeTiming();
        if (!plugin.applyFilter(action, f.document, parameters, nullptr))
            state.SkipWithError("filter failed");
        state.PauseTiming();
        f.document.delMesh(copy);
        state.ResumeTiming();
    }
    state.counters["vertices"] = double(f.surface.positions.size());
}

void BM_TaubinSmoothInMeshLab(benchmark::State &state) {
    Fixture &f = fixture();
    for (auto _ : state) {
        state.PauseTiming();
        MeshModel *copy = f.freshCopy();
        state.ResumeTiming();
        // MeshLab's FP_TAUBIN_SMOOTH, filter_unsharp.cpp, with its defaults.
        vcg::tri::UpdateFlags<CMeshO>::FaceBorderFromNone(copy->cm);
        vcg::tri::Smooth<CMeshO>::VertexCoordTaubin(copy->cm, 10, 0.5f, -0.53f, false, nullptr);
        copy->UpdateBoxAndNormals();
        state.PauseTiming();
        f.document.delMesh(copy);
        state.ResumeTiming();
    }
    state.counters["vertices"] = double(f.surface.positions.size());
}

}  // namespace

BENCHMARK(BM_LanczosFairingUnit)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LanczosFairingFilterInMeshLab)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TaubinSmoothInMeshLab)->Unit(benchmark::kMillisecond);

int main(int argc, char **argv) {
    // MeshLab's plugin objects (QActions) want a Qt application; no display is needed.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    return 0;
}
