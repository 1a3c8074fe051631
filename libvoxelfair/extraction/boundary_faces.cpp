#include "extraction/boundary_faces.h"

namespace voxelfair {
namespace {

struct FaceSink {
    std::vector<BoundaryFace> &faces;
    std::vector<Voxel> &voxels;
    const VoxelVolume &solid;

    // Faces of voxels z0 .. z1 - 1 of `run` in column (x, y).
    void add(int x, int y, const VoxelRun &run, int z0, int z1, uint8_t direction) {
        for (int z = z0; z < z1; ++z) {
            faces.push_back(BoundaryFace{uint16_t(x), uint16_t(y), uint16_t(z), direction});
            voxels.push_back(solid.voxels[run.firstVoxel + uint32_t(z - run.zBegin)]);
        }
    }
};

// Side faces of column (x, y) towards a neighbour column: the voxels of runs [a, aEnd) that the
// neighbour's runs [b, bEnd) do not cover (interval difference by merge walk).
void addUncovered(int x, int y, const VoxelRun *a, const VoxelRun *aEnd, const VoxelRun *b, const VoxelRun *bEnd,
                  uint8_t direction, FaceSink &sink) {
    for (; a != aEnd; ++a) {
        int z = a->zBegin;
        while (b != bEnd && b->zEnd <= z)
            ++b;  // neighbour runs wholly below this one
        for (const VoxelRun *cover = b; z < a->zEnd; ++cover) {
            if (cover == bEnd || cover->zBegin >= a->zEnd) {
                sink.add(x, y, *a, z, a->zEnd, direction);
                break;
            }
            if (cover->zBegin > z)
                sink.add(x, y, *a, z, cover->zBegin, direction);
            z = cover->zEnd;
        }
    }
}

}  // namespace

void collectBoundaryFaces(const VoxelVolume &solid, int y0, int y1, std::vector<BoundaryFace> &faces,
                          std::vector<Voxel> &voxels) {
    FaceSink sink{faces, voxels, solid};
    struct Side {
        int dx, dy;
        uint8_t direction;
    };
    constexpr Side kSides[4] = {{-1, 0, 0}, {1, 0, 1}, {0, -1, 2}, {0, 1, 3}};
    const VoxelRun *runs = solid.runs.data();
    for (int y = y0; y < y1; ++y) {
        for (int x = 0; x < solid.sizeX; ++x) {
            const size_t c = solid.columnIndex(x, y);
            const VoxelRun *first = runs + solid.columnFirstRun[c], *last = runs + solid.columnFirstRun[c + 1];
            if (first == last)
                continue;
            // Runs never touch inside a column, so both ends of every run are boundary faces.
            for (const VoxelRun *r = first; r != last; ++r) {
                sink.add(x, y, *r, r->zBegin, r->zBegin + 1, 4);
                sink.add(x, y, *r, r->zEnd - 1, r->zEnd, 5);
            }
            for (const Side &side : kSides) {
                const int nx = x + side.dx, ny = y + side.dy;
                const VoxelRun *b = nullptr, *bEnd = nullptr;  // outside the volume: nothing covers
                if (nx >= 0 && ny >= 0 && nx < solid.sizeX && ny < solid.sizeY) {
                    const size_t n = solid.columnIndex(nx, ny);
                    b = runs + solid.columnFirstRun[n];
                    bEnd = runs + solid.columnFirstRun[n + 1];
                }
                addUncovered(x, y, first, last, b, bEnd, side.direction, sink);
            }
        }
    }
}

}  // namespace voxelfair
