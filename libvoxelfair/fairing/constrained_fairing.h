// A second fairing mode beside the paper's (lanczos_fairing.h): staircase-aware, cell-constrained
// normal fairing. It removes the voxel staircase and keeps the surface where the voxels say it is:
//
// 1. Edges. Every edge whose two polygons meet at more than creaseAngle is a crease. A crease is
//    a staircase step when a polygon beside it is a riser: within stepReach quads, walking across
//    flat quads away from the crease, the next crease turns the other way (convex then concave).
//    Otherwise it is a genuine edge (box edges, cylinder caps, 1-voxel plates and rods), unless
//    the walks on both of its sides end, within featureReach quads, on staircase steps (a lone
//    straight edge in a rounded part), or it is an isolated single edge (its two ends touch no
//    other genuine edge). Boundary and non-manifold edges are always genuine. A crease with a
//    single 1-2 quad notch between long flats (a box turned a few degrees) is marked so that
//    step 2's far levels do not cross it (a 7-quad face took its corners' normals and bowed). The idea of
//    separating staircase from feature edges is from Moench, Adler and Preim, "Staircase-aware
//    smoothing of medical surface meshes" (VCBM 2010); the riser test is ours.
// 2. Normals. Polygon normals are averaged with their neighbours across edges, never across a
//    genuine edge: on a staircase the sum of unit face normals over a patch is the true normal
//    times the patch's projected area, so this removes the steps without bias, and a sphere's
//    averaged normals stay radial (no shrinking). A trous: level i averages with the polygons
//    2^i quads straight across each edge, so 3 levels reach as far as about 12 plain sweeps.
// 3. Positions. The vertices are moved to fit those normals (Sun, Rosin, Martin and Langbein,
//    "Fast and effective feature-preserving mesh denoising", IEEE TVCG 13(5), 2007): a vertex
//    away from genuine edges moves along its normal n so that each edge to a neighbour becomes
//    perpendicular to the mean of the two vertex normals (which holds exactly on a sphere); a
//    vertex on a genuine edge line moves towards the planes of its polygons (which keeps the
//    edge sharp); vertices where genuine edges end or meet do not move. positionSweeps
//    Gauss-Seidel sweeps, alternating direction.
// 3b. Where the filtered normals of a vertex's polygons turn by more than featureSpread (edges
//    and rims hidden in the staircase), the vertex is moved towards those polygons' planes (Sun et
//    al.'s own vertex update), which puts it on their line or corner (constrained/feature_fit.cpp).
//    The planes take the normal of the nearest flat side a few quads away, not the filtered one,
//    which turns over several quads there: the edge comes out sharper.
// 4. Every vertex stays inside the cell around its input position (half-width cellHalfWidth
//    voxels per axis): on the voxel surface the true surface crosses the cube spanned by the 8
//    voxel centres around each lattice vertex (Gibson, "Constrained elastic surface nets",
//    MICCAI 1998). This bounds every move, keeps 1-voxel plates and rods from collapsing, and
//    keeps the volume.
// 5. Drift. The fit only asks edges to be perpendicular to normals: a face can slide along its
//    normal and a part can grow, and near edges and fillets, whose filtered normals turn over
//    more quads than the true surface does, the cells push the rounded profile out, which drags
//    the flat faces with it (a rounded box became a pillow, +3.8% volume). So the displacement
//    along the normal is averaged over each vertex's neighbourhood (driftRounds Jacobi rounds)
//    and that local mean is taken off: the surface keeps the voxels' volume locally, as the
//    voxelization of a plane or a smooth surface does on average. Far from where the shape
//    turns (edges, fillets, lattice faces), the mean over driftWideRounds rounds is taken off
//    instead, which leaves less of the staircase's ripple on smooth surfaces
//    (constrained/drift_removal.cpp).
// Optional (fitPlanes, off by default): flat faces at any orientation found as digital plane
// regions, their vertices held on fitted planes, edge lines and corners (constrained/
// plane_regions.cpp). It brings turned boxes, plates and wedges about 0.01 RMS nearer, but costs
// 3-4 times the whole call on large curved surfaces and takes patches of spheres of radius 40 and
// up for planes.
// Optional (freeEdgeEnds, off by default): the vertices where a line of genuine edges ends are
// fitted like free vertices instead of pinned (turned boxes, plates and wedges about 0.01 nearer,
// but thin plates and wedges lose up to 2% of their volume).
// A second pass recomputes the polygon normals from the faired surface and repeats 2 and 3; the
// edge classes and the cells always come from the input. The stages are in fairing/constrained/
// (fairing_state.h lists them).
//
// How near it comes to the true surface on the shape families of testkit/shapes/shape_families.h
// (random orientations and sub-voxel offsets; tests/fairing/family_fidelity_test.cpp asserts the
// goals) and what it costs (benchmarks/fairing_benchmark) are measured in one place: the
// README's comparison table and performance table.
#pragma once

