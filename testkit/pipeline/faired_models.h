// Real faired meshes for the maps' tests, tools and benchmark: a shared model (or a volume) through
// the paper's chain as the pipeline runs it (tools/pipeline_stages.h: extraction 4.2, fairing
// 4.3, attributes 4.4, atlas 4.5), in model space (parts placed, as the importer places them),
// with the 4.4 vertex normals and the atlas' UVs; then MeshLab's decimation with texture
// (vcg_quadric_tex.h) when vcglib is there.
#pragma once

#include "pipeline/pipeline_stages.h"
#include "maps/normal_bake.h"
#include "smoothers/vcg_quadric_tex.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace voxelfair::mapstest {

struct FairedMesh {
    std::string name;
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> triangles;
    std::vector<glm::vec2> wedgeUv;
    int textureWidth = 0, textureHeight = 0;  // the atlas texture (width >= height)
    float voxelSize = 1.0f;
    size_t faceCount() const { return triangles.size() / 3; }
};

// The model's faired, textured triangle mesh at `texelsPerVoxel`.
inline FairedMesh fairedMesh(const pipeline::Model &model, float texelsPerVoxel) {
    pipeline::QuadMesh mesh = pipeline::extract(model.scene);
    pipeline::fair(mesh);
    const pipeline::Attributes chain = pipeline::smoothAttributes(mesh);
    FairedMesh out;
    out.name = model.name;
    out.positions = pipeline::displayPositions(mesh, model);
    out.normals = pipeline::displayNormals(mesh, model, chain.vertexNormals);
    out.triangles = chain.triangles;
    // Placed parts may have other voxel sizes (HVA scales): the largest part's voxel is the unit.
    std::vector<size_t> partQuads(model.toDisplay.size(), 0);
    for (uint32_t part : mesh.quadPart)
        ++partQuads[part];
    const size_t largest = size_t(std::max_element(partQuads.begin(), partQuads.end()) - partQuads.begin());
    const float scale = std::cbrt(std::abs(glm::determinant(glm::mat3(model.toDisplay[largest]))));
    pipeline::QuadMesh placed = mesh;
    placed.positions = out.positions;
    placed.voxelSize = mesh.voxelSize * (scale > 0.0f && std::isfinite(scale) ? scale : 1.0f);
    out.voxelSize = placed.voxelSize;
    AtlasOptions options;
    options.pack.texelsPerUnit = texelsPerVoxel;
    const TextureAtlas atlas = pipeline::buildAtlas(placed, chain, options);
    out.wedgeUv = atlas.layout.wedgeUv;
    out.textureWidth = atlas.layout.width;
    out.textureHeight = atlas.layout.height;
    return out;
}

// The shared models (pipeline::sharedModels) for the maps' tests and benchmark.
using pipeline::sharedModels;

}  // namespace voxelfair::mapstest
