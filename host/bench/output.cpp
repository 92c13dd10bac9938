// bench.json and bench.csv: the format tools/bench_report.py and tools/bench_check.py read (schema 1,
// docs/BENCHMARKS.md), JSON through nlohmann-json. Non-finite numbers are written as null, so a reader sees them
// rather than a parse error.
#include "bench/bench.h"
#include "core/analytic_texture.h"
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace tf {

namespace {

using Json = nlohmann::ordered_json; // keeps the keys in the order written: a readable file

// Non-finite numbers become null: nlohmann::json writes NaN and ±Inf as null.
Json times(const TimeSummary& t)
{
    return {{"min", t.min}, {"median", t.median}, {"max", t.max}, {"frames", t.frames}};
}

Json config_json(const BenchRun& run)
{
    const BenchConfig& c = run.config;
    Json scenes = Json::array(), labels = Json::array();
    for (SceneKind k : c.scenes)
        scenes.push_back(to_string(k));
    for (const BenchFilter& f : c.filters)
        labels.push_back(f.label);
    return {{"quick", c.quick},
            {"width", c.width},
            {"height", c.height},
            {"stage", to_string(c.stage)},
            {"texture", c.texture.name_or_path},
            {"format", to_string(c.texture.format)},
            {"build", to_string(c.texture.build)},
            {"texture_size", run.texture_width}, // level 0's width, as loaded (procedural: --texture-size)
            {"texture_height", run.texture_height},
            {"spp", c.truth_side * c.truth_side},
            {"truth_backend", c.truth_on_cpu ? "reference" : "vulkan"},
            // The analytic truth (box pixel over checker's, zoneplate's or grid's function) on the 2D scenes.
            {"analytic_truth", has_analytic_definition(c.texture.name_or_path)},
            {"warmup", c.warmup},
            {"frames", c.frames},
            {"flicker_frames", c.flicker_frames},
            {"lookups_per_pixel", c.lookups_per_pixel},
            {"timer", to_string(c.timer)},
            {"camera_step_texels", Json::array({camera_step_texels.x, camera_step_texels.y})},
            {"scenes", scenes},
            {"labels", labels}};
}

// Against the analytic truth: null where the scene has none (NaN), like a non-finite number.
Json analytic_error(const BenchResult& r)
{
    if (std::isnan(r.rmse_analytic))
        return nullptr;
    return {{"rmse", r.rmse_analytic}, {"psnr", psnr_from_rmse(r.rmse_analytic)}};
}

Json result_json(const BenchResult& r)
{
    return {{"scene", to_string(r.scene)},
            {"label", r.filter.label},
            {"filter", to_string(r.filter.options.filter)},
            {"args", r.filter.args},
            {"hardware", is_hardware(r.filter.options.filter)},
            {"stage", to_string(r.stage)},
            {"time_ms", times(r.time)},
            {"time_vs_hw_trilinear", r.vs_hw_trilinear},
            {"time_vs_baseline", r.vs_baseline},
            {"fetches_per_pixel", r.fetches_per_pixel},
            {"hw_lookups_per_pixel", r.hw_lookups_per_pixel},
            {"error",
             {{"box", {{"rmse", r.rmse_box}, {"psnr", psnr_from_rmse(r.rmse_box)}}},
              {"gaussian", {{"rmse", r.rmse_gaussian}, {"psnr", psnr_from_rmse(r.rmse_gaussian)}}},
              {"analytic", analytic_error(r)}}},
            {"flicker", {{"box", r.flicker_box}, {"gaussian", r.flicker_gaussian}, {"analytic", r.flicker_analytic}}},
            {"images", Json::array({r.image})}};
}

} // namespace

std::string bench_json(const BenchRun& run)
{
    Json baseline = Json::object(), truth = Json::object(), results = Json::array(), sweep = Json::array(),
         goals = Json::array();
    for (const auto& [scene, t] : run.baseline)
        baseline[to_string(scene)] = times(t);
    Json minimal = Json::object(), minimal_trilinear = Json::object();
    for (const auto& [scene, t] : run.minimal)
        minimal[to_string(scene)] = times(t);
    for (const auto& [scene, t] : run.minimal_trilinear)
        minimal_trilinear[to_string(scene)] = times(t);
    Json minimal_difference = Json::object();
    for (const auto& [scene, d] : run.minimal_trilinear_difference)
        minimal_difference[to_string(scene)] = d;
    for (SceneKind scene : run.config.scenes)
        if (run.truth_box.count(scene)) {
            truth[to_string(scene)] = {{"box", Json::array({run.truth_box.at(scene)})},
                                       {"gaussian", Json::array({run.truth_gaussian.at(scene)})}};
            if (run.truth_analytic.count(scene))
                truth[to_string(scene)]["analytic"] = Json::array({run.truth_analytic.at(scene)});
        }
    for (const BenchResult& r : run.results)
        results.push_back(result_json(r));
    for (const SatSweep& s : run.sat_sweep)
        sweep.push_back({{"label", s.label}, {"minify_2x_ms", times(s.at_2x)}, {"minify_64x_ms", times(s.at_64x)}});
    Json ewa_sweep = Json::array();
    for (const EwaSweepPoint& p : run.ewa_sweep)
        ewa_sweep.push_back({{"texels_per_pixel", p.texels_per_pixel}, {"psnr_gaussian_manual", p.psnr_manual},
                             {"psnr_gaussian_hardware", p.psnr_hardware}});
    Json stochastic = Json::array();
    for (const StochasticRow& r : run.stochastic) {
        Json box = Json::array(), gaussian = Json::array();
        for (size_t k = 0; k < r.frames.size(); ++k) {
            box.push_back({{"rmse", r.rmse_box[k]}, {"psnr", psnr_from_rmse(r.rmse_box[k])}});
            gaussian.push_back({{"rmse", r.rmse_gaussian[k]}, {"psnr", psnr_from_rmse(r.rmse_gaussian[k])}});
        }
        stochastic.push_back({{"scene", to_string(r.scene)}, {"label", r.label}, {"noise", to_string(r.noise)},
                              {"frame_ms", times(r.time)}, {"frames", r.frames},
                              {"error", {{"box", box}, {"gaussian", gaussian}}}});
    }
    for (const BenchGoal& g : run.goals)
        goals.push_back({{"goal", g.goal}, {"measured", g.measured}, {"status", g.status}, {"note", g.note}});
    Json out = {{"schema", 1},
                {"device", run.device.name},
                {"device_type", run.device.type},
                {"driver", run.device.driver_name + " " + run.device.driver_info},
                {"vulkan", version_string(run.device.api_version)},
                {"date", run.date},
                {"config", config_json(run)},
                {"baseline_ms", baseline},
                {"minimal_ms", minimal},
                {"minimal_trilinear_ms", minimal_trilinear},
                {"minimal_trilinear_vs_trilinear", minimal_difference},
                {"truth", truth},
                {"results", results},
                {"sat_sweep", sweep},
                {"ewa_sweep", ewa_sweep},
                {"stochastic", stochastic},
                {"goals", goals}};
    // Invalid UTF-8 (a texture path is bytes) is replaced, not thrown: the file is always written.
    return out.dump(1, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string bench_csv(const BenchRun& run)
{
    std::string out = "scene,label,filter,hardware,time_min_ms,time_median_ms,time_max_ms,time_vs_hw_trilinear,"
                      "time_vs_baseline,fetches_per_pixel,hw_lookups_per_pixel,rmse_box,psnr_box,rmse_gaussian,"
                      "psnr_gaussian,flicker_box,flicker_gaussian,rmse_analytic,psnr_analytic,flicker_analytic\n";
    for (const BenchResult& r : run.results) {
        const double values[] = {r.time.min, r.time.median, r.time.max, r.vs_hw_trilinear, r.vs_baseline,
                                 r.fetches_per_pixel, r.hw_lookups_per_pixel, r.rmse_box, psnr_from_rmse(r.rmse_box),
                                 r.rmse_gaussian, psnr_from_rmse(r.rmse_gaussian), r.flicker_box, r.flicker_gaussian,
                                 r.rmse_analytic, psnr_from_rmse(r.rmse_analytic), r.flicker_analytic};
        out += to_string(r.scene) + "," + r.filter.label + "," + to_string(r.filter.options.filter) + "," +
               (is_hardware(r.filter.options.filter) ? "true" : "false");
        for (double v : values)
            out += "," + csv_number(v);
        out += "\n";
    }
    return out;
}

} // namespace tf
