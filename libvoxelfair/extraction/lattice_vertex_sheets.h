// Which boundary quads around a lattice point share a vertex: the table that makes the boundary
// surface 2-manifold (internal to the extraction).
//
// Conventions, all relative to a lattice point p:
// - cell bit i + 2j + 4k is the voxel (p.x - 1 + i, p.y - 1 + j, p.z - 1 + k); a configuration is
//   the 8-bit mask of the solid ones;
// - quad slot 4a + bu + 2bv is the face on the plane through p perpendicular to axis a, between
//   the two cells whose bits on axes u = (a + 1) % 3 and v = (a + 2) % 3 are bu and bv; it holds
//   a boundary quad when exactly one of those two cells is solid;
// - half-edge 2b + s is the lattice edge leaving p towards -b (s = 0) or +b (s = 1).
//
// Each half-edge has the four cells around it; their quads (two, or four when two diagonal cells
// are solid) are paired, and the pairs chain the quads around p into closed fans, the sheets.
// Each sheet gets its own vertex. Four quads are paired by solid cell, so solid voxels touching
// only along an edge or at a corner get separate sheets. Both ends of an edge pair its quads the
// same way, so each resulting edge has two quads, except where the two solid cells are joined
// around both ends (a tunnel pinched to one lattice edge): the two edge copies would then link the
// same two vertices. There the quads are paired by empty cell instead ("joined"), which closes the
// zero-width tunnel; such a pinched half-edge is unique at its lattice point.
#pragma once

#include <array>
#include <cstdint>

namespace voxelfair {

constexpr int kLatticeQuadSlots = 12;
constexpr uint8_t kNoSheet = 0xFF;

struct LatticeVertexSheets {
    std::array<uint8_t, kLatticeQuadSlots> sheetOfSlot{};  // 0 .. sheetCount - 1, kNoSheet for no quad
    uint8_t sheetCount = 0;
};

struct LatticeVertexConfig {
    LatticeVertexSheets separate;  // four quads paired by solid cell at every half-edge
    LatticeVertexSheets joined;    // the same, but paired by empty cell at pinchedHalfEdge
    // The four-quad half-edge whose two solid cells are joined around p, or -1.
    int8_t pinchedHalfEdge = -1;
    // Half-edges towards +x, +y, +z holding four quads: counts each such lattice edge once.
    uint8_t fourQuadEdgesForward = 0;
};

// Indexed by configuration; built at compile time.
extern const std::array<LatticeVertexConfig, 256> kLatticeVertexConfigs;

}  // namespace voxelfair
