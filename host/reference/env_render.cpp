#include "reference/env_render.h"
#include "core/analytic_texture.h"

#include "reference/env_cast.h"
#include "reference/environment.h"
#include "reference/ground_truth.h"
#include "reference/stochastic.h"
#include "texture/error.h"
#include "texture/threads.h"

namespace tf {

namespace {

glm::dvec4 level0(const EnvironmentMap& env, const glm::dvec3& dir)
{
    return env.map == EnvMap::cube ? reference_cube_bilinear0(env.cube, dir) : reference_latlong_bilinear0(env.latlong, dir);
}

} // namespace

glm::dvec4 reference_environment_sample(const EnvironmentMap& env, const SamplerOptions& options, const EnvLookup& lookup)
{
    return env.map == EnvMap::cube ? reference_cube_sample(env.cube, options, lookup)
                                   : reference_latlong_sample(env.latlong, options, lookup);
}

Image reference_render_environment(const SceneParams& scene, const EnvironmentMap& env, const SamplerOptions& options,
                                   const RenderOptions& render)
{
    check_environment_filter(options);
    check_environment_truth(options);
    if (options.stochastic)
        check_reference_stochastic(options); // ewa's tap form has none
    if (render.view != DebugView::color)
        throw Error("--view " + to_string(render.view) + " is not available on the environment scenes: use --view color");
    const int width = scene.kind_size.y, height = scene.kind_size.z;
    Image out = make_image(width, height);
    if (options.filter == Filter::ground_truth) {
        const TruthRange range = truth_range(options); // checked as the GPU host checks it
        parallel_for(size_t(height), [&](size_t row) {
            const int y = int(row);
            for (int x = 0; x < width; ++x) {
                glm::dvec4 sum(0.0);
                for (int i = range.first; i < range.first + range.count; ++i) {
                    const glm::dvec2 p = ground_truth_sample(x, y, i, options.truth_side, options.pixel_filter);
                    sum += level0(env, reference_env_direction(scene, p.x, p.y));
                }
                out.texels[row * size_t(width) + size_t(x)] = glm::vec4(sum / double(range.count));
            }
        });
        return out;
    }
    const std::vector<EnvLookup> lookups = reference_env_lookups(scene, render.gradients);
    parallel_for(size_t(height), [&](size_t y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = y * size_t(width) + size_t(x);
            const glm::dvec4 value =
                !options.stochastic     ? reference_environment_sample(env, options, lookups[i])
                : env.map == EnvMap::cube ? reference_cube_stochastic_mean(env.cube, options, lookups[i], x, int(y))
                                          : reference_latlong_stochastic_mean(env.latlong, options, lookups[i], x, int(y));
            out.texels[i] = glm::vec4(value);
        }
    });
    return out;
}

} // namespace tf
