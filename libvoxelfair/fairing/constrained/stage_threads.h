// The threads of one call of fairConstrained: the caller and a few helpers kept for the whole
// call, which run the data-parallel stages (each vertex's, polygon's or slot's result depends on
// the stage's input alone, not on the order it is computed in) chunk by chunk.
//
// Contract: run(chunks, chunk) calls chunk(c) exactly once for every c in [0, chunks), on any of
// the threads, in any order, and returns when all have returned; `chunk` must not throw.
// forRanges(n, grain, range) calls range(first, last) on the ranges [0, grain), [grain, 2 grain),
// ... of [0, n). A stage whose chunks write disjoint results, with only order-free reductions
// across chunks (or, max, integer counts), gives the same bits for any count().
//
// Why helpers that stay and chunks that are claimed: starting threads for every stage (and every
// Jacobi round of step 5) costs tens of microseconds each, and on a loaded machine a thread that
// is descheduled for a time slice would hold a statically split round that long. Here the
// caller claims chunks too, and a helper that wakes late finds none left: nobody waits for a
// thread that has not started. A helper spins a short while for the next run and then sleeps on
// a condition variable, so back-to-back runs cost little and a helper waiting through a serial
// stage (the sweeps) holds no core.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

#if defined(__SSE2__) || defined(_M_X64) || defined(_M_AMD64)
#include <emmintrin.h>
#endif

namespace voxelfair::constrained {

class StageThreads {
public:
    // `count` threads in all (the caller is one); at least 1.
    explicit StageThreads(int count) : count_(std::max(count, 1)) {
        helpers_.reserve(size_t(count_ - 1));
        for (int t = 1; t < count_; ++t)
            helpers_.emplace_back([this] { serve(); });
    }
    ~StageThreads() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_.store(true, std::memory_order_release);
        }
        wake_.notify_all();
        for (std::thread &t : helpers_)
            t.join();
    }
    StageThreads(const StageThreads &) = delete;
    StageThreads &operator=(const StageThreads &) = delete;

    int count() const { return count_; }

    template <class Chunk>
    void run(size_t chunks, Chunk &&chunk) {
        if (count_ == 1 || chunks <= 1) {
            for (size_t c = 0; c < chunks; ++c)
                chunk(c);
            return;
        }
        for (size_t first = 0; first < chunks; first += kMaxChunks) {  // (one run almost always)
            const size_t count = std::min(chunks - first, kMaxChunks);
            auto part = [&chunk, first](size_t c) { chunk(first + c); };
            runPart(count, part);
        }
    }
    template <class Range>
    void forRanges(size_t n, size_t grain, Range &&range) {
        run((n + grain - 1) / grain, [&](size_t c) { range(c * grain, std::min(n, (c + 1) * grain)); });
    }

    // Work beside a serial stage: startAside(task) has a helper call task(0) while the caller goes
    // on (with one thread, task(0) runs here and now); joinAside() returns when it has returned
    // (running it here if no helper has taken it yet). `task` must live until then and must not
    // call run(); the caller calls no run() in between, and neither touches what the other writes.
    template <class Task>
    void startAside(Task &task) {
        if (count_ == 1) {
            task(size_t(0));
            return;
        }
        asideGeneration_ = publish(1, task);
        aside_ = true;
    }
    void joinAside() {
        if (!aside_)
            return;
        aside_ = false;
        work(asideGeneration_, true);
        for (unsigned spins = 0; done_.load(std::memory_order_acquire) != 1; ++spins)
            pause(spins);
    }

