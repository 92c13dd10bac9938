#include "io/report.h"
#include "io/output_path.h"

#include "texture/error.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace tf {
namespace {

// Good for both element text and double-quoted attribute values.
std::string escape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        default: out += c;
        }
    }
    return out;
}

// Each image column: the picture (or a note that there is none) with a caption.
void image_cell(std::ostringstream& html, const std::string& label, const std::string& src) {
    html << "<figure><figcaption>" << escape(label) << "</figcaption>";
    if (src.empty()) html << "<div class=\"missing\">no image</div>";
    else html << "<a href=\"" << escape(src) << "\"><img src=\"" << escape(src) << "\" width=\"256\" alt=\""
              << escape(label) << "\"></a>";
    html << "</figure>\n";
}

std::string render(const std::string& title, const std::vector<ReportCase>& cases) {
    int passed = 0, failed = 0;
    for (const ReportCase& c : cases) (c.pass ? passed : failed)++;

    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << escape(title)
         << "</title>\n<style>\n"
            "body { font-family: sans-serif; margin: 1.5em; }\n"
            ".summary { font-size: 1.2em; }\n"
            ".fail-text { color: #b00; font-weight: bold; } .pass-text { color: #070; }\n"
            ".case { border: 2px solid #b00; padding: 0.5em 1em; margin: 1em 0; }\n"
            ".images { display: flex; gap: 1em; flex-wrap: wrap; }\n"
            "figure { margin: 0; } figcaption { font-weight: bold; }\n"
            "img { image-rendering: pixelated; width: 256px; height: auto; background: #888; }\n"
            ".missing { width: 256px; height: 64px; background: #eee; color: #666; text-align: center; "
            "line-height: 64px; }\n"
            "pre { margin: 0.3em 0; font-size: 0.9em; }\n"
            "table { border-collapse: collapse; } td, th { border: 1px solid #ccc; padding: 0.2em 0.6em; "
            "vertical-align: top; text-align: left; }\n"
            "</style>\n</head>\n<body>\n";
    html << "<h1>" << escape(title) << "</h1>\n";
    html << "<p class=\"summary\"><span class=\"pass-text\">" << passed << " passed</span>, <span class=\""
         << (failed ? "fail-text" : "pass-text") << "\">" << failed << " failed</span> (" << cases.size()
         << " cases)</p>\n";

    if (failed) {
        html << "<h2>Failed</h2>\n";
        for (const ReportCase& c : cases) {
            if (c.pass) continue;
            html << "<div class=\"case\">\n<h3 class=\"fail-text\">FAIL " << escape(c.name) << "</h3>\n";
            html << "<div class=\"images\">\n";
            image_cell(html, "actual", c.actual_png);
            image_cell(html, "golden", c.golden_png);
            image_cell(html, "diff", c.diff_png);
            html << "</div>\n<pre>" << escape(c.numbers) << "</pre>\n</div>\n";
        }
    }
    if (passed) {
        html << "<h2>Passed</h2>\n<table>\n<tr><th>case</th><th>numbers</th></tr>\n";
        for (const ReportCase& c : cases) {
            if (!c.pass) continue;
            html << "<tr><td class=\"pass-text\">" << escape(c.name) << "</td><td><pre>" << escape(c.numbers)
                 << "</pre></td></tr>\n";
        }
        html << "</table>\n";
    }
    html << "</body>\n</html>\n";
    return html.str();
}

} // namespace

void write_html_report(const std::string& path, const std::string& title, const std::vector<ReportCase>& cases) {
    write_file_atomic(path, render(title, cases));
}

} // namespace tf
