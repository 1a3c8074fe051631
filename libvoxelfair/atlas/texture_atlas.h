// Section 4.5 of the paper, "Texture atlas extraction", as one call: charts (charts.h), packing
// (packing.h), baked diffuse texture (bake.h); for crisp colours, faces too thin for the texel
// grid are separated between charts and packing (crowded_faces.h). Like xatlas the stages can also be run one by
// one, e.g. to repack or rebake with other options without recomputing the charts.
//
//   AtlasMesh mesh;  mesh.positions = ...; mesh.triangles = ...; mesh.faceColours = ...;
//   TextureAtlas atlas = buildTextureAtlas(mesh);  // throws MeshError / OptionError (base/error.h)
//   // atlas.layout.wedgeUv: 3 UVs per face; atlas.texture.rgba: the image, top row first.
#pragma once

#include "atlas/atlas_mesh.h"
#include "atlas/bake.h"
#include "atlas/charts.h"
#include "atlas/crowded_faces.h"
#include "atlas/packing.h"

#include <string>

namespace voxelfair {

struct AtlasOptions {
    ChartOptions charts;
    PackOptions pack;
    BakeOptions bake;
    // Crisp bakes only: give crowded thin faces their own charts (crowded_faces.h), so every
    // interior point of every face reads its face's colour. When more than this share of the
    // faces would need it (a density too coarse for the model), alwaysCrisp decides: raise the
    // density instead (steps of sqrt 2, density mode, while the charts' area fits the largest
    // texture), else separate them all; without alwaysCrisp nothing is separated and the
    // result says so (crispGuaranteed false). 0 turns the separation off.
    double maxSeparatedShare = 0.1;
    bool alwaysCrisp = true;
};

struct TextureAtlas {
    AtlasCharts charts;
    AtlasLayout layout;
    AtlasTexture texture;
    // The separation of crowded faces that the layout was packed after, and whether every
    // interior point of every face is sure to read its face's colour (crisp bake, nothing over
    // the budget, and the packing density no lower than the one separated for). When it is not,
    // crowded.crowdedFaces counts the faces that may read a neighbour's colour somewhere.
    CrowdedFaces crowded;
    bool crispGuaranteed = false;
    // The least density the layout was packed for, raised from PackOptions::texelsPerUnit when
    // too many faces were crowded at it (alwaysCrisp); 0 with a fixed texture size.
    double crispDensity = 0;
};

// Throws what the stages throw: MeshError for an invalid mesh, OptionError for options out of range
// or charts that fit no allowed texture. A mesh without faces gives an empty atlas (no charts, a
// layout and texture of size 0).
TextureAtlas buildTextureAtlas(const AtlasMesh &mesh, const AtlasOptions &options = {});

}  // namespace voxelfair
