#include "bench/footprint_bench.h"
#include "bench/metrics.h"
#include "core/hash.h"
#include "io/texture_source.h"
#include "reference/ground_truth.h"
#include "reference/reference.h"
#include "texture/error.h"
#include "texture/threads.h"
#include "vulkan/device.h"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

namespace tf {

namespace {

using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

constexpr double two_pi = 6.283185307179586;
constexpr double major_min = 0.25, major_octaves = 10.0;  // 0.25..256 level-0 texels
constexpr double anisotropy_octaves = 6.0;                 // 1..64

// 24 hash bits as a number in [0, 1).
double unit(uint32_t h) { return double(h >> 8) * (1.0 / 16777216.0); }

// Draw j (0..7) of lookup k.
double draw(uint32_t k, uint32_t j) { return unit(mix32(k * 8u + j + 0x6a09e667u)); }

// The number the device reads (the sample pass's lookups are float): every side sees the same footprint.
double as_float(double x) { return double(float(x)); }

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

const char* truth_name(PixelFilter filter) { return filter == PixelFilter::box ? "box" : "gaussian"; }

// Squared display error summed over a set of lookups (RGB), and how many channel values it holds: rows pool.
struct ErrorSum {
    double squared = 0;
    double values = 0;
    double rmse() const { return values > 0 ? std::sqrt(squared / values) : NAN; }
    void add(const ErrorSum& other)
    {
        squared += other.squared;
        values += other.values;
    }
};

// display_rmse of the chosen lookups, as an ErrorSum.
ErrorSum display_error(const std::vector<glm::dvec4>& colors, const std::vector<glm::dvec4>& truth,
                       const std::vector<size_t>& chosen)
{
    if (chosen.empty()) // an empty bucket (a small --lookups): no error, null in the files
        return {};
    Image a = make_image(int(chosen.size()), 1), b = make_image(int(chosen.size()), 1);
    for (size_t i = 0; i < chosen.size(); ++i) {
        a.texels[i] = glm::vec4(colors[chosen[i]]);
        b.texels[i] = glm::vec4(truth[chosen[i]]);
    }
    const double rmse = display_rmse(a, b);
    const double values = 3.0 * double(chosen.size());
    return {rmse * rmse * values, values};
}

bool in_bucket(const FootprintLookup& l, const FootprintBucket& bucket)
{
    const double value = bucket.axis == "anisotropy" ? l.anisotropy : l.major;
    return value >= bucket.low && value < bucket.high && l.anisotropy < bucket.below_anisotropy;
}

// One texture's rows (and their sums, for the photos' pooled rows).
struct TextureRows {
    std::vector<FootprintRow> rows;
    std::vector<ErrorSum> errors, floors;
};

TextureRows texture_rows(const std::string& texture, const std::vector<FootprintLookup>& lookups,
                         const std::vector<FootprintFilter>& filters, const std::vector<FootprintAnswers>& answers,
                         const std::vector<std::vector<glm::dvec4>>& truths)
{
    TextureRows out;
    const PixelFilter pixel_filters[] = {PixelFilter::box, PixelFilter::gaussian};
    for (int t = 0; t < 2; ++t)
        for (const FootprintBucket& bucket : footprint_buckets()) {
            std::vector<size_t> chosen;
            for (size_t i = 0; i < lookups.size(); ++i)
                if (in_bucket(lookups[i], bucket))
                    chosen.push_back(i);
            const ErrorSum floor = display_error(truths[2 * t + 1], truths[2 * t], chosen);
            for (size_t f = 0; f < filters.size(); ++f) {
                FootprintRow row{texture, truth_name(pixel_filters[t]), filters[f].label, bucket, int(chosen.size())};
                const ErrorSum error = display_error(answers[f].colors, truths[2 * t], chosen);
                row.rmse = error.rmse();
                row.psnr = psnr_from_rmse(row.rmse);
                row.floor_psnr = psnr_from_rmse(floor.rmse());
                if (!answers[f].stats.empty() && !chosen.empty()) {
                    double fetches = 0, hw = 0;
                    for (size_t i : chosen) {
                        fetches += answers[f].stats[i].texel_fetches;
                        hw += answers[f].stats[i].hardware_lookups;
                    }
                    row.fetches = fetches / double(chosen.size());
                    row.hw_lookups = hw / double(chosen.size());
                }
                out.rows.push_back(row);
                out.errors.push_back(error);
                out.floors.push_back(floor);
            }
        }
    return out;
}

// The image files' rows pooled into rows of texture "photos": errors over all their lookups of the bucket.
std::vector<FootprintRow> pooled_rows(const std::vector<TextureRows>& photos)
{
    std::vector<FootprintRow> pooled = photos.at(0).rows;
    for (size_t r = 0; r < pooled.size(); ++r) {
        ErrorSum error, floor;
        double lookups = 0, fetches = 0, hw = 0;
        for (const TextureRows& t : photos) {
            error.add(t.errors[r]);
            floor.add(t.floors[r]);
            if (t.rows[r].lookups == 0) // its work is NaN: no lookup to count
                continue;
            lookups += t.rows[r].lookups;
            fetches += t.rows[r].fetches * t.rows[r].lookups;
            hw += t.rows[r].hw_lookups * t.rows[r].lookups;
        }
        FootprintRow& row = pooled[r];
        row.texture = "photos";
        row.lookups = int(lookups);
        row.rmse = error.rmse();
        row.psnr = psnr_from_rmse(row.rmse);
        row.floor_psnr = psnr_from_rmse(floor.rmse());
        row.fetches = lookups > 0 ? fetches / lookups : NAN;
        row.hw_lookups = lookups > 0 ? hw / lookups : NAN;
    }
    return pooled;
}

const char* axis_title(const std::string& axis)
{
    return axis == "major"        ? "major axis (level-0 texels)"
           : axis == "anisotropy" ? "anisotropy"
                                  : "major axis (level-0 texels), anisotropy below 2";
}

} // namespace

std::vector<FootprintLookup> footprint_lookups(int width, int height, const FootprintSampling& sampling)
{
    std::vector<FootprintLookup> lookups(size_t(std::max(0, sampling.lookups)));
    for (size_t i = 0; i < lookups.size(); ++i) {
        const uint32_t k = uint32_t(i);
        FootprintLookup& l = lookups[i];
        l.major = major_min * std::exp2(major_octaves * draw(k, 2));
        l.anisotropy = std::exp2(anisotropy_octaves * draw(k, 3));
        const double minor = l.major / l.anisotropy;
        // J = R(theta) diag(major, minor) R(phi)^T in level-0 texels: the ellipse at angle theta, the pixel's
        // axes at another (so that the columns are not the ellipse's axes, as in a real view).
        const double theta = two_pi * draw(k, 4), phi = two_pi * draw(k, 5);
        const double ct = std::cos(theta), st = std::sin(theta), cp = std::cos(phi), sp = std::sin(phi);
        const double j00 = ct * l.major * cp + st * minor * sp, j01 = ct * l.major * sp - st * minor * cp;
        const double j10 = st * l.major * cp - ct * minor * sp, j11 = st * l.major * sp + ct * minor * cp;
        l.lookup = {as_float(draw(k, 0)),  as_float(draw(k, 1)),  as_float(j00 / width),
                    as_float(j10 / height), as_float(j01 / width), as_float(j11 / height)};
        l.truth_side = std::clamp(int(std::ceil(4.0 * l.major)), sampling.min_side, sampling.max_side);
    }
    return lookups;
}

glm::dvec4 footprint_truth(const Image& level0, const Lookup& lookup, PixelFilter filter, int side, uint32_t index,
                           uint32_t stream, Wrap wrap)
{
    glm::dvec4 sum(0.0);
    const int count = side * side;
    for (int i = 0; i < count; ++i) {
        const glm::dvec2 p = ground_truth_sample(int(index), int(stream), i, side, filter);
        const double s = p.x - (double(index) + 0.5), t = p.y - (double(stream) + 0.5);
        sum += reference_bilinear(level0, lookup.u + lookup.dudx * s + lookup.dudy * t,
                                  lookup.v + lookup.dvdx * s + lookup.dvdy * t, wrap);
    }
    return sum / double(count);
}

std::vector<FootprintAnswers> run_footprint_filters(const VulkanContext* context, const std::string& name,
                                                    const MipChain& chain, const std::vector<FootprintFilter>& filters,
                                                    const std::vector<Lookup>& lookups, TextureFormat format)
{
    const bool device = std::any_of(filters.begin(), filters.end(), [](const FootprintFilter& f) { return f.device; });
    const bool sat = std::any_of(filters.begin(), filters.end(), [](const FootprintFilter& f) { return f.sat; });
    auto run = [&](const GpuTexture* gpu) {
        std::vector<FootprintAnswers> answers;
        const FootprintTexture texture{name, &chain, context, gpu};
        for (const FootprintFilter& f : filters) {
            answers.push_back(f.evaluate(texture, lookups));
            if (answers.back().colors.size() != lookups.size() ||
                (!answers.back().stats.empty() && answers.back().stats.size() != lookups.size()))
                throw Error("bench --footprints: filter " + f.label + " answered " +
                            std::to_string(answers.back().colors.size()) + " of " + std::to_string(lookups.size()) +
                            " lookups");
        }
        return answers;
    };
    if (!device)
        return run(nullptr);
    if (!context)
        throw Error("bench --footprints: a device filter was chosen but no device is open");
    return with_texture(*context, chain, sat, format, [&](const GpuTexture& gpu) { return run(&gpu); });
}

TextureSource footprint_source(const FootprintConfig& config, const std::string& name)
{
    TextureSource source;
    source.name_or_path = name;
    source.procedural_size = config.texture_size;
    source.format = config.format;
    return source;
}

TextureUse footprint_use(const FootprintConfig& config, const DeviceLimits* device)
{
    TextureUse use;
    use.sat = std::any_of(config.filters.begin(), config.filters.end(), [](const FootprintFilter& f) { return f.sat; });
    use.device = device;
    return use;
}

std::vector<FootprintBucket> footprint_buckets()
{
    std::vector<FootprintBucket> buckets;
    for (const char* axis : {"major", "major-isotropic"}) {
        const double below = std::string(axis) == "major" ? INFINITY : 2.0;
        buckets.push_back({axis, "<1", 0.0, 1.0, below});
        for (int low = 1; low < 256; low *= 2)
            buckets.push_back({axis, std::to_string(low) + "-" + std::to_string(2 * low), double(low), 2.0 * low, below});
    }
    for (int low = 1; low < 16; low *= 2)
        buckets.push_back({"anisotropy", std::to_string(low) + "-" + std::to_string(2 * low), double(low), 2.0 * low});
    buckets.push_back({"anisotropy", ">16", 16.0, INFINITY});
    return buckets;
}

FootprintRun run_footprint_bench(const VulkanContext* context, const FootprintConfig& config)
{
    FootprintRun run;
    run.config = config;
    run.date = utc_date();
    if (context)
        run.device = context->info;
    const DeviceLimits limits = context ? device_limits(context->info) : DeviceLimits{};
    const SamplerOptions defaults; // the filters' wrap (repeat): the truths wrap the same way
    std::vector<TextureRows> photos;
    for (const std::string& name : config.textures) {
        const MipChain chain = load_texture(footprint_source(config, name), footprint_use(config, context ? &limits : nullptr));
        const Image& level0 = chain.levels.at(0);
        run.textures.push_back({name, level0.width, level0.height});
        const std::vector<FootprintLookup> lookups = footprint_lookups(level0.width, level0.height, config.sampling);
        std::vector<Lookup> plain;
        for (const FootprintLookup& l : lookups)
            plain.push_back(l.lookup);

        // Four truths a lookup: box and Gaussian, each twice (streams 0 and 1: the noise floor).
        auto start = Clock::now();
        std::vector<std::vector<glm::dvec4>> truths(4, std::vector<glm::dvec4>(lookups.size()));
        parallel_for(lookups.size(), [&](size_t i) {
            const FootprintLookup& l = lookups[i];
            for (int t = 0; t < 4; ++t)
                truths[size_t(t)][i] = footprint_truth(level0, l.lookup, t < 2 ? PixelFilter::box : PixelFilter::gaussian,
                                                       l.truth_side, uint32_t(i), uint32_t(t % 2), defaults.wrap);
        });
        const double truth_seconds = seconds_since(start);
        start = Clock::now();
        const std::vector<FootprintAnswers> answers = run_footprint_filters(context, name, chain, config.filters, plain, config.format);
        const double filter_seconds = seconds_since(start);
        run.truth_seconds += truth_seconds;
        run.filter_seconds += filter_seconds;
        std::printf("footprints: %s %dx%d, %zu lookups: truths %.1f s, %zu filters %.1f s\n", name.c_str(),
                    level0.width, level0.height, lookups.size(), truth_seconds, config.filters.size(), filter_seconds);
        std::fflush(stdout);

        TextureRows rows = texture_rows(name, lookups, config.filters, answers, truths);
        run.rows.insert(run.rows.end(), rows.rows.begin(), rows.rows.end());
        if (!is_procedural_texture(name))
            photos.push_back(std::move(rows));
    }
    if (!photos.empty()) {
        const std::vector<FootprintRow> pooled = pooled_rows(photos);
        run.rows.insert(run.rows.end(), pooled.begin(), pooled.end());
    }
    return run;
}

std::string footprint_json(const FootprintRun& run)
{
    Json textures = Json::array(), labels = Json::array(), buckets = Json::array(), rows = Json::array();
    for (const FootprintTextureInfo& t : run.textures)
        textures.push_back({{"name", t.name}, {"width", t.width}, {"height", t.height}});
    for (const FootprintFilter& f : run.config.filters)
        labels.push_back(f.label);
    for (const FootprintBucket& b : footprint_buckets())
        buckets.push_back({{"axis", b.axis}, {"name", b.name}, {"low", b.low}, {"high", b.high},
                           {"below_anisotropy", b.below_anisotropy}}); // infinite: null
    for (const FootprintRow& r : run.rows)
        rows.push_back({{"texture", r.texture},
                        {"truth", r.truth},
                        {"label", r.label},
                        {"axis", r.bucket.axis},
                        {"bucket", r.bucket.name},
                        {"lookups", r.lookups},
                        {"rmse", r.rmse},
                        {"psnr", r.psnr},
                        {"floor_psnr", r.floor_psnr},
                        {"fetches", r.fetches},
                        {"hw_lookups", r.hw_lookups}});
    const FootprintSampling& s = run.config.sampling;
    Json out = {{"schema", 1},
                {"kind", "footprints"},
                {"device", run.device.name},
                {"device_type", run.device.type},
                {"driver", run.device.name.empty() ? "" : run.device.driver_name + " " + run.device.driver_info},
                {"date", run.date},
                {"command", run.command},
                {"config",
                 {{"quick", run.config.quick},
                  {"lookups", s.lookups},
                  {"truth_min_side", s.min_side},
                  {"truth_max_side", s.max_side},
                  {"texture_size", run.config.texture_size},
                  {"format", to_string(run.config.format)},
                  {"textures", textures},
                  {"labels", labels},
                  {"buckets", buckets}}},
                {"truth_seconds", run.truth_seconds},
                {"filter_seconds", run.filter_seconds},
                {"rows", rows}};
    return out.dump(1, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string footprint_csv(const FootprintRun& run)
{
    std::string out = "texture,truth,label,axis,bucket,lookups,rmse,psnr,floor_psnr,fetches,hw_lookups\n";
    for (const FootprintRow& r : run.rows) {
        // A texture path may hold a comma or a quote: quoted as RFC 4180 has it.
        std::string texture = r.texture;
        if (texture.find_first_of(",\"\n") != std::string::npos) {
            std::string quoted = "\"";
            for (char c : texture)
                quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
            texture = quoted + "\"";
        }
        out += texture + "," + r.truth + "," + r.label + "," + r.bucket.axis + "," + r.bucket.name + "," +
               std::to_string(r.lookups);
        for (double v : {r.rmse, r.psnr, r.floor_psnr, r.fetches, r.hw_lookups})
            out += "," + csv_number(v);
        out += "\n";
    }
    return out;
}

std::string footprint_tables(const FootprintRun& run)
{
    // texture -> truth -> axis -> label -> bucket -> row, in the run's order.
    std::vector<std::string> textures;
    for (const FootprintRow& r : run.rows)
        if (std::find(textures.begin(), textures.end(), r.texture) == textures.end())
            textures.push_back(r.texture);
    std::string out;
    char cell[64];
    for (const std::string& texture : textures)
        for (const char* truth : {"box", "gaussian"})
            for (const char* axis : {"major", "anisotropy", "major-isotropic"}) {
                std::vector<const FootprintRow*> rows;
                for (const FootprintRow& r : run.rows)
                    if (r.texture == texture && r.truth == truth && r.bucket.axis == axis)
                        rows.push_back(&r);
                std::vector<std::string> buckets;
                for (const FootprintBucket& b : footprint_buckets())
                    if (b.axis == axis)
                        buckets.push_back(b.name);
                out += "\n" + texture + ", " + truth + " truth, PSNR (dB) by " +
                       axis_title(axis) + "\n\n| filter |";
                for (const std::string& b : buckets)
                    out += " " + b + " |";
                out += "\n|---|";
                for (size_t b = 0; b < buckets.size(); ++b)
                    out += "---:|";
                out += "\n";
                std::vector<std::string> labels = {"noise floor"};
                for (const FootprintFilter& f : run.config.filters)
                    labels.push_back(f.label);
                labels.push_back("lookups");
                for (const std::string& label : labels) {
                    out += "| " + label + " |";
                    for (const std::string& b : buckets) {
                        // The floor and the count are the bucket's, in every filter's row: the first one's.
                        const bool per_bucket = label == "noise floor" || label == "lookups";
                        const FootprintRow* row = nullptr;
                        for (const FootprintRow* r : rows)
                            if (!row && r->bucket.name == b && (per_bucket || r->label == label))
                                row = r;
                        const double value = !row ? NAN
                                             : label == "noise floor" ? row->floor_psnr
                                             : label == "lookups"     ? double(row->lookups)
                                                                      : row->psnr;
                        std::snprintf(cell, sizeof cell, label == "lookups" ? " %.0f |" : " %.1f |", value);
                        out += cell;
                    }
                    out += "\n";
                }
            }
    return out;
}

} // namespace tf
