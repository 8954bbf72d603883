// Work the canvas spreads over the machine's cores (the flattening of curves that come into sight,
// the bands of a layer picture): how many threads, and running one piece of work on them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace kontur {

// The processors this machine has (at least 1).
inline std::size_t cores()
{
    return std::max<std::size_t>(1, std::thread::hardware_concurrency());
}

// Threads for `work` units when each thread should have at least `perThread` of them: 1 below
// that, and never more than the cores or 8.
inline std::size_t threadsFor(std::size_t work, std::size_t perThread)
{
    return std::clamp<std::size_t>(work / perThread, 1, std::min<std::size_t>(cores(), 8));
}

// Runs `work` on `threads` threads (this one among them) and waits for all; `work` takes its
// share itself (a shared counter).
template <typename Work> void onThreads(std::size_t threads, const Work &work)
{
    std::vector<std::jthread> others;
    others.reserve(threads > 0 ? threads - 1 : 0);
    for (std::size_t k = 1; k < threads; ++k)
        others.emplace_back(work);
    work();
}

} // namespace kontur
