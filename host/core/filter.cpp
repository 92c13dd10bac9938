#include "core/filter.h"

#include "texture/error.h"

#include <utility>

namespace tf {

namespace {

// One table per enum keeps parse, to_string and the error message in step.
const std::pair<Filter, const char*> kFilterNames[] = {
    {Filter::nearest, "nearest"},
    {Filter::bilinear, "bilinear"},
    {Filter::trilinear, "trilinear"},
    {Filter::nearest_mip, "nearest-mip"},
    {Filter::bilinear_mip, "bilinear-mip"},
    {Filter::hw_nearest, "hw-nearest"},
    {Filter::hw_bilinear, "hw-bilinear"},
    {Filter::hw_trilinear, "hw-trilinear"},
    {Filter::hw_aniso, "hw-aniso"},
    {Filter::brilinear, "brilinear"},
    {Filter::aniso, "aniso"},
    {Filter::ewa, "ewa"},
    {Filter::sat, "sat"},
    {Filter::sat_assembly, "sat-assembly"},
    {Filter::bspline, "bspline"},
    {Filter::catmull_rom, "catmull-rom"},
    {Filter::ewa_fast, "ewa-fast"},
    {Filter::ground_truth, "ground-truth"},
    {Filter::none, "none"},
};

const std::pair<AnisoShape, const char*> kShapeNames[] = {{AnisoShape::gpu, "gpu"}, {AnisoShape::feline, "feline"}};
const std::pair<Taps, const char*> kTapsNames[] = {{Taps::manual, "manual"}, {Taps::hardware, "hardware"}};
const std::pair<Reconstruction, const char*> kReconstructionNames[] = {
    {Reconstruction::bilinear, "bilinear"},
    {Reconstruction::bspline, "bspline"},
    {Reconstruction::catmull_rom, "catmull-rom"},
};

const std::pair<PixelFilter, const char*> kPixelFilterNames[] = {{PixelFilter::box, "box"},
                                                                 {PixelFilter::gaussian, "gaussian"}};

const std::pair<Wrap, const char*> kWrapNames[] = {
    {Wrap::repeat, "repeat"},
    {Wrap::clamp, "clamp"},
    {Wrap::mirror, "mirror"},
};

template <typename Table>
std::string name_list(const Table& table) {
    std::string list;
    for (const auto& entry : table) {
        if (!list.empty()) list += ", ";
        list += entry.second;
    }
    return list;
}

template <typename Enum, size_t N>
Enum parse_name(const std::pair<Enum, const char*> (&table)[N], const std::string& name, const char* what) {
    for (const auto& [value, text] : table)
        if (name == text) return value;
    throw Error(std::string("unknown ") + what + " '" + name + "' (expected one of: " + name_list(table) + ")");
}

template <typename Enum, size_t N>
std::string name_of(const std::pair<Enum, const char*> (&table)[N], Enum value, const char* what) {
    for (const auto& [v, text] : table)
        if (v == value) return text;
    throw Error(std::string("invalid ") + what + " value " + std::to_string(int(value)));
}

} // namespace

Filter parse_filter(const std::string& name) { return parse_name(kFilterNames, name, "filter"); }
std::string to_string(Filter filter) { return name_of(kFilterNames, filter, "filter"); }
Wrap parse_wrap(const std::string& name) { return parse_name(kWrapNames, name, "wrap mode"); }
std::string to_string(Wrap wrap) { return name_of(kWrapNames, wrap, "wrap mode"); }
AnisoShape parse_aniso_shape(const std::string& name) { return parse_name(kShapeNames, name, "aniso shape"); }
std::string to_string(AnisoShape shape) { return name_of(kShapeNames, shape, "aniso shape"); }
Taps parse_taps(const std::string& name) { return parse_name(kTapsNames, name, "taps form"); }
std::string to_string(Taps taps) { return name_of(kTapsNames, taps, "taps form"); }
Reconstruction parse_reconstruction(const std::string& name) {
    return parse_name(kReconstructionNames, name, "reconstruction");
}
std::string to_string(Reconstruction r) { return name_of(kReconstructionNames, r, "reconstruction"); }
PixelFilter parse_pixel_filter(const std::string& name) { return parse_name(kPixelFilterNames, name, "pixel filter"); }
std::string to_string(PixelFilter filter) { return name_of(kPixelFilterNames, filter, "pixel filter"); }

const std::vector<Filter>& all_filters() {
    static const std::vector<Filter> filters = [] {
        std::vector<Filter> list;
        for (const auto& entry : kFilterNames)
            if (!is_scene_level(entry.first)) list.push_back(entry.first);
        return list;
    }();
    return filters;
}

bool is_hardware(Filter filter) {
    switch (filter) {
    case Filter::hw_nearest:
    case Filter::hw_bilinear:
    case Filter::hw_trilinear:
    case Filter::hw_aniso:
        return true;
    default:
        return false;
    }
}

bool is_scene_level(Filter filter) { return filter == Filter::ground_truth || filter == Filter::none; }

bool takes_taps(Filter filter) {
    return filter == Filter::aniso || filter == Filter::ewa || filter == Filter::bspline || filter == Filter::catmull_rom;
}

bool takes_magnify(Filter filter) { return filter == Filter::trilinear || filter == Filter::aniso || filter == Filter::ewa; }

bool uses_hardware_lookups(const SamplerOptions& options)
{
    return is_hardware(options.filter) || options.filter == Filter::ewa_fast ||
           (options.taps == Taps::hardware && takes_taps(options.filter));
}

namespace {

bool reads_lod_bias(Filter f)
{
    switch (f) {
    case Filter::nearest_mip:
    case Filter::bilinear_mip:
    case Filter::trilinear:
    case Filter::brilinear:
    case Filter::aniso:
    case Filter::ewa:
    case Filter::ewa_fast:
    case Filter::sat:          // scales the footprint by exp2(bias) (sat.glsl)
    case Filter::sat_assembly:
    case Filter::hw_trilinear: // mipLodBias
    case Filter::hw_aniso:
        return true;
    default: // level 0 only (hw-nearest and hw-bilinear: maxLod 0), ground-truth, none
        return false;
    }
}

// The clamps of the LOD: every filter that picks levels (not sat, which has none).
bool reads_lod_range(Filter f) { return reads_lod_bias(f) && f != Filter::sat && f != Filter::sat_assembly; }

struct FlagReaders {
    const char* flag;
    bool (*reads)(Filter filter, bool stochastic);
};

const FlagReaders kFlagReaders[] = {
    {"--wrap", [](Filter f, bool) { return f != Filter::none; }}, // none shows fract(uv), no texel
    {"--aniso", [](Filter f, bool) { return f == Filter::hw_aniso; }},
    {"--band", [](Filter f, bool) { return f == Filter::brilinear; }},
    {"--probes", [](Filter f, bool) { return f == Filter::aniso; }},
    {"--aniso-shape", [](Filter f, bool) { return f == Filter::aniso; }},
    {"--taps", [](Filter f, bool stochastic) {
         return takes_taps(f) || (stochastic && (f == Filter::bilinear || f == Filter::trilinear));
     }},
    {"--magnify", [](Filter f, bool) { return takes_magnify(f); }},
    {"--alpha", [](Filter f, bool) { return f == Filter::ewa; }},
    {"--max-aniso", [](Filter f, bool) { return f == Filter::ewa; }},
    {"--boxes", [](Filter f, bool) { return f == Filter::sat_assembly; }},
    {"--pixel-filter", [](Filter f, bool) { return f == Filter::ground_truth; }},
    {"--spp", [](Filter f, bool) { return f == Filter::ground_truth; }},
    {"--truth", [](Filter f, bool) { return f == Filter::ground_truth; }},
    {"--stochastic", [](Filter f, bool) { return takes_stochastic(f); }},
    {"--lod-bias", [](Filter f, bool) { return reads_lod_bias(f); }},
    {"--lod-min", [](Filter f, bool) { return reads_lod_range(f); }},
    {"--lod-max", [](Filter f, bool) { return reads_lod_range(f); }},
};

const FlagReaders& flag_readers(const std::string& flag)
{
    for (const FlagReaders& r : kFlagReaders)
        if (flag == r.flag)
            return r;
    throw Error("filter_reads: " + flag + " is not a sampler flag");
}

std::string and_list(const std::vector<std::string>& names)
{
    std::string list;
    for (size_t i = 0; i < names.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return list;
}

} // namespace

const std::vector<std::string>& sampler_flag_names()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> list;
        for (const FlagReaders& r : kFlagReaders)
            list.push_back(r.flag);
        return list;
    }();
    return names;
}

