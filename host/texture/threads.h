#pragma once
// The host's one threading primitive (not installed; the lowest layer, so the texture library and the CPU
// reference share it): run_on_threads gives body(t) a thread each, parallel_for hands out indices.
#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace tf {

inline unsigned hardware_threads() { return std::max(1u, std::min(std::thread::hardware_concurrency(), 64u)); }

// body(t) for t in [0, count) on its own thread each (t = 0 on the caller's); the first exception (in t
// order) is rethrown here after every thread has ended.
template <typename Body>
void run_on_threads(unsigned count, Body body)
{
    std::vector<std::exception_ptr> failures(count);
    auto run = [&](unsigned t) {
        try {
            body(t);
        } catch (...) {
            failures[t] = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < count; ++t)
        pool.emplace_back(run, t);
    run(0);
    for (std::thread& thread : pool)
        thread.join();
    for (const std::exception_ptr& failure : failures)
        if (failure)
            std::rethrow_exception(failure);
}

// body(i) for i in [0, count) on every core, indices handed out one at a time; after an exception no new
// index starts, and the exception is rethrown here.
template <typename Body>
void parallel_for(size_t count, Body body)
{
    std::atomic<size_t> next{0};
    std::atomic<bool> failed{false};
    run_on_threads(hardware_threads(), [&](unsigned) {
        try {
            for (size_t i; !failed && (i = next.fetch_add(1)) < count;)
                body(i);
        } catch (...) {
            failed = true;
            throw;
        }
    });
}

} // namespace tf
