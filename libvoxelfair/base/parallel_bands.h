// Work split into numbered bands (for the bakers: runs of texel rows), run on up to `threads`
// std::threads that take the next band from a shared counter. Each band's result must depend on
// the band alone, never on which thread ran it or when: then the output is the same for any
// thread count (the bakers write only their own band's rows).
#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace voxelfair {

// Threads to use for `requested` (0: one per hardware thread), at most `bands`, at least 1.
inline int bandThreads(int requested, size_t bands) {
    int n = requested > 0 ? requested : int(std::thread::hardware_concurrency());
    n = std::clamp(n, 1, 64);
    return int(std::max<size_t>(1, std::min(size_t(n), bands)));
}

// Calls band(b, worker) once for every b in [0, bands), worker in [0, bandThreads(threads, bands))
// naming the thread that runs it (for per-thread scratch buffers); returns when all are done.
// `band` must not throw.
template <class Band>
void runWorkerBands(size_t bands, int threads, Band &&band) {
    const int n = bandThreads(threads, bands);
    if (n <= 1) {
        for (size_t b = 0; b < bands; ++b)
            band(b, 0);
        return;
    }
    std::atomic<size_t> next{0};
    auto work = [&](int worker) {
        for (size_t b = next++; b < bands; b = next++)
            band(b, worker);
    };
    std::vector<std::thread> pool;
    pool.reserve(size_t(n - 1));
    for (int t = 1; t < n; ++t)
        pool.emplace_back(work, t);
    work(0);
    for (std::thread &t : pool)
        t.join();
}

// Calls band(b) once for every b in [0, bands); returns when all are done. `band` must not throw.
template <class Band>
void runBands(size_t bands, int threads, Band &&band) {
    runWorkerBands(bands, threads, [&band](size_t b, int) { band(b); });
}

}  // namespace voxelfair
