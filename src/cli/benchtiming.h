// Timing of kontur-cli's benchmarks: repeated samples after one warm-up, in nanoseconds per operation.
#pragma once

#include <chrono>
#include <functional>
#include <vector>

namespace kontur::cli {

struct BenchTiming
{
    std::vector<double> samples; // nanoseconds per operation, one per timed sample
    double checksum = 0.0;       // keeps the optimiser from dropping the work
    const char *per = "operation";
};

// Runs `sample` (which performs `opsPerSample` operations and returns a checksum) once to warm up
// caches, page faults and allocations, then `repeat` timed times.
inline BenchTiming measure(int repeat, double opsPerSample, const std::function<double()> &sample)
{
    using Clock = std::chrono::steady_clock;
    BenchTiming timing;
    timing.checksum += sample();
    for (int r = 0; r < repeat; ++r) {
        const auto start = Clock::now();
        timing.checksum += sample();
        const auto stop = Clock::now();
        timing.samples.push_back(std::chrono::duration<double, std::nano>(stop - start).count() / opsPerSample);
    }
    return timing;
}

} // namespace kontur::cli
