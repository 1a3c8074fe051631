#include "maps/face_value_bake.h"

#include "atlas/atlas_mesh.h"
#include "atlas/bake.h"
#include "atlas/packing.h"
#include "base/error.h"

#include <string>
#include <utility>

namespace voxelfair {

FaceValueImage bakeFaceValues(const FaceValueMesh &mesh, const glm::u8vec3 *faceValues, int width, int height,
                              int dilation, glm::u8vec3 background, bool blocks) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw OptionError("face value bake: the image size " + std::to_string(width) + " x " + std::to_string(height) +
                          " is outside 1..16384");
    if (dilation < 0)
        throw OptionError("face value bake: the dilation must not be negative");
    if (mesh.faceCount > 0 &&
        (mesh.positions == nullptr || mesh.triangles == nullptr || mesh.wedgeUv == nullptr || faceValues == nullptr))
        throw MeshError("face value bake: positions, triangles, UVs and values are required for every face");
    for (size_t i = 0; i < 3 * mesh.faceCount; ++i)
        if (mesh.triangles[i] >= mesh.vertexCount)
            throw MeshError("face value bake: face " + std::to_string(i / 3) + " uses vertex " +
                            std::to_string(mesh.triangles[i]) + " of " + std::to_string(mesh.vertexCount));

    FaceValueImage out;
    out.width = width;
    out.height = height;
    if (mesh.faceCount == 0) {
        out.rgba.assign(size_t(width) * size_t(height) * 4, 0);
        for (size_t i = 0; i < out.rgba.size(); i += 4)
            out.rgba[i] = background.r, out.rgba[i + 1] = background.g, out.rgba[i + 2] = background.b;
        return out;
    }
    // The atlas' crisp bake with the values as face colours: the same texels per face.
    AtlasMesh atlasMesh;
    static_cast<TriangleMesh &>(atlasMesh) = mesh;
    atlasMesh.faceColours = faceValues;
    AtlasLayout layout;
    layout.size = layout.width = width;
    layout.height = height;
    layout.gutter = 2 * dilation;
    layout.block = blocks ? 2 : 1;
    layout.wedgeUv.assign(mesh.wedgeUv, mesh.wedgeUv + 3 * mesh.faceCount);
    BakeOptions options;
    options.source = BakeSource::FaceColours;
    options.dilation = dilation;
    options.background = glm::u8vec4(background, 0);
    AtlasTexture texture = bakeTexture(atlasMesh, layout, options);
    if (texture.rgba.size() != size_t(width) * size_t(height) * 4)
        throw MeshError("face value bake: the atlas bake gave no image for this mesh");
    out.rgba = std::move(texture.rgba);
    return out;
}

}  // namespace voxelfair
