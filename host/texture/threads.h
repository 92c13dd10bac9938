#pragma once
// The texture library's one threading primitive (not installed): body(t) for t in [0, count) on its own
// thread each (t = 0 on the caller's); the first exception is rethrown here after every thread has ended.
#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace tf {

inline unsigned hardware_threads() { return std::max(1u, std::min(std::thread::hardware_concurrency(), 64u)); }

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

} // namespace tf