#include "fairing/lanczos_fairing.h"  // FairingStatus
#include "base/simd_variant.h"

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace voxelfair {

struct ConstrainedFairingOptions {
    // Rounds of normal filtering + position fitting; a later round re-estimates the normals from
    // the faired surface (0 leaves the mesh alone).
    int passes = 2;
    // Normal averaging levels (step 2): level i averages each polygon with the four polygons 2^i
    // quads away, so 3 levels reach as far as about 12 plain sweeps. Passes after the first use
    // one level less.
    int normalLevels = 3;
    // Position fitting sweeps per pass (step 3).
    int positionSweeps = 6;
    // Step 3b (constrained/feature_fit.cpp): sweeps per pass that move the vertices whose
    // polygons' filtered normals turn by more than featureSpreadDegrees towards those polygons'
    // planes (0 turns it off).
    int featureFitIterations = 10;
    float featureSpreadDegrees = 10.0f;
    // Step 3b's planes take the normals of flat sides within this angle (see
    // constrained/feature_fit.cpp), which sharpens edges the staircase hides; 0 keeps the
    // filtered normals.
    float featureFlatDegrees = 10.0f;
    // Find flat faces at any orientation and hold their vertices on fitted planes, edges and
    // corners (constrained/plane_regions.cpp). Off: slow on large curved surfaces (see above).
    bool fitPlanes = false;
    // Step 1: fit the vertices where a line of genuine edges ends (one sharp edge) like the other
    // free vertices (steps 3, 3b, 5) instead of pinning them at their input position. Off by
    // default: on a turned box a staircase edge is many short genuine lines, whose ends, pinned,
    // stay 0.2 voxels outside on average (RMS 0.36); freed, they land on the surface (mean -0.03,
    // RMS 0.17) and the mean RMS of 8 boxes turned about two axes drops 0.133 -> 0.124, plates
    // 0.120 -> 0.111, wedges 0.117 -> 0.106; but the edges then round off inwards and thin
    // plates and wedges lose up to 2% of their volume (the goal is 1%; see the README).
    bool freeEdgeEnds = false;
    // Neighbourhood rounds of the drift removal (step 5); 0 turns it off.
    int driftRounds = 8;
    // Rounds of step 5's wide mean, taken off far from where the shape turns; at most
    // driftRounds: the local mean everywhere.
    int driftWideRounds = 24;
    // Half-width, in voxels, of the box around its input position that each vertex stays in.
    // 0.5 is the constraint of surface nets; it must be > 0.
    float cellHalfWidth = 0.5f;
    // Keep genuine edges sharp (step 1). Off, every crease is smoothed like a staircase step.
    bool keepSharpEdges = true;
    // Polygons meeting at more than this angle (degrees, in (0, 180)) form a crease.
    float creaseAngleDegrees = 60.0f;
    // Step 1's reaches, in quads: how far a staircase riser may be (2 catches the 2-by-2 steps of
    // small circles) and how far a genuine edge looks for the edges at the ends of its faces.
    int stepReach = 2;
    int featureReach = 8;
    // Step 1: a crease with a single notch (riser and tread each within stepReach) on one side
    // and flats of at least this many quads beyond the notch and on its other side (one of them 2
    // longer) is a corner of a box turned a few degrees, which step 2's far levels do not cross
    // (constrained/edge_classes.cpp); 0 turns it off.
    int cornerFlats = 5;
    // Size of a voxel in the positions' units. 0 = detectVoxelSize().
    float voxelSize = 0.0f;
    // Threads for the stages whose results do not depend on the order of the work (classification,
    // normal filtering, the fit's set-up, step 5's rounds): the same output for any count. 0: one
    // per hardware thread; meshes under 16,384 vertices a thread use fewer.
    int threads = 0;
};

struct ConstrainedFairingReport {
    FairingStatus status = FairingStatus::Ok;
    const char *message = "ok";    // static text saying why when status != Ok
    float voxelSize = 0.0f;        // the unit of cellHalfWidth used (given or detected)
    int passes = 0;                // passes run
    size_t creaseEdges = 0;        // manifold edges whose polygons meet at more than creaseAngle
    size_t sharpEdges = 0;         // edges kept sharp: genuine creases, boundary, non-manifold
    size_t edgeLineVertices = 0;   // vertices on a line of sharp edges (fitted to their planes)
    size_t pinnedVertices = 0;     // vertices where sharp edges end or meet, or not selected: never moved
    size_t planeRegions = 0;       // flat faces found (fitPlanes)
    size_t planeVertices = 0;      // vertices held on their planes, edge lines or corners
    size_t featureVertices = 0;    // vertices fitted to their polygons' planes (step 3b, last pass)
    size_t skippedVertices = 0;    // vertices with non-finite coordinates: never moved, never neighbours
    size_t movedVertices = 0;      // vertices that ended more than 1e-6 voxel from their input
    size_t clampedVertices = 0;    // vertices that ended on the wall of their cell
    float maxDisplacement = 0.0f;  // longest move of a vertex from its input, in position units
};

inline namespace VOXELFAIR_SIMD_VARIANT {  // sse2 or scalar: see simd_variant.h

// Smooths the mesh's positions in place (mesh/polygon_mesh.h); the staircase test needs quads (the voxel surface's), other
// polygons are smoothed but their creases count as genuine. With `vertexSelected` (nullable,
// one byte per vertex) only vertices with a non-zero byte move; the others stay as they are and
// still act as neighbours. Never produces NaN: non-finite vertices are skipped (their polygons
// count as holes), degenerate polygons are ignored.
ConstrainedFairingReport fairConstrained(const MutablePolygonMesh &mesh, const uint8_t *vertexSelected,
                                         const ConstrainedFairingOptions &options = {});

}  // namespace VOXELFAIR_SIMD_VARIANT

}  // namespace voxelfair
