// Stage 1 of the atlas (paper section 4.5): split the mesh into charts and project each onto
// the plane of its seed face.
//
//   * Seeds: faces ordered by the largest absolute component of their unit normal, descending
//     (the most axis-aligned faces start charts first); ties keep face order.
//   * Growth: breadth-first over edge-adjacent faces; an unassigned neighbour joins when its
//     normal is within the cone around the SEED face's normal (not the neighbour's), as the
//     authors did (doc/method.md §6b). Non-manifold edges, and edges between faces of different
//     texel scales, are chart borders. A mesh storing its
//     corners unshared (more border edges than faces) has its edges matched by position.
//   * Beyond the paper: a chart whose projection winds over itself (a helical ramp), or goes
//     round a vertex past a gap so that its faces there overlap, is cut
//     back to the half of its faces nearest the seed until it does not (chart_overlap.h), so
//     no texel is shared by two faces.
//   * Beyond the paper: charts of a few faces (the rounded corners of a faired voxel model) move
//     whole into an edge-adjacent chart within a wider cone around its axis (chart_merge.h),
//     so there are fewer, larger charts; the faces they move to get stretch up to 1 / mergeCosine.
//   * Projection: orthographic onto the seed plane (seed_plane.h), in model units (times the
//     mesh's faceTexelScale, when given), so every chart has the same texel density once packed. UVs are per wedge (3 per face): a vertex on
//     a chart border simply gets one UV per chart, which is the paper's vertex cloning.
//
// Stretch: a face at angle t to its seed normal is shrunk by cos t across one direction and kept
// along the other, so the singular values of the (density-normalised) map from the surface to
// UV are 1 and cos t >= minSeedCosine (>= mergeCosine for faces of merged small charts). Both cone tests below use the geometric normal too, so
// the bound holds even with caller-given normals.
//
// Degenerate faces (area below 1e-6 of the squared longest edge, or a vertex not finite) have
// no plane to project on: each gets its own chart whose UV triangle is fixed in texels,
// (0,0) (1,0) (0,1), so it still has positive UV area and shows its colour in one texel.
#pragma once

#include "atlas/atlas_mesh.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace voxelfair {

struct ChartOptions {
    // A face joins a chart when dot(seed normal, face normal) >= minSeedCosine. Default 0.7
    // (about 45.6 degrees) is the authors' C_TEX_MIN_ANGLE (doc/method.md §6b); the paper's text
    // states theta_min = 60 degrees, i.e. 0.5. Clamped to [0.05, 1]: the cone must stay inside
    // the hemisphere, or faces would fold over in the projection.
    float minSeedCosine = 0.7f;
    // Beyond the paper (chart_merge.h): a chart of at most mergeFaces faces moves whole into an
    // edge-adjacent chart when all its faces lie within mergeCosine of that chart's axis (0.5:
    // the paper's 60 degrees, for these faces only; never narrower than minSeedCosine) and
    // overlap none of its faces there. 0 turns merging off.
    size_t mergeFaces = 8;
    float mergeCosine = 0.5f;
    // Beyond the paper (chart_split.h): a chart whose faces cover less than minChartFill of its
    // bounding box (a ring of thin bars, a long diagonal bar) is cut by recursive bisection into
    // pieces that cover at least that much. Default 1/8; 0 cuts none.
    float minChartFill = 0.125f;
    // Threads (0: one per hardware thread): on meshes of 4096 faces or more, the faces' edge
    // adjacency is built on a second one beside their normals and seed order (the last fifth of
    // the normals on that one too), and the first pass's fold checks run on two after its charts
    // are grown. The charts are the same for any count.
    int threads = 0;
};

struct AtlasCharts {
    // Chart c holds faces chartFaces[chartFirstFace[c] .. chartFirstFace[c + 1]), seed first,
    // then in breadth-first order. Charts are numbered in seed order; degenerate faces' charts last.
    std::vector<uint32_t> chartFirstFace;
    std::vector<uint32_t> chartFaces;
    std::vector<uint32_t> faceChart;
    // The projection direction (unit seed normal); (0,0,0) marks a degenerate face's chart.
    std::vector<glm::vec3> chartAxis;
    // Size of the projected chart; its wedge UVs lie in [0, size]. Model units, except for
    // degenerate charts, whose UVs and size are in texels.
    std::vector<glm::vec2> chartSize;
    // Chart-local UVs (bounding box starting at the origin), three per entry of chartFaces:
    // wedgeUv[3 * i + k] is corner k of face chartFaces[i]. Stored in chart order so the later
    // stages read each chart contiguously.
    std::vector<glm::vec2> wedgeUv;
    // The mesh's edge adjacency (edge_adjacency.h): for half-edge 3f + k (corner k to corner
    // k + 1 of face f), the other face's half-edge on that edge, or kNoOpposite. The packer
    // fills each chart's inside from its outline (chart_outline.h); empty, it rasterises every
    // triangle instead.
    std::vector<uint32_t> faceOpposite;

    size_t degenerateFaces = 0;     // faces given their own tiny chart (includes nonFiniteFaces)
    size_t nonFiniteFaces = 0;      // faces with a vertex that is not finite
    size_t ignoredNormals = 0;      // given normals not finite, zero, or outside the face's own cone
    size_t foldedCharts = 0;        // times a chart winding over itself in UV was cut back
    size_t mergedCharts = 0;        // small charts moved into a neighbour (chart_merge.h)
    size_t splitCharts = 0;         // sparse charts cut into pieces (chart_split.h)
    size_t separatedFaces = 0;      // thin faces given their own chart for crisp colours (crowded_faces.h)
    size_t nonManifoldEdges = 0;    // edges of three or more faces, used as chart borders
    size_t borderEdges = 0;         // edges of one face (open meshes)
    bool weldedByPosition = false;  // corners were unshared: edges were matched by position

    size_t chartCount() const { return chartAxis.size(); }
    // Takes the charts of `other` (faces, axes, sizes, UVs), giving it these; the counters stay.
    void swapCharts(AtlasCharts &other) {
        chartFirstFace.swap(other.chartFirstFace);
        chartFaces.swap(other.chartFaces);
        faceChart.swap(other.faceChart);
        chartAxis.swap(other.chartAxis);
        chartSize.swap(other.chartSize);
        wedgeUv.swap(other.wedgeUv);
    }
    size_t faceCount() const { return faceChart.size(); }
    bool isDegenerate(size_t chart) const {
        return chartAxis[chart].x == 0 && chartAxis[chart].y == 0 && chartAxis[chart].z == 0;
    }
    // The charts' projected area (model units squared), degenerate charts left out.
    double projectedArea() const;
};

// Throws MeshError for an invalid mesh (validateAtlasMesh); no charts for a mesh without faces.
AtlasCharts computeCharts(const AtlasMesh &mesh, const ChartOptions &options = {});

}  // namespace voxelfair
