#include "atlas/texture_atlas.h"

namespace voxelfair {

TextureAtlas buildTextureAtlas(const AtlasMesh &mesh, const AtlasOptions &options) {
    TextureAtlas atlas;
    atlas.charts = computeCharts(mesh, options.charts);
    const bool crisp = options.maxSeparatedShare > 0 && options.bake.source == BakeSource::FaceColours &&
                       mesh.faceColours != nullptr && atlas.charts.status == AtlasStatus::Ok;
    double separatedAt = 0;  // the density the charts were last separated for
    auto separate = [&](double density) {
        atlas.crowded = separateCrowdedFaces(mesh, atlas.charts, {density, options.maxSeparatedShare});
        separatedAt = density;
        return atlas.crowded.separatedFaces > 0;
    };
    if (crisp && options.pack.textureSize <= 0)
        separate(options.pack.texelsPerUnit);
    atlas.layout = packCharts(atlas.charts, options.pack);
    // A fixed size (or the maximum size) sets the density only while packing: separate for the
    // density found, a little below it since the separated charts take room, and pack again.
    // Separating for a density serves every higher one. Separated charts lower the density, which
    // can crowd more faces; if that ends over the budget, the first packing is kept (denser).
    AtlasCharts firstCharts;
    AtlasLayout firstLayout;
    CrowdedFaces firstCrowded;
    for (int round = 0; crisp && round < 4 && atlas.layout.status == AtlasStatus::Ok; ++round) {
        const double found = atlas.layout.texelsPerUnit;
        if (found >= separatedAt && separatedAt > 0)
            break;
        if (round == 0) {
            firstCharts = atlas.charts;
            firstLayout = atlas.layout;
        }
        const bool fixed = options.pack.textureSize > 0 || atlas.layout.densityReduced;
        const bool separated = separate(fixed ? found * 0.98 : found);
        if (round == 0)
            firstCrowded = atlas.crowded;
        if (!separated)
            break;  // nothing more to separate: the layout stands
        atlas.layout = packCharts(atlas.charts, options.pack);
    }
    atlas.crispGuaranteed = crisp && atlas.layout.status == AtlasStatus::Ok && !atlas.crowded.overBudget() &&
                            atlas.layout.texelsPerUnit >= separatedAt;
    if (crisp && !atlas.crispGuaranteed && !firstCharts.chartAxis.empty()) {
        atlas.charts = std::move(firstCharts);
        atlas.layout = std::move(firstLayout);
        atlas.crowded = firstCrowded;
        atlas.crowded.separatedFaces = 0;
    }
    atlas.texture = bakeTexture(mesh, atlas.layout, options.bake);
    return atlas;
}

}  // namespace voxelfair
