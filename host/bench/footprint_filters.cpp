// bench --footprints' filter table: a label and how to evaluate a batch of lookups. A new filter or peer is one
// entry in footprint_filters() below: a device filter through on_device(SamplerOptions), a host one through
// on_host(function of one lookup) or its own EvaluateLookups (a peer that takes the whole batch at once).
#include "bench/bench.h"
#include "bench/footprint_bench.h"
#include "io/oiio_texture.h"
#include "reference/reference.h"
#include "texture/error.h"
#include "texture/threads.h"
#include "vulkan/backend.h"
#include <algorithm>

namespace tf {

namespace {

// The library's sample pass (one invocation a lookup; hw-* a subgroup of 2x2 quads whose differences equal the
// gradients), with the shader's own counts of texel fetches and hardware lookups.
FootprintFilter on_device(const std::string& label, const SamplerOptions& options)
{
    return {label, true, needs_sat(options.filter),
            [options](const FootprintTexture& texture, const std::vector<Lookup>& lookups) {
                FootprintAnswers answers;
                const std::vector<glm::vec4> colors =
                    gpu_sample(*texture.context, *texture.gpu, lookups, options, &answers.stats);
                answers.colors.assign(colors.begin(), colors.end());
                return answers;
            },
            options};
}

// A host filter of one lookup, run on every core (no work counted).
using HostLookup = std::function<glm::dvec4(const MipChain& chain, const Lookup& lookup)>;
FootprintFilter on_host(const std::string& label, HostLookup filter)
{
    return {label, false, false, [filter](const FootprintTexture& texture, const std::vector<Lookup>& lookups) {
                FootprintAnswers answers;
                answers.colors.resize(lookups.size());
                parallel_for(lookups.size(), [&](size_t i) { answers.colors[i] = filter(*texture.chain, lookups[i]); });
                return answers;
            }};
}

// A peer: OpenImageIO's TextureSystem on the texture's level 0 (io/oiio_texture.h; it builds its own levels).
FootprintFilter oiio_filter(const OiioTextureMode& mode)
{
    return {"oiio-" + to_string(mode), false, false,
            [mode](const FootprintTexture& texture, const std::vector<Lookup>& lookups) {
                FootprintAnswers answers;
                const std::vector<glm::vec4> colors =
                    oiio_texture_lookups(texture.chain->levels[0], lookups, Wrap::repeat, mode);
                answers.colors.assign(colors.begin(), colors.end());
                return answers;
            }};
}

FootprintFilter reference_filter(const std::string& label, Filter filter)
{
    SamplerOptions options;
    options.filter = filter;
    return on_host(label, [options](const MipChain& chain, const Lookup& lookup) {
        return reference_sample(chain, options, lookup);
    });
}

} // namespace

std::vector<FootprintFilter> footprint_filters()
{
    std::vector<FootprintFilter> filters;
    for (const BenchFilter& f : bench_filters()) // every label of the scene bench, on the device
        filters.push_back(on_device(f.label, f.options));
    // Host filters and peers: one line each.
    filters.push_back(reference_filter("ref-ewa", Filter::ewa)); // the CPU reference's EWA, in double
    if (oiio_texture_available()) // the lean build has no peer: its labels are then unknown
        for (const OiioTextureMode& mode : all_oiio_texture_modes())
            filters.push_back(oiio_filter(mode));
    return filters;
}

std::vector<std::string> default_footprint_labels()
{
    std::vector<std::string> labels = {"ewa",          "ewa-hw",    "ewa-fast", "hw-aniso16",   "hw-trilinear",
                                       "trilinear",    "aniso16",   "aniso16-hw", "sat-assembly"};
    if (oiio_texture_available()) // OpenImageIO's modes a renderer built on it would use
        for (const char* mode : {"oiio-trilinear", "oiio-aniso", "oiio-aniso-bicubic", "oiio-aniso-smartbicubic"})
            labels.push_back(mode);
    return labels;
}

std::vector<FootprintFilter> select_footprint_filters(const std::vector<std::string>& labels)
{
    const std::vector<FootprintFilter> all = footprint_filters();
    std::vector<FootprintFilter> chosen;
    for (const std::string& label : labels) {
        auto known = std::find_if(all.begin(), all.end(), [&](const FootprintFilter& f) { return f.label == label; });
        if (known == all.end()) {
            std::string valid;
            for (const FootprintFilter& f : all)
                valid += (valid.empty() ? "" : ", ") + f.label;
            throw Error("bad value for --filters: unknown label '" + label + "' (bench --footprints knows: " + valid +
                        ")");
        }
        if (std::any_of(chosen.begin(), chosen.end(), [&](const FootprintFilter& f) { return f.label == label; }))
            throw Error("bad value for --filters: '" + label + "' is listed twice");
        chosen.push_back(*known);
    }
    return chosen;
}

} // namespace tf