bool filter_reads(Filter filter, const std::string& flag, bool stochastic)
{
    return flag_readers(flag).reads(filter, stochastic);
}

std::string filters_reading(const std::string& flag)
{
    const FlagReaders& r = flag_readers(flag);
    std::vector<std::string> always, stochastic;
    for (const auto& [filter, name] : kFilterNames)
        if (r.reads(filter, false))
            always.push_back(name);
        else if (r.reads(filter, true))
            stochastic.push_back(name);
    return and_list(always) + (stochastic.empty() ? "" : "; with --stochastic also " + and_list(stochastic));
}

bool is_lod_flag(const std::string& flag) { return flag == "--lod-bias" || flag == "--lod-min" || flag == "--lod-max"; }

void check_magnify(const SamplerOptions& options) {
    if (options.magnify != Reconstruction::bilinear && !takes_magnify(options.filter))
        throw Error("--magnify " + to_string(options.magnify) + " applies to trilinear, aniso and ewa (level 0's "
                    "reconstruction), not to --filter " + to_string(options.filter) +
                    (options.filter == Filter::bilinear ? " (--filter " + to_string(options.magnify) + " is that cubic alone)" : ""));
}

bool takes_stochastic(Filter filter)
{
    return filter == Filter::bilinear || filter == Filter::trilinear || filter == Filter::aniso || filter == Filter::ewa;
}

