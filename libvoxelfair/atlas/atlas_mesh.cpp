#include "atlas/atlas_mesh.h"

#include <cmath>

namespace voxelfair {

const char *toString(AtlasStatus status) {
    switch (status) {
    case AtlasStatus::Ok: return "ok";
    case AtlasStatus::EmptyMesh: return "the mesh has no faces";
    case AtlasStatus::InvalidInput: return "invalid input";
    }
    return "unknown status";
}

AtlasStatus validateAtlasMesh(const AtlasMesh &mesh, std::string *message) {
    auto fail = [&](AtlasStatus s, std::string text) {
        if (message)
            *message = std::move(text);
        return s;
    };
    if (mesh.faceCount == 0)
        return fail(AtlasStatus::EmptyMesh, "the mesh has no faces: nothing to map");
    if (!mesh.triangles)
        return fail(AtlasStatus::InvalidInput, "faceCount > 0 but no triangle indices");
    if (mesh.vertexCount == 0 || !mesh.positions)
        return fail(AtlasStatus::InvalidInput, "faces given but no vertex positions");
    if (mesh.vertexCount >= UINT32_MAX || mesh.faceCount >= UINT32_MAX / 3)
        return fail(AtlasStatus::InvalidInput, "more vertices or faces than 32-bit indices address");
    for (size_t i = 0; i < mesh.faceCount * 3; ++i)
        if (mesh.triangles[i] >= mesh.vertexCount)
            return fail(AtlasStatus::InvalidInput, "face " + std::to_string(i / 3) + " uses vertex " +
                                                       std::to_string(mesh.triangles[i]) + " of " +
                                                       std::to_string(mesh.vertexCount));
    if (mesh.faceTexelScale)
        for (size_t f = 0; f < mesh.faceCount; ++f)
            if (!(mesh.faceTexelScale[f] > 0) || !std::isfinite(mesh.faceTexelScale[f]))
                return fail(AtlasStatus::InvalidInput,
                            "face " + std::to_string(f) + " has a texel scale that is not positive and finite");
    if (message)
        message->clear();
    return AtlasStatus::Ok;
}

}  // namespace voxelfair
