// One model through the paper's chain to its texture atlas (pipeline_stages.h: extraction 4.2,
// the paper's fairing 4.3, attributes 4.4, atlas 4.5) and what the atlas's checks and reports
// measure of it (atlas/atlas_measures.h): coverage, overlaps, crisp colour fidelity, charts per
// thousand faces. Shared by tests/atlas/atlas_models_test and tools/atlas_report.
#pragma once

#include "atlas/atlas_measures.h"
#include "pipeline/pipeline_stages.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <vector>

namespace voxelfair::pipeline {

struct AtlasRun {
    QuadMesh mesh;  // faired
    Attributes attributes;
    TextureAtlas atlas;
    AtlasMeasures measures;
    ColourFidelity fidelity;
    double atlasMs = 0;  // the atlas alone, wall clock (for reports; tests do not time)

    size_t faceCount() const { return attributes.triangleCount(); }
    double chartsPerKiloFace() const {
        return faceCount() ? 1000.0 * double(atlas.charts.chartCount()) / double(faceCount()) : 0.0;
    }
};

// The chain at `options` (texelsPerUnit in texels per voxel edge, as buildAtlas takes it);
// nullopt when the model has no surface. Throws what buildTextureAtlas throws (base/error.h).
inline std::optional<AtlasRun> runAtlas(const Model &model, const AtlasOptions &options) {
    AtlasRun run;
    run.mesh = extract(model.scene);
    if (run.mesh.quadCount() == 0)
        return std::nullopt;
    fair(run.mesh);
    run.attributes = smoothAttributes(run.mesh);
    const auto t0 = std::chrono::steady_clock::now();
    run.atlas = buildAtlas(run.mesh, run.attributes, options);
    run.atlasMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const AtlasMesh view = atlasMesh(run.mesh, run.attributes);
    run.measures = measureAtlas(view, run.atlas.charts, run.atlas.layout);
    run.fidelity = measureColourFidelity(view, run.atlas.layout, run.atlas.texture);
    return run;
}

inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace voxelfair::pipeline
