// The atlas' steps that take each chart alone (masks, merges, splits, final UVs) run on runs of
// consecutive charts of about equal faces, a few per thread (dynamic load balance without
// splitting a chart), each run written apart and joined in order: their results are the same
// for any thread count. One definition of the runs and of the size under which a step stays on
// one thread.
#pragma once

#include "atlas/charts.h"
#include "base/parallel_bands.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace voxelfair {

// Meshes with fewer faces than this take the atlas' steps on one thread: starting threads would
// cost more than they save.
constexpr size_t kLeastParallelFaces = 4096;

struct ChartRuns {
    int workers = 1;           // threads for runBands (1 under kLeastParallelFaces faces)
    std::vector<size_t> from;  // run r holds charts from[r] .. from[r + 1] - 1; count() + 1 entries
    size_t count() const { return from.size() - 1; }
};

// Charts cut where the faces before them pass a multiple of faces / runs: 4 runs per worker
// (`threads` as bandThreads takes it), one run on one worker.
inline ChartRuns chartRuns(const AtlasCharts &charts, int threads) {
    const size_t chartCount = charts.chartCount(), faceCount = charts.faceCount();
    ChartRuns runs;
    runs.workers = faceCount >= kLeastParallelFaces ? bandThreads(threads, chartCount) : 1;
    const size_t count = runs.workers > 1 ? std::min<size_t>(4 * size_t(runs.workers), chartCount) : 1;
    runs.from.assign(count + 1, chartCount);
    runs.from[0] = 0;
    for (size_t run = 1, c = 0; run < count; ++run) {
        while (c < chartCount && charts.chartFirstFace[c] < faceCount * run / count)
            ++c;
        runs.from[run] = c;
    }
    return runs;
}

}  // namespace voxelfair
