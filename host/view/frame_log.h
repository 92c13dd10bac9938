#pragma once
// --frame-log FILE: one CSV row a presented frame (frame time, the scene's render time, preview fraction,
// filters, the dynamic texture's frame (-1: none) and rebuild time), for the viewer benchmark
// (docs/BENCHMARKS.md, docs/VIEWER.md). Written atomically when the viewer ends.
#include <string>

namespace tf {

struct Viewer;

struct FrameLog {
    std::string path; // empty: no log
    std::string rows;
    int frames = 0;
    explicit FrameLog(std::string path);
    void add(const Viewer& viewer);
    void write() const;
};

} // namespace tf
