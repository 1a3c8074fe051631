#include "atlas/pack_tight.h"

#include "atlas/turned_shape.h"
#include "base/default_init_allocator.h"
#include "base/parallel_bands.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace voxelfair {
namespace {

// The free texels of a width x height atlas, row by row. run(y)[x] > 0: x is free and starts a free run
// of exactly that length; run(y)[x] < 0: x is taken, and so are the next -run(y)[x] - 1 texels
// (a safe jump, maybe short of the next free texel). Per block of kBlock texels, the longest run
// starting in it lets searches skip whole blocks.
class FreeRuns {
public:
    static constexpr int kBlock = 64;

    FreeRuns(int width, int height)
        : side_(width), height_(height), blocks_((width + kBlock - 1) / kBlock), run_(size_t(width) * height),
          blockMax_(size_t(height) * blocks_), widest_(size_t(height), int16_t(width)),
          firstRow_(size_t(width) + 1, 0) {
        // Every row starts as the first: one free run of the whole width.
        for (int x = 0; x < width; ++x)
            run_[size_t(x)] = int16_t(width - x);
        for (int b = 0; b < blocks_; ++b)
            blockMax_[size_t(b)] = int16_t(width - b * kBlock);
        for (int y = 1; y < height; ++y) {
            std::memcpy(&run_[size_t(y) * width], run_.data(), size_t(width) * sizeof(int16_t));
            std::memcpy(&blockMax_[size_t(y) * blocks_], blockMax_.data(), size_t(blocks_) * sizeof(int16_t));
        }
    }

    int16_t at(int y, int x) const { return run_[size_t(y) * side_ + x]; }
    int widest(int y) const { return widest_[size_t(y)]; }

    // The lowest row with a free run of at least `length`. Runs only ever shrink, so each
    // length's answer only moves up: amortised O(side) per length over a whole packing.
    int firstRow(int length) {
        int &row = firstRow_[size_t(length)];
        while (row < height_ && widest_[size_t(row)] < length)
            ++row;
        return row;
    }

    // The same without noting the answer (safe beside other readers).
    int firstRowFrom(int length) const {
        int row = firstRow_[size_t(length)];
        while (row < height_ && widest_[size_t(row)] < length)
            ++row;
        return row;
    }

    // The first x >= from in row y starting a free run of at least `length`, or -1.
    int nextRun(int y, int from, int length) const {
        const int16_t *r = &run_[size_t(y) * side_];
        const int16_t *blockMax = &blockMax_[size_t(y) * blocks_];
        int x = from;
        while (x < side_) {
            const int b = x / kBlock;
            if (blockMax[b] < length) {
                x = (b + 1) * kBlock;
                continue;
            }
            const int end = std::min(side_, (b + 1) * kBlock);
            while (x < end) {
                const int v = r[x];
                if (v >= length)
                    return x;
                x += v > 0 ? v : -v;
            }
        }
        return -1;
    }

