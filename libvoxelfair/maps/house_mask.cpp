#include "maps/house_mask.h"

#include "base/error.h"

namespace voxelfair {

HouseMask bakeHouseMask(const FaceValueMesh &mesh, const uint8_t *facePaletteIndex, int width, int height, int dilation,
                        bool blocks) {
    if (mesh.faceCount > 0 && facePaletteIndex == nullptr)
        throw MeshError("house mask: every face needs its palette index");
    HouseMask out;
    std::vector<glm::u8vec3> values(mesh.faceCount);
    for (size_t f = 0; f < mesh.faceCount; ++f) {
        const bool house = isRemapIndex(facePaletteIndex[f]);
        out.houseFaces += house ? 1 : 0;
        values[f] = glm::u8vec3(house ? 255 : 0);
    }
    // The image with its gutter rings; the chart texels counted on a bake without them.
    const FaceValueImage image = bakeFaceValues(mesh, values.data(), width, height, dilation, {0, 0, 0}, blocks);
    out.width = image.width;
    out.height = image.height;
    out.grey.resize(size_t(width) * size_t(height));
    for (size_t i = 0; i < out.grey.size(); ++i)
        out.grey[i] = image.rgba[4 * i];
    if (out.houseFaces > 0) {
        const FaceValueImage charts = bakeFaceValues(mesh, values.data(), width, height, 0);
        for (size_t i = 0; i < out.grey.size(); ++i)
            out.houseTexels += charts.rgba[4 * i] == 255 ? 1 : 0;
    }
    return out;
}

}  // namespace voxelfair
