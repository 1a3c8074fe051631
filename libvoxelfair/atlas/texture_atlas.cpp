#include "atlas/texture_atlas.h"

#include "base/error.h"

#include <algorithm>
#include <cmath>

namespace voxelfair {
namespace {

// Packs the charts again after a separation; false, the layout left as it was, when they no
// longer fit any allowed texture (packCharts throws OptionError then).
bool repack(const AtlasCharts &charts, const PackOptions &pack, AtlasLayout &layout) {
    try {
        layout = packCharts(charts, pack);
        return true;
    } catch (const OptionError &) {
        return false;
    }
}

}  // namespace

TextureAtlas buildTextureAtlas(const AtlasMesh &mesh, const AtlasOptions &options) {
    TextureAtlas atlas;
    atlas.charts = computeCharts(mesh, options.charts);
    const bool crisp = options.maxSeparatedShare > 0 && options.bake.source == BakeSource::FaceColours &&
                       mesh.faceColours != nullptr && mesh.faceCount > 0;
    double separatedAt = 0;  // the density the charts were last separated for
    auto separate = [&](double density, double share) {
        atlas.crowded = separateCrowdedFaces(mesh, atlas.charts, {density, share, options.pack.threads});
        separatedAt = density;
        return atlas.crowded.separatedFaces > 0;
    };
    PackOptions pack = options.pack;
    if (crisp && pack.textureSize <= 0) {
        // Density mode. Where too many faces are crowded, each step of sqrt 2 moves interior
        // points apart by that factor: raise the density while the charts (twice their area for
        // gutters and packing) stay within the largest texture, then separate what is left.
        double density = pack.texelsPerUnit;
        // The charts' area, measured when first needed: a separation over the budget leaves the
        // charts as they were, so it is theirs before any separation.
        double area = -1;
        auto areaOf = [&] { return area >= 0 ? area : (area = atlas.charts.projectedArea()); };
        const double largest = double(std::clamp(pack.maxTextureSize, 1, 16384));
        separate(density, options.maxSeparatedShare);
        while (options.alwaysCrisp && atlas.crowded.overBudget() &&
               2 * areaOf() * (2 * density * density) <= largest * largest) {
            density *= std::sqrt(2.0);
            separate(density, options.maxSeparatedShare);
        }
        if (options.alwaysCrisp && atlas.crowded.overBudget())
            separate(density, 1.0);
        pack.texelsPerUnit = float(density);
        atlas.crispDensity = density;
    }
    atlas.layout = packCharts(atlas.charts, pack);
    // A fixed size (or the maximum size) sets the density only while packing: separate for the
    // density found, a little below it since the separated charts take room, and pack again.
    // Separating for a density serves every higher one. Separated charts lower the density, which
    // can crowd more faces: with alwaysCrisp they are separated too, round after round; without
    // it, if that ends over the budget, the first packing is kept (denser). Each repacking's
    // density search starts at the density the round before found (PackOptions::startDensity).
    AtlasCharts firstCharts;
    AtlasLayout firstLayout;
    CrowdedFaces firstCrowded;
    bool packed = true;  // false once the separated charts fit no allowed texture
    for (int round = 0; crisp && round < (options.alwaysCrisp ? 8 : 4) && packed; ++round) {
        const double found = atlas.layout.texelsPerUnit;
        if (found >= separatedAt && separatedAt > 0)
            break;
        if (round == 0) {
            firstCharts = atlas.charts;
            firstLayout = atlas.layout;
        }
        const bool fixed = options.pack.textureSize > 0 || atlas.layout.densityReduced;
        const bool separated =
            separate(fixed ? found * 0.98 : found, options.alwaysCrisp ? 1.0 : options.maxSeparatedShare);
        if (round == 0)
            firstCrowded = atlas.crowded;
        if (!separated)
            break;  // nothing more to separate: the layout stands
        pack.startDensity = found;
        packed = repack(atlas.charts, pack, atlas.layout);
    }
    atlas.crispGuaranteed = crisp && packed && !atlas.crowded.overBudget() && atlas.layout.texelsPerUnit >= separatedAt;
    // Kept as well when separating made the charts too many for a fixed size at any density (the
    // first charts are always kept by then: round 0 stores them before repacking).
    if (crisp && !atlas.crispGuaranteed && (!options.alwaysCrisp || !packed) && !firstCharts.chartAxis.empty()) {
        atlas.charts = std::move(firstCharts);
        atlas.layout = std::move(firstLayout);
        atlas.crowded = firstCrowded;
        atlas.crowded.separatedFaces = 0;
    }
    atlas.texture = bakeTexture(mesh, atlas.layout, options.bake);
    return atlas;
}

}  // namespace voxelfair
