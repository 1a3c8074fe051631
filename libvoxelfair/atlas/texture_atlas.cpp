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
    // Separating for a density serves every higher one.
    for (int round = 0; crisp && round < 4 && atlas.layout.status == AtlasStatus::Ok; ++round) {
        const double found = atlas.layout.texelsPerUnit;
        if (found >= separatedAt && separatedAt > 0)
            break;
        const bool fixed = options.pack.textureSize > 0 || atlas.layout.densityReduced;
        if (!separate(fixed ? found * 0.98 : found))
            break;  // nothing more to separate: the layout stands
        atlas.layout = packCharts(atlas.charts, options.pack);
    }
    atlas.crispGuaranteed = crisp && atlas.layout.status == AtlasStatus::Ok && !atlas.crowded.overBudget() &&
                            atlas.layout.texelsPerUnit >= separatedAt;
    atlas.texture = bakeTexture(mesh, atlas.layout, options.bake);
    return atlas;
}

}  // namespace voxelfair
