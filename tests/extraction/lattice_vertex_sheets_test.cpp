#include "extraction/lattice_vertex_sheets.h"

#include <gtest/gtest.h>

using namespace voxelfair;

namespace {

int cellBit(int i, int j, int k) { return 1 << (i + 2 * j + 4 * k); }

bool slotHasQuad(int config, int slot) {
    const int a = slot / 4;
    const int cell = (slot & 1) << ((a + 1) % 3) | ((slot >> 1) & 1) << ((a + 2) % 3);
    return ((config >> cell) & 1) != ((config >> (cell | 1 << a)) & 1);
}

int quadCount(int config) {
    int n = 0;
    for (int s = 0; s < kLatticeQuadSlots; ++s)
        n += slotHasQuad(config, s);
    return n;
}

void expectWellFormed(int config, const LatticeVertexSheets &sheets) {
    std::vector<int> quadsPerSheet(sheets.sheetCount, 0);
    for (int s = 0; s < kLatticeQuadSlots; ++s) {
        if (!slotHasQuad(config, s)) {
            EXPECT_EQ(sheets.sheetOfSlot[s], kNoSheet) << "slot " << s;
            continue;
        }
        ASSERT_LT(sheets.sheetOfSlot[s], sheets.sheetCount) << "slot " << s;
        ++quadsPerSheet[sheets.sheetOfSlot[s]];
    }
    // A closed fan around a lattice point has at least three quads.
    for (int n : quadsPerSheet)
        EXPECT_GE(n, 3);
}

}  // namespace

TEST(LatticeVertexSheets, EverySlotWithAQuadHasASheetAndEverySheetIsAClosedFan) {
    for (int config = 0; config < 256; ++config) {
        SCOPED_TRACE(config);
        const LatticeVertexConfig &c = kLatticeVertexConfigs[config];
        expectWellFormed(config, c.separate);
        expectWellFormed(config, c.joined);
        if (c.pinchedHalfEdge < 0) {
            EXPECT_EQ(c.joined.sheetCount, c.separate.sheetCount);
        } else {
            // Re-pairing a sheet that passes the half-edge twice cuts it in two.
            EXPECT_EQ(c.joined.sheetCount, c.separate.sheetCount + 1);
        }
    }
}

TEST(LatticeVertexSheets, EmptyAndFullPointsHaveNoQuads) {
    EXPECT_EQ(quadCount(0), 0);
    EXPECT_EQ(quadCount(255), 0);
    EXPECT_EQ(kLatticeVertexConfigs[0].separate.sheetCount, 0);
    EXPECT_EQ(kLatticeVertexConfigs[255].separate.sheetCount, 0);
}

TEST(LatticeVertexSheets, OneSolidCellGivesOneSheetOfThreeQuads) {
    for (int cell = 0; cell < 8; ++cell) {
        const LatticeVertexConfig &c = kLatticeVertexConfigs[1 << cell];
        EXPECT_EQ(quadCount(1 << cell), 3);
        EXPECT_EQ(c.separate.sheetCount, 1);
        EXPECT_EQ(c.fourQuadEdgesForward, 0);
        EXPECT_EQ(c.pinchedHalfEdge, -1);
        // Seven solid cells: the empty corner is a single concave fan.
        EXPECT_EQ(kLatticeVertexConfigs[255 & ~(1 << cell)].separate.sheetCount, 1);
    }
}

TEST(LatticeVertexSheets, CellsTouchingAlongAnEdgeGetOneSheetEach) {
    // Cells (1,0,0) and (1,1,1) share the half-edge towards +x; (0,0,0) and (0,1,1) the one towards -x.
    const LatticeVertexConfig &forward = kLatticeVertexConfigs[cellBit(1, 0, 0) | cellBit(1, 1, 1)];
    EXPECT_EQ(forward.separate.sheetCount, 2);
    EXPECT_EQ(forward.fourQuadEdgesForward, 1);
    EXPECT_EQ(forward.pinchedHalfEdge, -1);
    const LatticeVertexConfig &backward = kLatticeVertexConfigs[cellBit(0, 0, 0) | cellBit(0, 1, 1)];
    EXPECT_EQ(backward.separate.sheetCount, 2);
    EXPECT_EQ(backward.fourQuadEdgesForward, 0);
}

TEST(LatticeVertexSheets, CellsTouchingAtACornerGetOneSheetEach) {
    for (int cell = 0; cell < 4; ++cell) {
        const int config = 1 << cell | 1 << (7 - cell);
        EXPECT_EQ(kLatticeVertexConfigs[config].separate.sheetCount, 2) << config;
        EXPECT_EQ(kLatticeVertexConfigs[config].fourQuadEdgesForward, 0) << config;
        // The complement: two empty corners meeting at the point leave two separate concave sheets.
        EXPECT_EQ(kLatticeVertexConfigs[255 & ~config].separate.sheetCount, 2) << config;
    }
}

TEST(LatticeVertexSheets, SolidCellsJoinedBehindTheirEdgeArePinched) {
    // (1,0,0) and (1,1,1) touch along the +x half-edge and join through (0,0,0), (0,1,0), (0,1,1).
    const int config = cellBit(1, 0, 0) | cellBit(1, 1, 1) | cellBit(0, 0, 0) | cellBit(0, 1, 0) | cellBit(0, 1, 1);
    const LatticeVertexConfig &c = kLatticeVertexConfigs[config];
    EXPECT_EQ(c.pinchedHalfEdge, 1);
    EXPECT_EQ(c.separate.sheetCount, 1);
    EXPECT_EQ(c.joined.sheetCount, 2);
    // Without (0,1,0) they stay apart behind the edge too.
    EXPECT_EQ(kLatticeVertexConfigs[config & ~cellBit(0, 1, 0)].pinchedHalfEdge, -1);
}
