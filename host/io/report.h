#pragma once
// HTML report of a golden-image regression run: one self-contained file, no scripts or external assets.
#include <string>
#include <vector>

namespace tf {

struct ReportCase {
    std::string name;
    bool pass = false;
    std::string numbers;     // describe() text
    std::string actual_png;  // paths relative to the report; may be empty (typically when passing)
    std::string golden_png;
    std::string diff_png;
};

// Failures first (actual / golden / diff side by side, numbers under each), then passes as compact
// table rows. Input order is kept within each group. Written to a temporary file and renamed, so a
// reader never sees half a report. Throws tf::Error naming the path on failure.
void write_html_report(const std::string& path, const std::string& title, const std::vector<ReportCase>& cases);

} // namespace tf
