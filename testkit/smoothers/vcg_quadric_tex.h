// MeshLab 2020.09's "Simplification: Quadric Edge Collapse Decimation (with texture)" as its
// filter runs it (filter_meshing: QuadricTexSimplification, then per-face normals normalised and
// vertex normals from them), with vcglib in our process: the pipeline's decimation (paper 4.6),
// for the normal map's tests and benchmark. Parameters are the pipeline script's: quality
// threshold 0.3, texture weight 1, optimal placement, no boundary or normal preservation.
// Only with VOXELFAIR_HAVE_VCGLIB.
#pragma once

#ifdef VOXELFAIR_HAVE_VCGLIB

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/local_optimization.h>
#include <vcg/complex/algorithms/local_optimization/tri_edge_collapse_quadric_tex.h>
#include <vcg/complex/algorithms/update/flag.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/container/simple_temporary_data.h>

namespace voxelfair::vcgdecimate {

class Vertex;
class Face;
struct UsedTypes : vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType> {};
class Vertex : public vcg::Vertex<UsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::VFAdj,
                                  vcg::vertex::Mark, vcg::vertex::BitFlags> {};
class Face : public vcg::Face<UsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::WedgeTexCoord2f,
                              vcg::face::VFAdj, vcg::face::Mark, vcg::face::BitFlags> {};
class Mesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face>> {};

using VertexPair = vcg::tri::BasicVertexPair<Vertex>;
class Collapse
    : public vcg::tri::TriEdgeCollapseQuadricTex<Mesh, VertexPair, Collapse, vcg::tri::QuadricTexHelper<Mesh>> {
public:
    using Base = vcg::tri::TriEdgeCollapseQuadricTex<Mesh, VertexPair, Collapse, vcg::tri::QuadricTexHelper<Mesh>>;
    Collapse(const VertexPair &p, int i, vcg::BaseParameterClass *pp) : Base(p, i, pp) {}
};

// A triangle mesh with per-vertex normals and per-corner UVs, as the normal bake reads it.
struct TexturedMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> triangles;
    std::vector<glm::vec2> wedgeUv;
    size_t faceCount() const { return triangles.size() / 3; }
};

// Keeps `share` of the faces (MeshLab's TargetPerc). Normals are recomputed like the filter does.
inline TexturedMesh decimate(const std::vector<glm::vec3> &positions, const std::vector<uint32_t> &triangles,
                             const std::vector<glm::vec2> &wedgeUv, double share) {
    Mesh m;
    auto vi = vcg::tri::Allocator<Mesh>::AddVertices(m, positions.size());
    for (const glm::vec3 &p : positions)
        (vi++)->P() = vcg::Point3f(p.x, p.y, p.z);
    auto fi = vcg::tri::Allocator<Mesh>::AddFaces(m, triangles.size() / 3);
    for (size_t t = 0; t + 2 < triangles.size(); t += 3, ++fi)
        for (int k = 0; k < 3; ++k) {
            fi->V(k) = &m.vert[triangles[t + size_t(k)]];
            fi->WT(k).U() = wedgeUv[t + size_t(k)].x;
            fi->WT(k).V() = wedgeUv[t + size_t(k)].y;
            fi->WT(k).N() = 0;
        }
    vcg::tri::UpdateTopology<Mesh>::VertexFace(m);
    vcg::tri::UpdateFlags<Mesh>::FaceBorderFromVF(m);

    vcg::tri::TriEdgeCollapseQuadricTexParameter pp;
    pp.QualityThr = 0.3;
    pp.ExtraTCoordWeight = 1.0;
    pp.OptimalPlacement = true;
    pp.PreserveBoundary = false;
    pp.BoundaryWeight = pp.BoundaryWeight * 0.5;
    pp.QualityQuadric = false;
    pp.NormalCheck = false;
    const int target = int(double(m.fn) * share);

    vcg::tri::UpdateNormal<Mesh>::PerFace(m);
    vcg::math::Quadric<double> zero;
    zero.SetZero();
    vcg::tri::QuadricTexHelper<Mesh>::QuadricTemp td3(m.vert, zero);
    vcg::tri::QuadricTexHelper<Mesh>::TDp3() = &td3;
    std::vector<std::pair<vcg::TexCoord2<float>, vcg::Quadric5<double>>> qv;
    vcg::tri::QuadricTexHelper<Mesh>::Quadric5Temp td(m.vert, qv);
    vcg::tri::QuadricTexHelper<Mesh>::TDp() = &td;
    {
        vcg::LocalOptimization<Mesh> session(m, &pp);
        session.Init<Collapse>();
        session.SetTargetSimplices(target);
        session.SetTimeBudget(0.1f);
        while (session.DoOptimization() && m.fn > target) {
        }
        session.Finalize<Collapse>();
    }
    vcg::tri::QuadricTexHelper<Mesh>::TDp3() = nullptr;
    vcg::tri::QuadricTexHelper<Mesh>::TDp() = nullptr;

    vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(m);
    vcg::tri::UpdateNormal<Mesh>::PerVertexFromCurrentFaceNormal(m);
    vcg::tri::UpdateNormal<Mesh>::NormalizePerVertex(m);

    TexturedMesh out;
    std::vector<uint32_t> index(m.vert.size(), 0);
    for (size_t v = 0; v < m.vert.size(); ++v) {
        if (m.vert[v].IsD())
            continue;
        index[v] = uint32_t(out.positions.size());
        const vcg::Point3f &p = m.vert[v].cP(), &n = m.vert[v].cN();
        out.positions.emplace_back(p[0], p[1], p[2]);
        out.normals.emplace_back(n[0], n[1], n[2]);
    }
    for (const Face &f : m.face) {
        if (f.IsD())
            continue;
        for (int k = 0; k < 3; ++k) {
            out.triangles.push_back(index[vcg::tri::Index(m, f.cV(k))]);
            out.wedgeUv.emplace_back(f.cWT(k).U(), f.cWT(k).V());
        }
    }
    return out;
}

}  // namespace voxelfair::vcgdecimate

#endif
