#include "extraction/cavity_fill.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace voxelfair {
namespace {

// Union-find over the empty gaps. Node 0 is the exterior; node r + 1 is the gap just above run r,
// between it and the next run of its column. The smaller root wins, so the exterior stays root 0.
class GapSets {
public:
    explicit GapSets(size_t runs) : parent_(runs + 1) {
        for (size_t i = 0; i < parent_.size(); ++i)
            parent_[i] = uint32_t(i);
    }
    uint32_t find(uint32_t n) {
        while (parent_[n] != n)
            n = parent_[n] = parent_[parent_[n]];  // path halving
        return n;
    }
    void unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a < b)
            std::swap(a, b);
        parent_[a] = b;
    }
    bool enclosed(uint32_t n) { return find(n) != 0; }

private:
    std::vector<uint32_t> parent_;
};

// The empty z-intervals of one column, in order: interval t in [0, runCount] lies below run t;
// the first and last touch the padding below and above the volume, so they are the exterior.
struct ColumnGaps {
    const VoxelRun *runs;
    uint32_t firstRun;
    uint32_t runCount;
    int sizeZ;

    int begin(uint32_t t) const { return t == 0 ? 0 : runs[t - 1].zEnd; }
    int end(uint32_t t) const { return t == runCount ? sizeZ : runs[t].zBegin; }
    uint32_t node(uint32_t t) const { return t == 0 || t == runCount ? 0 : firstRun + t; }
};

ColumnGaps columnGaps(const VoxelVolume &v, size_t column) {
    const uint32_t first = v.columnFirstRun[column];
    return {v.runs.data() + first, first, v.columnFirstRun[column + 1] - first, v.sizeZ};
}

// Unites the gaps of two face-neighbouring columns whose z ranges overlap (merge walk).
void linkColumns(const ColumnGaps &a, const ColumnGaps &b, GapSets &sets) {
    if (a.runCount < 2 && b.runCount < 2)
        return;  // only exterior intervals on both sides
    uint32_t ta = 0, tb = 0;
    while (ta <= a.runCount && tb <= b.runCount) {
        const int endA = a.end(ta), endB = b.end(tb);
        if (std::max(a.begin(ta), b.begin(tb)) < std::min(endA, endB)) {
            const uint32_t na = a.node(ta), nb = b.node(tb);
            if (na != nb)
                sets.unite(na, nb);
        }
        if (endA < endB)
            ++ta;
        else
            ++tb;
    }
}

}  // namespace

VoxelVolume fillEnclosedCavities(const VoxelVolume &volume, size_t *filled, Voxel fill) {
    if (filled)
        *filled = 0;
    const int sx = volume.sizeX, sy = volume.sizeY;
    GapSets sets(volume.runs.size());
    for (int y = 0; y < sy; ++y) {
        for (int x = 0; x < sx; ++x) {
            const size_t c = volume.columnIndex(x, y);
            const ColumnGaps gaps = columnGaps(volume, c);
            if (x == 0 || y == 0 || x == sx - 1 || y == sy - 1) {  // beside the padding
                for (uint32_t t = 1; t < gaps.runCount; ++t)
                    sets.unite(gaps.node(t), 0);
            }
            if (x + 1 < sx)
                linkColumns(gaps, columnGaps(volume, c + 1), sets);
            if (y + 1 < sy)
                linkColumns(gaps, columnGaps(volume, c + size_t(sx)), sets);
        }
    }

    // Gap r + 1 is enclosed: run r and the next one merge, with the gap's voxels in between.
    std::vector<bool> enclosedAbove(volume.runs.size(), false);
    size_t count = 0;
    for (size_t c = 0; c + 1 < volume.columnFirstRun.size(); ++c) {
        for (uint32_t r = volume.columnFirstRun[c]; r + 1 < volume.columnFirstRun[c + 1]; ++r) {
            if (!sets.enclosed(r + 1))
                continue;
            enclosedAbove[r] = true;
            count += volume.runs[r + 1].zBegin - volume.runs[r].zEnd;
        }
    }
    if (filled)
        *filled = count;
    if (count == 0)
        return volume;

    VoxelVolume out;
    out.sizeX = volume.sizeX;
    out.sizeY = volume.sizeY;
    out.sizeZ = volume.sizeZ;
    out.columnFirstRun.reserve(volume.columnFirstRun.size());
    out.runs.reserve(volume.runs.size());
    out.voxels.reserve(volume.voxels.size() + count);
    for (size_t c = 0; c + 1 < volume.columnFirstRun.size(); ++c) {
        out.columnFirstRun.push_back(uint32_t(out.runs.size()));
        const uint32_t first = volume.columnFirstRun[c];
        for (uint32_t r = first; r < volume.columnFirstRun[c + 1]; ++r) {
            const VoxelRun &run = volume.runs[r];
            if (r > first && enclosedAbove[r - 1]) {
                out.voxels.insert(out.voxels.end(), size_t(run.zBegin - volume.runs[r - 1].zEnd), fill);
                out.runs.back().zEnd = run.zEnd;
            } else {
                out.runs.push_back(VoxelRun{run.zBegin, run.zEnd, uint32_t(out.voxels.size())});
            }
            const auto begin = volume.voxels.begin() + run.firstVoxel;
            out.voxels.insert(out.voxels.end(), begin, begin + (run.zEnd - run.zBegin));
        }
    }
    out.columnFirstRun.push_back(uint32_t(out.runs.size()));
    return out;
}

}  // namespace voxelfair
