#include "atlas/atlas_mesh.h"

#include "base/error.h"

#include <cmath>
#include <string>

namespace voxelfair {

void validateAtlasMesh(const AtlasMesh &mesh) {
    validate(static_cast<const TriangleMesh &>(mesh));
    if (mesh.faceTexelScale)
        for (size_t f = 0; f < mesh.faceCount; ++f)
            if (!(mesh.faceTexelScale[f] > 0) || !std::isfinite(mesh.faceTexelScale[f]))
                throw MeshError("face " + std::to_string(f) + " has a texel scale that is not positive and finite");
}

}  // namespace voxelfair
