#include "scene_to_meshlab.h"

#include "fairing/voxel_size.h"
#include "mesh/polygon_mesh.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/allocate.h>

namespace voxelfair {

int sceneImportMask() {
    using vcg::tri::io::Mask;
    return Mask::IOM_VERTCOORD | Mask::IOM_FACEINDEX | Mask::IOM_FACECOLOR | Mask::IOM_FACEQUALITY |
           Mask::IOM_BITPOLYGONAL;
}

void sceneToMeshLab(const SceneSurface &surface, PaletteKind kind, MeshModel &model) {
    CMeshO &m = model.cm;
    m.Clear();
    auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, surface.positions.size());
    for (const glm::vec3 &p : surface.positions) {
        vi->P() = CMeshO::CoordType(p.x, p.y, p.z);
        ++vi;
    }

    auto part = vcg::tri::Allocator<CMeshO>::GetPerFaceAttribute<int>(m, kPartAttributeName);
    auto paletteIndex = vcg::tri::Allocator<CMeshO>::GetPerFaceAttribute<uint8_t>(m, kPaletteIndexAttributeName);
    vcg::tri::Allocator<CMeshO>::GetPerMeshAttribute<int>(m, kPaletteKindAttributeName)() = int(kind);
    auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, 2 * surface.quadCount());
    for (size_t q = 0; q < surface.quadCount(); ++q) {
        const uint32_t *c = &surface.quads[4 * q];
        const Rgb colour = surface.quadColours[q];
        // Quad (a, b, c, d) -> (a, b, c) + (a, c, d); the diagonal a-c is faux in both, so
        // MeshLab treats the pair as one polygon (edge 2 of the first, edge 0 of the second).
        const uint32_t triangles[2][3] = {{c[0], c[1], c[2]}, {c[0], c[2], c[3]}};
        for (int t = 0; t < 2; ++t, ++fi) {
            for (int k = 0; k < 3; ++k)
                fi->V(k) = &m.vert[triangles[t][k]];
            fi->SetF(t == 0 ? 2 : 0);
            fi->C() = vcg::Color4b(colour.r, colour.g, colour.b, 255);
            fi->Q() = CMeshO::ScalarType(surface.quadParts[q]);
            part[fi] = surface.quadParts[q];
            paletteIndex[fi] = surface.quadVoxels[q].colour;
        }
    }
    // Each part's voxel size, while every edge is still one voxel.
    std::vector<float> voxelSizes;
    {
        std::vector<std::vector<uint32_t>> partQuads;
        for (size_t q = 0; q < surface.quadCount(); ++q) {
            const int p = surface.quadParts[q];
            if (p < 0)
                continue;
            if (size_t(p) >= partQuads.size())
                partQuads.resize(size_t(p) + 1);
            partQuads[size_t(p)].insert(partQuads[size_t(p)].end(), &surface.quads[4 * q], &surface.quads[4 * q] + 4);
        }
        voxelSizes.assign(partQuads.size(), 0.0f);
        std::vector<uint32_t> offsets;
        for (size_t p = 0; p < partQuads.size(); ++p) {
            offsets.resize(partQuads[p].size() / 4 + 1);
            for (size_t q = 0; q < offsets.size(); ++q)
                offsets[q] = uint32_t(4 * q);
            voxelSizes[p] = detectVoxelSize(polygonMesh(surface.positions, offsets, partQuads[p]));
        }
    }
    vcg::tri::Allocator<CMeshO>::GetPerMeshAttribute<std::vector<float>>(m, kPartVoxelSizeAttributeName)() =
        std::move(voxelSizes);
    // meshlabserver does not compute the box for polygonal imports: do it here.
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

}  // namespace voxelfair
