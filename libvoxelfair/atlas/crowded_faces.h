// Between charts and packing, for crisp colours: faces too thin for the texel grid get their own
// charts, so that every interior point of every face (faceInteriorPoints: the incentre and the
// points halfway to the corners) reads that face's colour in the baked texture.
//
// Why this is enough. The bake (bake.h) settles each face's interior points in one of two ways:
//   * a face whose UV inradius is at least sqrt(2) texels holds the centre of the texel under
//     each of its interior points, so it painted those texels itself;
//   * a thinner ("thin") face paints the texels under its interior points last.
// A texel is painted wrong for some face only if it lies under interior points of two faces of
// different colours, at least one of them thin. Two points less than sqrt(2) texels apart may
// share a texel, points further apart never do, wherever the packer puts the chart and however
// it turns it. Faces of different charts never share texels (packing keeps a gutter). So if no
// thin face has an interior point within sqrt(2) texels of an interior point of a differently
// coloured face of its chart, every sample reads its face's colour.
//
// What it does. Chart by chart, such "crowded" thin faces are found with a grid over the thin
// faces' interior points, then separated thinnest first until none is left with a crowded
// partner (the thicker of two thin faces usually stays). A separated face is projected onto its own
// plane, so its stretch is 1; the charts it leaves keep theirs, re-boxed to the origin.
//
// Cost. Only charts holding a thin face and more than one colour are searched; at 8 texels per
// voxel a faired voxel model has few thin faces (the slivers the fairing squeezes). At 2 texels
// per voxel almost every voxel triangle is thin and pixel-art colours crowd almost all of them:
// a texture that coarse cannot keep every voxel, and separating half the mesh into one-face
// charts would ruin the atlas. Past `maxSeparatedShare` of the faces the search stops, nothing
// is separated and the result says so, for the caller to report.
#pragma once

#include "atlas/atlas_mesh.h"
#include "atlas/charts.h"

#include <cstddef>

namespace voxelfair {

struct CrowdedFaceOptions {
    // The density the atlas will be packed at (PackOptions::texelsPerUnit or the density found).
    // Separating at a density also serves every higher one: points only move apart.
    double texelsPerUnit = 4.0;
    // The most faces separated, as a share of all faces; beyond it none is.
    double maxSeparatedShare = 0.1;
    // Threads searching the charts and rebuilding them (0: one per hardware thread); the result is
    // the same for any count.
    int threads = 0;
};

struct CrowdedFaces {
    size_t thinFaces = 0;  // UV inradius under sqrt(2) texels (with a 0.01 texel margin)
    // Thin faces that need their own chart. Over the budget the search stops: then it counts
    // those found until the budget was passed, and thinFaces those seen until then.
    size_t crowdedFaces = 0;
    size_t separatedFaces = 0;  // crowdedFaces, or 0 when over the budget
    bool overBudget() const { return crowdedFaces != separatedFaces; }
};

// Needs the mesh's face colours (does nothing without them) and charts computed from this mesh.
CrowdedFaces separateCrowdedFaces(const AtlasMesh &mesh, AtlasCharts &charts, const CrowdedFaceOptions &options);

}  // namespace voxelfair