Noise parse_noise(const std::string& name)
{
    if (name == "white") return Noise::white;
    if (name == "blue") return Noise::blue;
    throw Error("'" + name + "' is not a noise (expected white or blue)");
}

std::string to_string(Noise noise) { return noise == Noise::blue ? "blue" : "white"; }

void check_stochastic(const SamplerOptions& options)
{
    if (options.accumulate < 1 || options.accumulate > HARNESS_MAX_ACCUMULATE)
        throw Error("bad value for --accumulate: " + std::to_string(options.accumulate) + " (expected 1.." +
                    std::to_string(HARNESS_MAX_ACCUMULATE) + " frames)");
    if (!options.stochastic) {
        if (options.accumulate != 1)
            throw Error("--accumulate " + std::to_string(options.accumulate) +
                        " needs --stochastic white|blue (a deterministic filter gives the same frame every time)");
        return;
    }
    if (!takes_stochastic(options.filter))
        throw Error("--stochastic applies to bilinear, trilinear, aniso and ewa (their one-texel forms), not to --filter " +
                    to_string(options.filter));
    if (options.magnify != Reconstruction::bilinear)
        throw Error("--stochastic reads level 0 bilinearly: it does not combine with --magnify " +
                    to_string(options.magnify));
    if (options.stochastic_first > (1u << 28))
        throw Error("--stochastic: first frame " + std::to_string(options.stochastic_first) + " is past 2^28");
}

int32_t stochastic_push(const SamplerOptions& options, uint32_t frame)
{
    return options.stochastic ? int32_t(((frame & 0x1fffffffu) << 2) | uint32_t(options.noise)) : 0;
}

TruthRange truth_range(const SamplerOptions& options)
{
    const int side = options.truth_side;
    if (side < 1 || side > max_ground_truth_side)
        throw Error("ground truth: truth_side " + std::to_string(side) + " is outside 1.." +
                    std::to_string(max_ground_truth_side) + " (samples a pixel = side^2)");
    const int total = side * side;
    const std::string grid =
        " the " + std::to_string(total) + " samples of the " + std::to_string(side) + "x" + std::to_string(side) + " grid";
    if (options.truth_first < 0 || options.truth_first >= total)
        throw Error("ground truth: truth_first " + std::to_string(options.truth_first) + " is not one of" + grid +
                    " (0.." + std::to_string(total - 1) + ")");
    const int rest = total - options.truth_first;
    if (options.truth_count < 0 || options.truth_count > rest)
        throw Error("ground truth: truth_count " + std::to_string(options.truth_count) + " from truth_first " +
                    std::to_string(options.truth_first) + " runs past" + grid + " (at most " + std::to_string(rest) +
                    "; 0 = the rest)");
    return {options.truth_first, options.truth_count == 0 ? rest : options.truth_count};
}

} // namespace tf
