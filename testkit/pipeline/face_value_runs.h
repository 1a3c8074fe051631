// One model through the paper's chain to its texture atlas with each triangle's palette index:
// what the per-voxel maps (maps/house_mask.h, maps/material_maps.h) bake from, and where their
// tests look. Shared by tests/maps/house_mask_test and tests/maps/material_maps_test.
#pragma once

#include "atlas/texel_raster.h"
#include "maps/face_value_bake.h"
#include "pipeline/pipeline_stages.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace voxelfair::pipeline {

struct FaceValueRun {
    QuadMesh mesh;  // faired (the paper's pass)
    Attributes attributes;
    TextureAtlas atlas;
    std::vector<uint8_t> paletteIndex;  // per triangle, its voxel's

    FaceValueMesh view() const {
        FaceValueMesh m;
        static_cast<TriangleMesh &>(m) = triangleMesh(mesh.positions, attributes.triangles);
        m.wedgeUv = atlas.layout.wedgeUv.data();
        return m;
    }
};

inline FaceValueRun faceValueRun(const Model &model) {
    FaceValueRun run;
    run.mesh = extract(model.scene);
    fair(run.mesh);
    run.attributes = smoothAttributes(run.mesh);
    run.atlas = buildAtlas(run.mesh, run.attributes);
    run.paletteIndex.resize(run.attributes.triangleCount());
    for (size_t t = 0; t < run.paletteIndex.size(); ++t)
        run.paletteIndex[t] = run.mesh.quadPaletteIndex[run.attributes.triangleQuad[t]];
    return run;
}

// Calls visit(face, x, y) with the texel (x, y up, clamped to the texture) of each of the interior
// points the atlas judges a face by (atlas/texel_raster.h faceInteriorPoints), for every face with
// area in a width x height texture.
template <class Visit>
void forEachInteriorTexel(const glm::vec2 *wedgeUv, size_t faceCount, int width, int height, Visit &&visit) {
    const glm::dvec2 extent(width, height);
    for (size_t f = 0; f < faceCount; ++f) {
        glm::dvec2 q[3], points[4];
        for (int k = 0; k < 3; ++k)
            q[k] = glm::dvec2(wedgeUv[3 * f + size_t(k)]) * extent;
        if (!(faceInteriorPoints(q, points) > 0))
            continue;
        for (const glm::dvec2 &p : points)
            visit(f, std::clamp(int(std::floor(p.x)), 0, width - 1), std::clamp(int(std::floor(p.y)), 0, height - 1));
    }
}

}  // namespace voxelfair::pipeline
