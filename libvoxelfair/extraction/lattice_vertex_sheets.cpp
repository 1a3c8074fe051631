#include "extraction/lattice_vertex_sheets.h"

#include <stdexcept>

namespace voxelfair {
namespace {

constexpr bool solidCell(int config, int cell) { return (config >> cell) & 1; }

// The slot of the face perpendicular to `axis` on the side of `cell` (its `axis` bit is ignored).
constexpr int slotOf(int axis, int cell) {
    return 4 * axis + ((cell >> ((axis + 1) % 3)) & 1) + 2 * ((cell >> ((axis + 2) % 3)) & 1);
}

constexpr bool slotHasQuad(int config, int slot) {
    const int axis = slot / 4;
    const int cell = (slot & 1) << ((axis + 1) % 3) | ((slot >> 1) & 1) << ((axis + 2) % 3);
    return solidCell(config, cell) != solidCell(config, cell | 1 << axis);
}

// The four cells around a half-edge in circular order; face[k] separates cell[k] and cell[k + 1].
struct Ring {
    int cell[4] = {};
    int face[4] = {};
};

constexpr Ring ringAround(int halfEdge) {
    const int b = halfEdge / 2, u = (b + 1) % 3, w = (b + 2) % 3;
    const int side = (halfEdge & 1) << b;
    const int offsets[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    Ring ring;
    for (int k = 0; k < 4; ++k)
        ring.cell[k] = side | offsets[k][0] << u | offsets[k][1] << w;
    for (int k = 0; k < 4; ++k)
        ring.face[k] = slotOf(k % 2 == 0 ? u : w, ring.cell[k]);
    return ring;
}

struct SlotSets {
    int parent[kLatticeQuadSlots] = {};
    constexpr SlotSets() {
        for (int s = 0; s < kLatticeQuadSlots; ++s)
            parent[s] = s;
    }
    constexpr int find(int s) const {
        while (parent[s] != s)
            s = parent[s];
        return s;
    }
    constexpr void unite(int a, int b) { parent[find(a)] = find(b); }
};

constexpr int quadsAround(int config, const Ring &ring) {
    int n = 0;
    for (int k = 0; k < 4; ++k)
        n += slotHasQuad(config, ring.face[k]);
    return n;
}

// Chains the quads around p through every half-edge. Four quads are paired by the solid cell they
// bound, or by the empty cell at `joinedHalfEdge`. Cell k is bounded by faces k - 1 and k.
constexpr SlotSets pairQuads(int config, int joinedHalfEdge) {
    SlotSets sets;
    for (int h = 0; h < 6; ++h) {
        const Ring ring = ringAround(h);
        const int n = quadsAround(config, ring);
        if (n == 2) {
            int present[2] = {}, m = 0;
            for (int k = 0; k < 4; ++k)
                if (slotHasQuad(config, ring.face[k]))
                    present[m++] = ring.face[k];
            sets.unite(present[0], present[1]);
        } else if (n == 4) {
            const bool aroundCell0 = solidCell(config, ring.cell[0]) != (h == joinedHalfEdge);
            if (aroundCell0) {
                sets.unite(ring.face[3], ring.face[0]);
                sets.unite(ring.face[1], ring.face[2]);
            } else {
                sets.unite(ring.face[0], ring.face[1]);
                sets.unite(ring.face[2], ring.face[3]);
            }
        }
    }
    return sets;
}

constexpr LatticeVertexSheets numberSheets(int config, const SlotSets &sets) {
    LatticeVertexSheets sheets;
    int sheetOfRoot[kLatticeQuadSlots] = {};
    for (int s = 0; s < kLatticeQuadSlots; ++s)
        sheetOfRoot[s] = -1;
    for (int s = 0; s < kLatticeQuadSlots; ++s) {
        sheets.sheetOfSlot[s] = kNoSheet;
        if (!slotHasQuad(config, s))
            continue;
        int &sheet = sheetOfRoot[sets.find(s)];
        if (sheet < 0)
            sheet = sheets.sheetCount++;
        sheets.sheetOfSlot[s] = uint8_t(sheet);
    }
    return sheets;
}

constexpr std::array<LatticeVertexConfig, 256> buildConfigs() {
    std::array<LatticeVertexConfig, 256> configs{};
    for (int config = 0; config < 256; ++config) {
        LatticeVertexConfig &entry = configs[config];
        const SlotSets separate = pairQuads(config, -1);
        entry.separate = numberSheets(config, separate);
        entry.joined = entry.separate;
        for (int h = 0; h < 6; ++h) {
            const Ring ring = ringAround(h);
            if (quadsAround(config, ring) != 4)
                continue;
            if (h & 1)
                ++entry.fourQuadEdgesForward;
            // Faces 0 and 2 lie in different pairs; one sheet holding both means the two solid
            // cells are joined around p.
            if (separate.find(ring.face[0]) != separate.find(ring.face[2]))
                continue;
            // The extraction checks a single half-edge per lattice point.
            if (entry.pinchedHalfEdge >= 0)
                throw std::logic_error("two pinched half-edges at one lattice point");
            entry.pinchedHalfEdge = int8_t(h);
            entry.joined = numberSheets(config, pairQuads(config, h));
        }
    }
    return configs;
}

}  // namespace

constexpr std::array<LatticeVertexConfig, 256> kLatticeVertexConfigs = buildConfigs();

}  // namespace voxelfair