    // Marks [x0, x1] of row y taken. A taken texel's value only needs to be a safe jump (its
    // taken stretch never shrinks), so only the span itself and the free texels just left of it
    // (whose runs now end at x0) are rewritten.
    void take(int y, int x0, int x1) {
        int16_t *r = &run_[size_t(y) * side_];
        int16_t next = x1 + 1 < side_ && r[x1 + 1] < 0 ? r[x1 + 1] : int16_t(0);
        for (int x = x1; x >= x0; --x)
            r[x] = --next;
        int x = x0 - 1;
        // Four texels at a time while all four are free (no value is 0: free ones are positive,
        // taken ones negative, so no sign bit means free): texels x - 3 .. x get x0 - x + 3 .. x0 - x.
        for (; x >= 3; x -= 4) {
            uint64_t v;
            std::memcpy(&v, r + x - 3, 8);
            if (v & 0x8000800080008000u)
                break;
            v = uint64_t(x0 - x) * 0x0001000100010001u + 0x0000000100020003u;
            std::memcpy(r + x - 3, &v, 8);
        }
        for (; x >= 0 && r[x] > 0; --x)
            r[x] = int16_t(x0 - x);
        int16_t *blockMax = &blockMax_[size_t(y) * blocks_];
        for (int b = (x + 1) / kBlock; b <= x1 / kBlock; ++b) {
            const int end = std::min(side_, (b + 1) * kBlock);
            blockMax[b] = std::max<int16_t>(0, *std::max_element(r + b * kBlock, r + end));
        }
        widest_[size_t(y)] = *std::max_element(blockMax, blockMax + blocks_);
    }

private:
    int side_, height_, blocks_;                                          // side_: the width
    std::vector<int16_t, DefaultInitAllocator<int16_t>> run_, blockMax_;  // written in full when made
    std::vector<int16_t> widest_;
    std::vector<int> firstRow_;
};

// The lowest, then leftmost, free place for `shape` in a width x height atlas from row y, column x
// on, with a top that `below(top)` accepts (true up to some row, then false). Returns true with
// (y, x) set; false with y at the first row not searched.
//
// A row y is searched only if every row of the shape finds a free run as long as its longest span
// in the atlas row it would cover. When shape row r misses at atlas row Y = y + r (its widest run
// W is shorter), every later y' whose shape row Y - y' needs more than W misses there too: the
// search goes on from the first y' whose row at Y needs at most W (or that is past Y). The rows
// between are only checked against `below`, so y ends where it would without the skip.
constexpr size_t kCheckedRows = 8;
template <class Below>
bool lowestFit(const FreeRuns &runs, const TurnedShape &shape, int side, int height, Below &&below, int &y, int &x) {
    const ShapeSpan &wr = shape.spans[0];
    const int16_t *need = shape.need.data();
    int next = y;        // rows before it are known to miss
    size_t blocked = 0;  // the span that met an obstacle last
    for (; y + shape.height <= height && below(y + shape.height); ++y, x = 0) {
        if (y < next)
            continue;
        int missed = -1;
        for (size_t k = 0; k < std::min(shape.needRows.size(), kCheckedRows); ++k) {
            const int r = shape.needRows[k];
            if (runs.widest(y + r) < need[r]) {
                missed = r;
                break;
            }
        }
        if (missed >= 0) {
            const int widest = runs.widest(y + missed);
            int r = missed - 1;
            while (r >= 0 && need[r] > widest)
                --r;
            next = y + missed - r;
            continue;
        }
        while (x + shape.width <= side) {
            const int p = runs.nextRun(y + wr.row, x + wr.left, wr.length);
            if (p < 0)
                break;
            x = p - wr.left;
            if (x + shape.width > side)
                break;
            // The span that met an obstacle last is tried first: it mostly meets one again.
            bool fits = true;
            for (size_t k = 0; k < shape.spans.size(); ++k) {
                const size_t i = k == 0 ? blocked : k == blocked ? 0 : k;
                if (i == 0)
                    continue;  // the first span fits there (nextRun)
                const ShapeSpan &sp = shape.spans[i];
                const int v = runs.at(y + sp.row, x + sp.left);
                if (v < sp.length) {
                    x += v > 0 ? v + 1 : -v;  // past the obstacle this row met
                    blocked = i;
                    fits = false;
                    break;
                }
            }
            if (fits)
                return true;
        }
    }
    return false;
}

// A second thread for packTight's large charts: share(count, search) calls search(t) for every t
// in [0, count), each t taken by whichever of the caller and the helper comes first, so the
// caller never waits for a helper that has not started, only for a search it is running.
class TurnSharing {
public:
    TurnSharing() : helper_([this] { run(); }) {}
    TurnSharing(const TurnSharing &) = delete;
    TurnSharing &operator=(const TurnSharing &) = delete;
    ~TurnSharing() {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        wake_.notify_one();
        helper_.join();
    }

    // `search` must not throw.
    void share(int count, const std::function<void(int)> &search) {
        std::unique_lock<std::mutex> lock(mutex_);
        search_ = &search, next_ = 0, count_ = count;
        lock.unlock();
        wake_.notify_one();
        for (lock.lock(); next_ < count_; lock.lock()) {
            const int t = next_++;
            lock.unlock();
            search(t);
        }
        done_.wait(lock, [this] { return running_ == 0; });
        search_ = nullptr, count_ = 0;
    }

private:
    void run() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return stop_ || next_ < count_; });
            if (stop_)
                return;
            const int t = next_++;
            const std::function<void(int)> *search = search_;
            ++running_;
            lock.unlock();
            (*search)(t);
            lock.lock();
            if (--running_ == 0)
                done_.notify_one();
        }
    }

    std::mutex mutex_;
    std::condition_variable wake_, done_;
    const std::function<void(int)> *search_ = nullptr;
    int next_ = 0, count_ = 0, running_ = 0;
    bool stop_ = false;
    std::thread helper_;  // last: started once the rest is ready
};

}  // namespace

