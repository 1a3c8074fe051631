// One input through the chain (paper §4.2-4.5) and through the comparison smoothers, each stage
// timed (best of kRepeats runs in this process, one thread).
#pragma once

#include "pipeline/pipeline_stages.h"
#include "shapes/analytic_shapes.h"
#include "smoother_lineup.h"

#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace voxelfair::report {

// One smoothing of the extracted surface and what the later stages made of it.
struct Variant {
    std::string name;
    pipeline::QuadMesh mesh;  // positions after smoothing (raw: as extracted)
    pipeline::Attributes attributes;
    double smoothMs = 0, attributesMs = 0, atlasMs = 0;
    TextureAtlas atlas;
    size_t atlasVertices = 0;
    bool hasAtlas = false;
    std::string atlasError;                                   // why there is no atlas, when there is none
    std::vector<glm::vec3> displayPositions, displayNormals;  // model space, for pictures
};

struct ModelRun {
    std::string name;
    std::string kind;  // "VXL", "VOX", "shape"
    std::string palette;
    size_t boxVoxels = 0, solidVoxels = 0, parts = 0;
    double extractMs = 0;
    double taubinToVcgMs = 0;                             // building vcglib's mesh, which MeshLab already holds
    Variant raw, ours, taubin, constrained, hc, twoStep;  // hc, twoStep: MeshLab's (smoother_lineup.h)
    bool hasTaubin = false, hasConstrained = false, hasOtherMeshLab = false, hasVtk = false;
    lineup::TriangleSurface vtk;
    const shapes::Shape *shape = nullptr;
};

constexpr int kRepeats = 3;  // timed runs per stage; the best counts

// Runs the chain on `model`: extraction, our fairing, the constrained mode, MeshLab's smoothers and
// VTK's when built with them; attributes and atlas after each.
ModelRun runChain(const pipeline::Model &model, const std::string &kind);

}  // namespace voxelfair::report
