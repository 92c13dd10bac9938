#include "cli_common.h"
#include "commands.h"
#include "gpu_backend.h"
#include "lookups_csv.h"
#include "output_path.h"
#include "reference_render.h"
#include <cstdio>

namespace tf {

int run_sample(const std::vector<std::string>& argv)
{
    std::vector<FlagSpec> specs = join({texture_flags(),
                                        sampler_flags(),
                                        {{"--lookups", "IN.csv", "header u,v,dudx,dvdx,dudy,dvdy; one lookup a row"},
                                         {"-o", "OUT.csv", "r,g,b,a in linear light, one row per lookup"}},
                                        device_flags()});
    Args args = parse_args("sample", argv, specs, 0);
    if (args.has("--help")) {
        std::fputs(format_help("texfilter sample --texture T|PATH --filter F --lookups IN.csv "
                               "[--backend vulkan|reference] -o OUT.csv",
                               specs)
                       .c_str(),
                   stdout);
        return 0;
    }
    SamplerOptions options = sampler_options_from(args);
    Backend backend = backend_from(args);
    std::string out = args.require("-o");
    check_output_path(out, {".csv"});
    std::vector<Lookup> lookups = read_lookups_csv(args.require("--lookups"));
    MipChain chain = load_texture(texture_source_from(args));

    std::vector<glm::dvec4> colors;
    if (backend == Backend::reference) {
        colors = reference_sample_all(chain, lookups, options);
    } else {
        GpuSession gpu(context_options_from(args));
        GpuTexture texture = upload_texture(gpu.context, chain, needs_sat(options.filter));
        std::vector<glm::vec4> results;
        try {
            results = gpu_sample(gpu.context, texture, lookups, options);
        } catch (...) {
            destroy_texture(gpu.context, texture);
            throw;
        }
        destroy_texture(gpu.context, texture);
        gpu.finish();
        colors.assign(results.begin(), results.end());
    }
    write_colors_csv(out, colors);
    std::printf("%s: %zu lookups\n", out.c_str(), colors.size());
    return 0;
}

} // namespace tf