private:
    static void pause(unsigned spins) {
        if (spins < kSpins) {
#if defined(__SSE2__) || defined(_M_X64) || defined(_M_AMD64)
            _mm_pause();
#endif
        } else {
            std::this_thread::yield();
        }
    }
    // Claims and runs chunks of run `generation` until none is left. The claim word holds the
    // run's generation and the unclaimed chunks [front, back): the caller takes them from the
    // front, the helpers from the back, so that each thread works on about the same part of the
    // arrays from one run to the next (its cache holds them) wherever the two meet.
    void work(uint64_t generation, bool fromFront) {
        void *const job = job_.load(std::memory_order_relaxed);
        void (*const call)(void *, size_t) = call_.load(std::memory_order_relaxed);
        uint64_t claim = claim_.load(std::memory_order_acquire);
        for (;;) {
            const uint64_t front = claim >> kFrontShift & kChunkMask, back = claim & kChunkMask;
            if (claim >> kGenerationShift != generation || front >= back)
                return;
            const uint64_t claimed = fromFront ? claim + (uint64_t(1) << kFrontShift) : claim - 1;
            if (!claim_.compare_exchange_weak(claim, claimed, std::memory_order_acq_rel))
                continue;
            call(job, size_t(fromFront ? front : back - 1));
            done_.fetch_add(1, std::memory_order_release);
            claim = claim_.load(std::memory_order_acquire);
        }
    }
    template <class Chunk>
    void runPart(size_t chunks, Chunk &chunk) {
        work(publish(chunks, chunk), true);
        for (unsigned spins = 0; done_.load(std::memory_order_acquire) != chunks; ++spins)
            pause(spins);
    }
    // Makes `chunks` chunks of `chunk` claimable and wakes the helpers; returns the run's generation.
    template <class Chunk>
    uint64_t publish(size_t chunks, Chunk &chunk) {
        // Published before the claim word: a thread whose claim of this run succeeds sees them.
        using Job = std::remove_reference_t<Chunk>;
        job_.store(const_cast<void *>(static_cast<const void *>(&chunk)), std::memory_order_relaxed);
        call_.store([](void *job, size_t c) { (*static_cast<Job *>(job))(c); }, std::memory_order_relaxed);
        done_.store(0, std::memory_order_relaxed);
        const uint64_t generation =
            ((claim_.load(std::memory_order_relaxed) >> kGenerationShift) + 1) & kGenerationMask;
        {
            std::lock_guard<std::mutex> lock(mutex_);  // a helper about to sleep sees the new run
            claim_.store(generation << kGenerationShift | uint64_t(chunks), std::memory_order_release);
        }
        wake_.notify_all();
        return generation;
    }
    void serve() {
        uint64_t seen = 0;
        for (;;) {
            auto fresh = [&] {
                return claim_.load(std::memory_order_acquire) >> kGenerationShift != seen ||
                       stop_.load(std::memory_order_acquire);
            };
            for (unsigned spins = 0; !fresh() && spins < kSpins; ++spins)
                pause(spins);
            if (!fresh()) {
                std::unique_lock<std::mutex> lock(mutex_);
                wake_.wait(lock, fresh);
            }
            if (stop_.load(std::memory_order_acquire))
                return;
            seen = claim_.load(std::memory_order_acquire) >> kGenerationShift;
            work(seen, false);
        }
    }

    // The claim word: generation (16 bits; a helper that sleeps through 65,536 runs at most misses
    // one, which the caller then runs alone), front and back (24 bits each).
    static constexpr int kGenerationShift = 48, kFrontShift = 24;
    static constexpr uint64_t kGenerationMask = 0xffff, kChunkMask = 0xffffff;
    static constexpr size_t kMaxChunks = kChunkMask;
    static constexpr unsigned kSpins = 1u << 11;  // some tens of microseconds of pause instructions
    const int count_;
    std::vector<std::thread> helpers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::atomic<uint64_t> claim_{0};
    std::atomic<size_t> done_{0};
    std::atomic<void *> job_{nullptr};
    std::atomic<void (*)(void *, size_t)> call_{nullptr};
    std::atomic<bool> stop_{false};
    uint64_t asideGeneration_ = 0;  // the caller's alone
    bool aside_ = false;
};

}  // namespace voxelfair::constrained
