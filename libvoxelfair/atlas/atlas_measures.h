// Measures of an atlas, computed from its final float UVs and texture: what the tests assert
// and tools/atlas_report prints. All texel tests use texel_raster.h, like the bake.
#pragma once

#include "atlas/bake.h"
#include "atlas/charts.h"
#include "atlas/packing.h"

#include <cstddef>
#include <vector>

namespace voxelfair {

struct ChartStretch {
    // Over the chart's faces, of the map surface -> UV divided by the density: the largest
    // singular value (1 for an orthographic projection: lengths along the seed plane are kept)
    // and the inverse of the smallest (1 / cos of the face's angle to the seed normal, so at
    // most 1 / ChartOptions::minSeedCosine: 1.43 for the default 0.7). The second is Sander et
    // al.'s L-infinity stretch (2001). Degenerate faces are left out.
    double maxStretch = 0;
    double maxInverseStretch = 0;
};

struct AtlasMeasures {
    // Texels that two different charts both overlap (conservative coverage): must be 0.
    size_t overlappingChartTexels = 0;
    // Texel centres inside two UV triangles (top-left rule), also within one chart: catches a
    // chart folding onto itself. Must be 0.
    size_t overlappingCentres = 0;
    // Faces whose UV triangle has no positive area (double precision, from the float UVs): must be 0.
    size_t facesWithoutUvArea = 0;
    // Packing efficiency: texels the charts' triangles overlap (conservative coverage, the
    // texels the bake paints before dilation), over all texels.
    size_t coveredTexels = 0;
    double packingEfficiency = 0;
    // The same with texel centres only (the centre pass of the bake): a stricter count.
    double centreEfficiency = 0;
    // Worst over all charts (ChartStretch), and the surface-area-weighted mean of 1/cos.
    double maxStretch = 0;
    double maxInverseStretch = 0;
    double meanInverseStretch = 0;
    std::vector<ChartStretch> charts;
};

AtlasMeasures measureAtlas(const AtlasMesh &mesh, const AtlasCharts &charts, const AtlasLayout &layout);

// Colour fidelity of a crisp (FaceColours) texture: each face is sampled at four interior
// points of its UV triangle, the incentre and the points halfway from it to each corner, and a
// sample counts when the texture returns exactly the face's colour.
//   * nearest: the texel containing the point (GL_NEAREST), and every texel within kUvRounding
//     of it (texel_raster.h), where the UVs rounded in a text file may move it;
//   * bilinear: the four texel centres around it, weighted (GL_LINEAR, clamp to edge).
// Guarantee from the bake: a sample at distance r from the triangle's edges reads only texels
// whose centre is inside the face when r >= sqrt(2)/2 (nearest) or r >= sqrt(2) (bilinear).
// The halfway points are at half the inradius, so faces with a UV inradius of at least sqrt(2)
// texels (nearest) or 2 sqrt(2) (bilinear) are certain to match: guaranteedNearest/Bilinear
// count those faces' samples.
struct ColourFidelity {
    size_t samples = 0;
    size_t nearestMatches = 0, bilinearMatches = 0;
    size_t guaranteedNearest = 0, guaranteedNearestMatches = 0;
    size_t guaranteedBilinear = 0, guaranteedBilinearMatches = 0;
    double minInradius = 0;  // smallest UV inradius of a face, texels
    double nearest() const { return samples ? double(nearestMatches) / samples : 1.0; }
    double bilinear() const { return samples ? double(bilinearMatches) / samples : 1.0; }
};

ColourFidelity measureColourFidelity(const AtlasMesh &mesh, const AtlasLayout &layout, const AtlasTexture &texture);

}  // namespace voxelfair