TightPacking packTight(const ChartMasks &masks, int side, int height, bool allowTurns,
                       std::vector<ChartPlacement> &placements, const ChartBitmaps *bitmaps, int threads) {
    TightPacking result;
    const size_t charts = masks.charts.size();
    placements.assign(charts, ChartPlacement{});
    auto area = [&](uint32_t c) { return int64_t(masks.charts[c].width) * masks.charts[c].height; };
    auto longSide = [&](uint32_t c) { return std::max(masks.charts[c].width, masks.charts[c].height); };
    // Longest side first, then largest area, then chart number: sorted on keys made once (a
    // terrain's 800k charts: the sort through the masks took 14% of its atlas).
    std::vector<std::pair<uint64_t, uint32_t>> keyed(charts);
    for (uint32_t c = 0; c < charts; ++c)  // sides < 2^15, areas < 2^30: ascending keys, descending sizes
        keyed[c] = {~((uint64_t(longSide(c)) << 32) | uint64_t(area(c))), c};
    std::sort(keyed.begin(), keyed.end());
    std::vector<uint32_t> order(charts);
    for (size_t i = 0; i < charts; ++i)
        order[i] = keyed[i].second;

    // Small charts go in as their bounding boxes, in two turns. Where the search for a box size
    // ended is a lower bound for the next box of that size, as the atlas only fills up: each
    // size scans the atlas at most once in all, which keeps thousands of micro charts cheap.
    // Small charts with a bitmap go in by their shape, their search resumed the same way per
    // turned size (a heuristic for them: another shape of that size may fit lower).
    // (width << 32 | height << 8 | turns, or kBoxKey for a box) -> (y, x)
    const int64_t shapedArea = int64_t(side) * height / 1024;
    constexpr uint64_t kBoxKey = 4;
    std::unordered_map<uint64_t, std::pair<int, int>> cursors;
    auto boxed = [&](uint32_t c) { return packedAsBox(area(c), side, height, bitmaps && bitmaps->has(c)); };

    // The room the charts will take (boxes, or row spans) cannot exceed the atlas.
    int64_t needed = 0;
    for (uint32_t c = 0; c < charts; ++c) {
        const ChartMask &m = masks.charts[c];
        if (boxed(c)) {
            needed += area(c);
            continue;
        }
        if (bitmaps && bitmaps->has(c)) {
            needed += int64_t(bitmaps->setBlocks[c]);
            continue;
        }
        const int16_t *l = m.rowLeft(masks.profiles), *r = m.rowRight(masks.profiles);
        for (int y = 0; y < m.height; ++y)
            needed += r[y] - l[y] + 1;
    }
    result.room = size_t(needed);
    if (needed > int64_t(side) * height)
        return result;

    FreeRuns runs(side, height);
    TurnedShape shape, best;
    // Large charts' turns (no cursor) searched side by side on two threads: each search gives up
    // once its top, then its turn, can no longer beat the best found (key top * 4 + turn), so the
    // turn kept is the first with the lowest top, as one after the other.
    std::optional<TurnSharing> sharing;
    TurnedShape turned[4];
    struct TurnFit {
        bool found = false;
        int y = 0, x = 0;
    } fits[4];
    std::atomic<int64_t> bestKey{INT64_MAX};
    ColumnRuns columnRuns;  // the chart's bitmap's columns, found once for its odd turns
    auto needsColumns = [&](uint32_t c) { return allowTurns && bitmaps && bitmaps->has(c) && !boxed(c); };
    // On more threads the columns of the next kColumnChunk charts in order that need them are
    // found ahead, side by side (each reads its own bitmap): order[i]'s in ahead[aheadOf[i - aheadFrom]].
    const int columnWorkers = bandThreads(threads, 2);
    constexpr size_t kColumnChunk = 256;
    std::vector<ColumnRuns> ahead(columnWorkers > 1 ? kColumnChunk : 0);
    std::vector<uint32_t> aheadCharts;
    std::vector<size_t> aheadOf;
    size_t aheadFrom = 0, aheadEnd = 0;  // order[aheadFrom .. aheadEnd) are covered
    for (size_t at = 0; at < charts; ++at) {
        const uint32_t c = order[at];
        const bool box = boxed(c), small = area(c) < shapedArea;
        const uint8_t *bits = bitmaps && bitmaps->has(c) ? bitmaps->of(c) : nullptr;
        const ColumnRuns *columns = nullptr;
        if (needsColumns(c) && columnWorkers > 1) {
            if (at >= aheadEnd) {
                aheadFrom = at;
                aheadCharts.clear();
                aheadOf.clear();
                for (aheadEnd = at; aheadEnd < charts && aheadCharts.size() < kColumnChunk; ++aheadEnd) {
                    const bool need = needsColumns(order[aheadEnd]);
                    aheadOf.push_back(need ? aheadCharts.size() : SIZE_MAX);
                    if (need)
                        aheadCharts.push_back(order[aheadEnd]);
                }
                runBands(aheadCharts.size(), columnWorkers, [&](size_t k) {
                    const uint32_t d = aheadCharts[k];
                    findColumnRuns(bitmaps->of(d), masks.charts[d].width, masks.charts[d].height, ahead[k]);
                });
            }
            columns = &ahead[aheadOf[at - aheadFrom]];
        } else if (needsColumns(c)) {
            findColumnRuns(bits, masks.charts[c].width, masks.charts[c].height, columnRuns);
            columns = &columnRuns;
        }
        int bestTop = INT32_MAX;
        const bool shared = !small && allowTurns && bandThreads(threads, 2) > 1;
        if (shared) {
            if (!sharing)
                sharing.emplace();
            bestKey = INT64_MAX;
            const std::function<void(int)> search = [&](int t) {
                fits[t].found = false;
                TurnedShape &sh = turned[t];
                turnedShape(masks.charts[c], masks.profiles, t, false, bits, columns, sh);
                if (sh.width > side || sh.height > height)
                    return;
                int y = std::max(0, runs.firstRowFrom(sh.spans[0].length) - sh.spans[0].row), x = 0;
                auto below = [&](int top) { return int64_t(top) * 4 + t < bestKey.load(std::memory_order_relaxed); };
                if (!lowestFit(runs, sh, side, height, below, y, x))
                    return;
                fits[t] = {true, y, x};
                const int64_t key = int64_t(y + sh.height) * 4 + t;
                int64_t seen = bestKey.load();
                while (key < seen && !bestKey.compare_exchange_weak(seen, key)) {
                }
            };
            sharing->share(4, search);
            int chosen = -1;
            for (int t = 0; t < 4; ++t)
                if (fits[t].found && (chosen < 0 || fits[t].y + turned[t].height < bestTop))
                    chosen = t, bestTop = fits[t].y + turned[t].height;
            if (chosen >= 0) {
                placements[c] = {fits[chosen].x, fits[chosen].y, chosen};
                std::swap(best, turned[chosen]);
            }
        }
        for (int turns = 0; turns < (allowTurns ? (box ? 2 : 4) : 1) && !shared; ++turns) {
            turnedShape(masks.charts[c], masks.profiles, turns, box, bits, columns, shape);
            if (shape.width > side || shape.height > height)
                continue;
            int y = std::max(0, runs.firstRow(shape.spans[0].length) - shape.spans[0].row), x = 0;
            std::pair<int, int> *cursor = nullptr;
            if (small) {  // boxes are small too
                const uint64_t key =
                    uint64_t(shape.width) << 32 | uint64_t(shape.height) << 8 | (box ? kBoxKey : uint64_t(turns));
                cursor = &cursors.try_emplace(key, 0, 0).first->second;
                if (cursor->first >= y)
                    std::tie(y, x) = *cursor;
            }
            const bool found = lowestFit(
                runs, shape, side, height, [bestTop](int top) { return top < bestTop; }, y, x);
            if (cursor)  // nothing of this size fits before here, now or later
                *cursor = {y, found ? x : 0};
            if (found) {
                bestTop = y + shape.height;
                placements[c] = {x, y, turns};
                std::swap(best, shape);
            }
        }
        if (bestTop == INT32_MAX)
            return result;
        result.top = std::max(result.top, bestTop);
        const ChartPlacement &p = placements[c];
        for (const ShapeSpan &sp : best.spans) {
            result.placedRoom += size_t(sp.length);
            runs.take(p.y + sp.row, p.x + sp.left, p.x + sp.left + sp.length - 1);
        }
    }
    result.fits = true;
    return result;
}

}  // namespace voxelfair
