#include "atlas/texture_atlas.h"

namespace voxelfair {

TextureAtlas buildTextureAtlas(const AtlasMesh &mesh, const AtlasOptions &options) {
    TextureAtlas atlas;
    atlas.charts = computeCharts(mesh, options.charts);
    atlas.layout = packCharts(atlas.charts, options.pack);
    atlas.texture = bakeTexture(mesh, atlas.layout, options.bake);
    return atlas;
}

}  // namespace voxelfair
