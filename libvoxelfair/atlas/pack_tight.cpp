#include "atlas/pack_tight.h"

#include "base/parallel_bands.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <mutex>
#include <numeric>
#include <optional>
#include <thread>
#include <tuple>
#include <unordered_map>

namespace voxelfair {
namespace {

// A chart as the search sees it, after a quarter turn: its rows' spans, longest first. A row
// is one span between its leftmost and rightmost texel, or, for a chart with a bitmap
// (chart_bitmaps.h), each run of its set texels, so holes inside its rows are left free.
struct Span {
    int16_t row, left, length;
};
struct Shape {
    int width = 0, height = 0;
    std::vector<int16_t> left, right;
    std::vector<Span> spans;
    // Per row, its longest span (0: none); and the rows with a span, longest first (as the spans).
    std::vector<int16_t> need;
    std::vector<int16_t> needRows;
};

// The first c in [from, right] where the bitmap byte row[c * stride] (0 or 1) is set (`set`) or
// not, right + 1 if none. Along a stored row (stride 1 or -1) eight bytes at a time.
int nextByte(const uint8_t *row, ptrdiff_t stride, int from, int right, bool set) {
    const uint64_t flip = set ? 0 : 0x0101010101010101u;  // set bytes of the word: the ones sought
    int c = from;
    if (stride == 1) {
        for (; c + 8 <= right + 1; c += 8) {
            uint64_t v;
            std::memcpy(&v, row + c, 8);
            if ((v ^= flip) != 0)
                return c + __builtin_ctzll(v) / 8;
        }
    } else if (stride == -1) {  // c runs down through memory: the word ending at row - c
        for (; c + 8 <= right + 1; c += 8) {
            uint64_t v;
            std::memcpy(&v, row - c - 7, 8);
            if ((v ^= flip) != 0)
                return c + (__builtin_clzll(v) - 7) / 8;
        }
    }
    while (c <= right && (row[c * stride] != 0) != set)
        ++c;
    return c;
}

// The shape of mask `m` turned by `turns` quarter turns counter-clockwise (turnInMask), or its
// bounding box.
void turnedShape(const ChartMask &m, const std::vector<int16_t> &profiles, int turns, bool box, const uint8_t *bits,
                 Shape &s) {
    const int16_t *colBottom = m.colBottom(profiles), *colTop = m.colTop(profiles);
    const int16_t *rowLeft = m.rowLeft(profiles), *rowRight = m.rowRight(profiles);
    const int w = m.width, h = m.height;
    s.width = turns & 1 ? h : w;
    s.height = turns & 1 ? w : h;
    s.left.resize(size_t(s.height));
    s.right.resize(size_t(s.height));
    for (int r = 0; r < s.height; ++r) {
        int16_t &left = s.left[size_t(r)], &right = s.right[size_t(r)];
        if (box) {
            left = 0, right = int16_t(s.width - 1);
            continue;
        }
        switch (turns) {
        case 0: left = rowLeft[r], right = rowRight[r]; break;
        case 1: left = int16_t(h - 1 - colTop[r]), right = int16_t(h - 1 - colBottom[r]); break;
        case 2: left = int16_t(w - 1 - rowRight[h - 1 - r]), right = int16_t(w - 1 - rowLeft[h - 1 - r]); break;
        default: left = colBottom[w - 1 - r], right = colTop[w - 1 - r]; break;
        }
    }
    s.spans.clear();
    if (box || bits == nullptr) {
        for (int r = 0; r < s.height; ++r)
            s.spans.push_back({int16_t(r), s.left[size_t(r)], int16_t(s.right[size_t(r)] - s.left[size_t(r)] + 1)});
    } else {
        // The bitmap read through the turn (the profiles' mapping above, texel by texel): row r
        // of the turned shape starts at bits[origin(r)] and steps by `stride` per column.
        ptrdiff_t stride = 1;
        auto origin = [&](int r) -> ptrdiff_t {
            switch (turns) {
            case 0: return ptrdiff_t(r) * w;
            case 1: return ptrdiff_t(h - 1) * w + r;
            case 2: return ptrdiff_t(h - 1 - r) * w + (w - 1);
            default: return w - 1 - r;
            }
        };
        switch (turns) {
        case 0: stride = 1; break;
        case 1: stride = -w; break;
        case 2: stride = -1; break;
        default: stride = w; break;
        }
        for (int r = 0; r < s.height; ++r) {
            const uint8_t *row = bits + origin(r);
            const int right = s.right[size_t(r)];
            for (int c = s.left[size_t(r)]; c <= right;) {
                c = nextByte(row, stride, c, right, true);
                if (c > right)
                    break;
                const int start = c;
                c = nextByte(row, stride, c, right, false);
                s.spans.push_back({int16_t(r), int16_t(start), int16_t(c - start)});
            }
        }
    }
    // The longest span admits the fewest places, so it is tested first and the others mostly
    // confirm it.
    std::stable_sort(s.spans.begin(), s.spans.end(), [](const Span &a, const Span &b) { return a.length > b.length; });
    s.need.assign(size_t(s.height), 0);
    s.needRows.clear();
    for (const Span &sp : s.spans)
        if (s.need[size_t(sp.row)] == 0) {
            s.need[size_t(sp.row)] = sp.length;
            s.needRows.push_back(sp.row);
        }
}

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
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x)
                run_[size_t(y) * width + x] = int16_t(width - x);
            for (int b = 0; b < blocks_; ++b)
                blockMax_[size_t(y) * blocks_ + b] = int16_t(width - b * kBlock);
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
    int side_, height_, blocks_;  // side_: the width
    std::vector<int16_t> run_, blockMax_, widest_;
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
bool lowestFit(const FreeRuns &runs, const Shape &shape, int side, int height, Below &&below, int &y, int &x) {
    const Span &wr = shape.spans[0];
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
                const Span &sp = shape.spans[i];
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
    std::vector<uint32_t> order(charts);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        if (longSide(a) != longSide(b))
            return longSide(a) > longSide(b);
        return area(a) != area(b) ? area(a) > area(b) : a < b;
    });

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
    Shape shape, best;
    // Large charts' turns (no cursor) searched side by side on two threads: each search gives up
    // once its top, then its turn, can no longer beat the best found (key top * 4 + turn), so the
    // turn kept is the first with the lowest top, as one after the other.
    std::optional<TurnSharing> sharing;
    Shape turned[4];
    struct TurnFit {
        bool found = false;
        int y = 0, x = 0;
    } fits[4];
    std::atomic<int64_t> bestKey{INT64_MAX};
    for (uint32_t c : order) {
        const bool box = boxed(c), small = area(c) < shapedArea;
        const uint8_t *bits = bitmaps && bitmaps->has(c) ? bitmaps->of(c) : nullptr;
        int bestTop = INT32_MAX;
        const bool shared = !small && allowTurns && bandThreads(threads, 2) > 1;
        if (shared) {
            if (!sharing)
                sharing.emplace();
            bestKey = INT64_MAX;
            const std::function<void(int)> search = [&](int t) {
                fits[t].found = false;
                Shape &sh = turned[t];
                turnedShape(masks.charts[c], masks.profiles, t, false, bits, sh);
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
            turnedShape(masks.charts[c], masks.profiles, turns, box, bits, shape);
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
        for (const Span &sp : best.spans) {
            result.placedRoom += size_t(sp.length);
            runs.take(p.y + sp.row, p.x + sp.left, p.x + sp.left + sp.length - 1);
        }
    }
    result.fits = true;
    return result;
}

}  // namespace voxelfair
