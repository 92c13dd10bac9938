// bench.json and bench.csv: the format tools/bench_report.py and tools/bench_check.py read (schema 1,
// docs/BENCHMARKS.md). Non-finite numbers are written as null, so a reader sees them rather than a parse error.
#include "bench/bench.h"
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tf {

namespace {

std::string number(double value)
{
    if (!std::isfinite(value))
        return "null";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::string quoted(const std::string& text)
{
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\')
            out += '\\', out += c;
        else if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        } else
            out += c;
    }
    return out + "\"";
}

std::string times(const TimeSummary& t)
{
    return "{\"min\": " + number(t.min) + ", \"median\": " + number(t.median) + ", \"max\": " + number(t.max) +
           ", \"frames\": " + std::to_string(t.frames) + "}";
}

template <typename Items, typename Write>
std::string list(const Items& items, Write write, const std::string& indent)
{
    std::string out = "[";
    bool first = true;
    for (const auto& item : items) {
        out += (first ? "\n" : ",\n") + indent + write(item);
        first = false;
    }
    return out + (first ? "]" : "\n" + indent.substr(1) + "]");
}

} // namespace

std::string bench_json(const BenchRun& run)
{
    const BenchConfig& c = run.config;
    std::ostringstream o;
    o << "{\n \"schema\": 1,\n";
    o << " \"device\": " << quoted(run.device.name) << ",\n";
    o << " \"device_type\": " << quoted(run.device.type) << ",\n";
    o << " \"driver\": " << quoted(run.device.driver_name + " " + run.device.driver_info) << ",\n";
    o << " \"vulkan\": " << quoted(version_string(run.device.api_version)) << ",\n";
    o << " \"date\": " << quoted(run.date) << ",\n";
    o << " \"config\": {\"quick\": " << (c.quick ? "true" : "false") << ", \"width\": " << c.width
      << ", \"height\": " << c.height << ", \"stage\": " << quoted(to_string(c.stage))
      << ", \"texture\": " << quoted(c.texture.name_or_path) << ", \"texture_size\": " << c.texture.procedural_size
      << ", \"spp\": " << c.truth_side * c.truth_side << ", \"truth_backend\": "
      << quoted(c.truth_on_cpu ? "reference" : "vulkan") << ", \"warmup\": " << c.warmup << ", \"frames\": " << c.frames
      << ", \"flicker_frames\": " << c.flicker_frames << ", \"timer\": " << quoted(to_string(c.timer)) << ", \"camera_step_texels\": [" << number(camera_step_texels.x)
      << ", " << number(camera_step_texels.y) << "],\n  \"scenes\": "
      << list(c.scenes, [](SceneKind k) { return quoted(to_string(k)); }, "   ") << ",\n  \"labels\": "
      << list(c.filters, [](const BenchFilter& f) { return quoted(f.label); }, "   ") << "},\n";
    o << " \"baseline_ms\": {";
    bool first = true;
    for (const auto& [scene, t] : run.baseline) {
        o << (first ? "" : ", ") << quoted(to_string(scene)) << ": " << times(t);
        first = false;
    }
    o << "},\n \"truth\": {";
    first = true;
    for (SceneKind scene : c.scenes) {
        if (!run.truth_box.count(scene))
            continue;
        o << (first ? "\n  " : ",\n  ") << quoted(to_string(scene)) << ": {\"box\": [" << quoted(run.truth_box.at(scene))
          << "], \"gaussian\": [" << quoted(run.truth_gaussian.at(scene)) << "]}";
        first = false;
    }
    o << "},\n \"results\": "
      << list(run.results,
              [](const BenchResult& r) {
                  return "{\"scene\": " + quoted(to_string(r.scene)) + ", \"label\": " + quoted(r.filter.label) +
                         ", \"filter\": " + quoted(to_string(r.filter.options.filter)) + ", \"args\": " +
                         quoted(r.filter.args) + ", \"hardware\": " + (is_hardware(r.filter.options.filter) ? "true" : "false") +
                         ", \"stage\": " + quoted(to_string(r.stage)) + ",\n   \"time_ms\": " + times(r.time) +
                         ", \"time_vs_hw_trilinear\": " + number(r.vs_hw_trilinear) +
                         ", \"time_vs_baseline\": " + number(r.vs_baseline) +
                         ",\n   \"fetches_per_pixel\": " + number(r.fetches_per_pixel) +
                         ", \"hw_lookups_per_pixel\": " + number(r.hw_lookups_per_pixel) +
                         ",\n   \"error\": {\"box\": {\"rmse\": " + number(r.rmse_box) + ", \"psnr\": " +
                         number(psnr_from_rmse(r.rmse_box)) + "}, \"gaussian\": {\"rmse\": " + number(r.rmse_gaussian) +
                         ", \"psnr\": " + number(psnr_from_rmse(r.rmse_gaussian)) + "}}" +
                         ", \"flicker\": {\"box\": " + number(r.flicker_box) + ", \"gaussian\": " +
                         number(r.flicker_gaussian) + "}" + ",\n   \"images\": [" + quoted(r.image) + "]}";
              },
              "  ")
      << ",\n \"sat_sweep\": "
      << list(run.sat_sweep,
              [](const SatSweep& s) {
                  return "{\"label\": " + quoted(s.label) + ", \"minify_2x_ms\": " + times(s.at_2x) +
                         ", \"minify_64x_ms\": " + times(s.at_64x) + "}";
              },
              "  ")
      << ",\n \"goals\": "
      << list(run.goals,
              [](const BenchGoal& g) {
                  return "{\"goal\": " + quoted(g.goal) + ", \"measured\": " + quoted(g.measured) +
                         ", \"status\": " + quoted(g.status) + ", \"note\": " + quoted(g.note) + "}";
              },
              "  ")
      << "\n}\n";
    return o.str();
}

std::string bench_csv(const BenchRun& run)
{
    std::string out = "scene,label,filter,hardware,time_min_ms,time_median_ms,time_max_ms,time_vs_hw_trilinear,"
                      "time_vs_baseline,fetches_per_pixel,hw_lookups_per_pixel,rmse_box,psnr_box,rmse_gaussian,"
                      "psnr_gaussian,flicker_box,flicker_gaussian\n";
    auto csv_number = [](double v) { return std::isfinite(v) ? number(v) : std::string(); };
    for (const BenchResult& r : run.results) {
        const double values[] = {r.time.min, r.time.median, r.time.max, r.vs_hw_trilinear, r.vs_baseline,
                                 r.fetches_per_pixel, r.hw_lookups_per_pixel, r.rmse_box, psnr_from_rmse(r.rmse_box),
                                 r.rmse_gaussian, psnr_from_rmse(r.rmse_gaussian), r.flicker_box, r.flicker_gaussian};
        out += to_string(r.scene) + "," + r.filter.label + "," + to_string(r.filter.options.filter) + "," +
               (is_hardware(r.filter.options.filter) ? "true" : "false");
        for (double v : values)
            out += "," + csv_number(v);
        out += "\n";
    }
    return out;
}

} // namespace tf
