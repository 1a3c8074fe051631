#include "comparison_report/runs.h"

#include "smoothers/vcg_taubin.h"

#include "base/error.h"

#include <algorithm>
#include <chrono>
#include <limits>

namespace voxelfair::report {

namespace {

// Best of `repeats` timed runs of run(input) with input = make() (making it is not timed), so a
// stage that works in place always starts from the same data.
template <class Make, class Run>
double bestMs(int repeats, Make make, Run run) {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < repeats; ++i) {
        auto input = make();
        const auto t0 = std::chrono::steady_clock::now();
        run(input);
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

// Best of `repeats` timed runs of a stage that needs no fresh input.
template <class Run>
double bestMs(int repeats, Run run) {
    return bestMs(
        repeats, [] { return 0; }, [&](int) { run(); });
}

// Attribute smoothing and, when asked, the atlas for a smoothed surface, timed; then the surface
// placed in model space for the pictures.
void finishVariant(Variant &v, const pipeline::Model &model, bool atlas) {
    v.attributesMs = bestMs(kRepeats, [&] { v.attributes = pipeline::smoothAttributes(v.mesh); });
    v.displayPositions = pipeline::displayPositions(v.mesh, model);
    v.displayNormals = pipeline::displayNormals(v.mesh, model, v.attributes.vertexNormals);
    if (!atlas)
        return;
    try {
        v.atlasMs = bestMs(kRepeats, [&] { v.atlas = pipeline::buildAtlas(v.mesh, v.attributes); });
    } catch (const Error &e) {
        v.atlasError = e.what();
        return;
    }
    v.hasAtlas = v.atlas.charts.faceCount() > 0;
    if (!v.hasAtlas)
        v.atlasError = "no faces";
    if (v.hasAtlas)
        v.atlasVertices = pipeline::atlasVertexCount(v.atlas, v.attributes);
}

}  // namespace

ModelRun runChain(const pipeline::Model &model, const std::string &kind) {
    ModelRun run;
    run.name = model.name;
    run.kind = kind;
    run.palette = model.paletteSource;
    run.boxVoxels = model.boxVoxels();
    run.solidVoxels = model.solidVoxels();
    run.parts = model.scene.parts.size();

    run.extractMs = bestMs(kRepeats, [&] { run.raw.mesh = pipeline::extract(model.scene); });
    run.raw.name = "raw voxels";
    finishVariant(run.raw, model, false);

    run.ours.name = "ours (paper, 1 pass)";
    run.ours.smoothMs = bestMs(
        kRepeats, [&] { return run.raw.mesh; },
        [&](pipeline::QuadMesh &m) {
            pipeline::fair(m);
            run.ours.mesh = std::move(m);
        });
    finishVariant(run.ours, model, true);

    run.hasConstrained = true;
    run.constrained.name = "constrained";
    run.constrained.smoothMs = bestMs(
        kRepeats, [&] { return run.raw.mesh; },
        [&](pipeline::QuadMesh &m) {
            pipeline::fairConstrainedMode(m);
            run.constrained.mesh = std::move(m);
        });
    finishVariant(run.constrained, model, true);

#ifdef VOXELFAIR_HAVE_VCGLIB
    // MeshLab holds the a-c triangulation; its Taubin Smooth runs on that (testkit/smoothers/vcg_taubin.h).
    run.hasTaubin = true;
    run.taubin.name = "Taubin (10 steps)";
    run.taubin.mesh = run.raw.mesh;
    run.taubinToVcgMs = bestMs(
        kRepeats, [] { return std::make_unique<vcgtaubin::Mesh>(); },
        [&](std::unique_ptr<vcgtaubin::Mesh> &m) {
            vcgtaubin::build(*m, run.raw.mesh.positions, run.raw.attributes.triangles);
        });
    std::unique_ptr<vcgtaubin::Mesh> smoothed;
    run.taubin.smoothMs = bestMs(
        kRepeats,
        [&] {
            auto m = std::make_unique<vcgtaubin::Mesh>();
            vcgtaubin::build(*m, run.raw.mesh.positions, run.raw.attributes.triangles);
            return m;
        },
        [&](std::unique_ptr<vcgtaubin::Mesh> &m) {
            vcgtaubin::taubinLikeMeshLab(*m);
            smoothed = std::move(m);
        });
    for (size_t i = 0; i < run.taubin.mesh.positions.size(); ++i) {
        const vcg::Point3f &p = smoothed->vert[i].cP();
        run.taubin.mesh.positions[i] = glm::vec3(p[0], p[1], p[2]);
    }
    finishVariant(run.taubin, model, true);
    // MeshLab's HC Laplacian and TwoStep Smooth, the same way (testkit/smoothers/vcg_smoothers.h).
    run.hasOtherMeshLab = true;
    run.hc.name = "HC Laplacian";
    run.hc.mesh = run.raw.mesh;
    run.hc.smoothMs = bestMs(1, [&] { vcgsmooth::hcLaplacian(run.hc.mesh.positions, run.raw.attributes.triangles); });
    finishVariant(run.hc, model, false);
    run.twoStep.name = "TwoStep";
    run.twoStep.mesh = run.raw.mesh;
    run.twoStep.smoothMs =
        bestMs(1, [&] { vcgsmooth::twoStep(run.twoStep.mesh.positions, run.raw.attributes.triangles); });
    finishVariant(run.twoStep, model, false);
#endif
#ifdef VOXELFAIR_HAVE_VTK
    run.hasVtk = true;
    run.vtk = lineup::vtkSurface(model);
#endif
    return run;
}

}  // namespace voxelfair::report
