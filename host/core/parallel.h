#pragma once
// parallel_for: the CPU reference's only threading primitive (rows or chunks of work over every core).
#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace tf {

// Runs body(i) for i in [0, count) on every core; the first exception from a worker is rethrown here.
template <typename Body>
void parallel_for(size_t count, Body body)
{
    unsigned threads = std::max(1u, std::min(std::thread::hardware_concurrency(), 64u));
    std::atomic<size_t> next{0};
    std::exception_ptr failure;
    std::atomic<bool> failed{false};
    auto work = [&] {
        try {
            for (size_t i; !failed && (i = next.fetch_add(1)) < count;)
                body(i);
        } catch (...) {
            if (!failed.exchange(true))
                failure = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread& t : pool)
        t.join();
    if (failure)
        std::rethrow_exception(failure);
}

} // namespace tf
