#include "flags/cli_common.h"
#include "core/analytic_texture.h"
#include "cli/commands.h"
#include "texture/error.h"
#include "vulkan/backend.h"
#include "vulkan/environment.h"
#include "io/environment_source.h"
#include "reference/env_render.h"
#include "vulkan/device.h"
#include "io/image_io.h"
#include "io/output_path.h"
#include "io/pfm.h"
#include "reference/debug_view.h"
#include "reference/render.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include <cstdio>
#include <optional>

namespace tf {

namespace {

// The output image and what rendering it takes, counted in the texture's memory budget check.
void add_render_output(TextureUse& use, int width, int height, const CommandDevice& device)
{
    use.other_bytes = render_output_bytes(width, height, !device.gpu, device.gpu && device.limits.host_memory);
    use.other_what = "a " + std::to_string(width) + "x" + std::to_string(height) + " render";
}

// skybox and reflect: the environment map --env makes of --texture, rendered on either backend.
Image render_environment_scene(SceneKind kind, int width, int height, int frame, const std::optional<Camera>& camera,
                               const TextureSource& source, const SamplerOptions& options, const RenderOptions& render,
                               CommandDevice& device)
{
    TextureUse use = device.texture_use(false);
    add_render_output(use, width, height, device);
    const EnvironmentMap env = load_environment(source, use);
    const int size = environment_size(env);
    SceneParams scene = scene_at_frame(make_scene(kind, width, height, size), frame, size);
    if (camera)
        scene = with_camera(scene, *camera);
    if (!device.gpu)
        return reference_render_environment(scene, env, options, render);
    const VulkanContext& context = device.gpu->context;
    Image image;
    {
        GpuEnvironment gpu = upload_environment(context, env);
        Cleanup cleanup;
        cleanup.add([&] { destroy_environment(context, gpu); });
        image = gpu_render_environment(context, gpu, scene, options, render);
    }
    device.gpu->finish();
    return image;
}

} // namespace

int run_render(const std::vector<std::string>& argv)
{
    std::vector<FlagSpec> specs = join(
        {{{"--scene", "S", scene_names()}},
         texture_flags(),
         sampler_flags(SamplerFlags::scenes),
         {{"--size", "WxH", "image size, even sides (default 256x256)"},
          {"--stage", "S", "fragment (default) or compute (2x2 quads from subgroup quad operations)"},
          {"--derivatives", "D", "fine (default), coarse (one pair a quad), ray (ray differentials) or cone (ray cones)"},
          {"--view", "V", "color (default), lod, anisotropy, fetches (a heat map 0..128) or data (linear floats: "
                          "R LOD, G anisotropy, B fetches + hardware lookups; write .pfm or .exr)"},
          {"--frame", "N", "frame N (0..1000000, default 0) of the benchmark's camera path: uv slides N x (0.37, 0.23) texels"},
          {"--camera", "X,Y,Z,YAW,PITCH", "camera position and yaw/pitch (degrees, relative to the scene's own view), "
                                          "as texfilter view prints it; applied after --frame"},
          {"-o", "OUT", "output .png (8-bit sRGB), .exr (linear half) or .pfm (linear float, any build)"}},
         device_flags()});
    Args args = parse_args("render", argv, specs, 0);
    if (args.has("--help")) {
        std::fputs(format_help("texfilter render --scene S --texture T|PATH --filter F [--size WxH] "
                               "[--backend vulkan|reference] [--aniso N] -o OUT.png|OUT.exr|OUT.pfm",
                               specs)
                       .c_str(),
                   stdout);
        return 0;
    }
    SceneKind kind = parse_flag(args, "--scene", "", parse_scene);
    RenderOptions render = make_render_options(kind, parse_flag(args, "--stage", "fragment", parse_stage),
                                               parse_flag(args, "--derivatives", "fine", parse_gradients));
    render.view = parse_flag(args, "--view", "color", parse_view);
    SamplerFlagUse flag_use;
    flag_use.lod_view = render.view == DebugView::lod || render.view == DebugView::data; // they show the LOD
    flag_use.environment = is_environment_scene(kind);
    SamplerOptions options = sampler_options_from(args, flag_use);
    check_env_flag(args, {kind}, "--scene " + to_string(kind));
    check_view(options.filter, render.view); // before any work
    const int frame = args.get_int("--frame", 0, 0, 1000000);
    std::optional<Camera> camera;
    if (args.has("--camera"))
        camera = parse_flag(args, "--camera", "", parse_camera);
    Backend backend = backend_from(args);
    if (backend == Backend::reference)
        check_reference_view(render.view);
    auto [width, height] = parse_size("--size", args.get("--size", "256x256"), 2, 8192);
    if (width % 2 || height % 2)
        throw Error("bad value for --size: '" + args.get("--size", "") + "' (sides must be even: derivatives come from 2x2 quads)");
    TextureSource source = texture_source_from(args);
    const bool environment = is_environment_scene(kind);
    if (environment) { // before any work
        check_environment_filter(options);
        check_environment_truth(options);
        if (render.view != DebugView::color)
            throw Error("--view " + to_string(render.view) + " is not available on the environment scenes (skybox, "
                        "reflect): use --view color");
    }
    resolve_analytic_truth(options, source.name_or_path); // --truth analytic: the texture's function, or refused
    check_format_filter(source.format, options); // integer data and hardware filtering, before any work
    std::string out = checked_output_path(args.require("-o"), {".png", ".exr", ".pfm"}, {source.name_or_path});
    if (render.view == DebugView::data && out.size() >= 4 && out.compare(out.size() - 4, 4, ".png") == 0)
        throw Error(out + ": --view data writes linear floats (LOD, anisotropy, fetches); use a .pfm or .exr output");
    if (!image_io_available() && !is_pfm_path(out))
        throw Error(out + ": image I/O was left out of this build (configure with -DTEXFILTER_IMAGE_IO=ON; "
                          ".pfm output is built in)");
    if (!is_pfm_path(out))
        load_image_io(); // a missing image I/O module fails here, before the render
    CommandDevice device = open_command_device(backend, args);
    if (environment) {
        write_image(out, render_environment_scene(kind, width, height, frame, camera, source, options, render, device));
        std::printf("%s\n", out.c_str());
        return 0;
    }
    if (device.gpu)
        check_format_support(device.gpu->context, source.format, options);
    const bool sat = needs_sat(options.filter);
    // No MipChain on the host: an RGBA32F file's levels are built in the staging buffer (other formats are
    // rounded level by level on the host, from the whole chain).
    const bool streamed = device.gpu && streams_level0(source) && !sat && source.format == TextureFormat::rgba32f &&
                          source.build == TextureBuild::cpu;
    TextureUse use = device.texture_use(sat);
    add_render_output(use, width, height, device);
    use.streamed = streamed;
    use.level0_only = source.build == TextureBuild::gpu; // the device builds the rest
    // Every path checks the texture (size, budget, device limits) once, before decoding it.
    std::optional<MipChain> chain;
    TextureSize size;
    if (streamed) {
        size = check_texture(source, use);
    } else {
        chain = load_texture(source, use);
        size = {chain->levels[0].width, chain->levels[0].height};
    }
    GpuSession* gpu = device.gpu.get();
    // make_scene, then the camera path's frame, then the camera (scene/camera.h: relative to the scene's own view).
    SceneParams scene = scene_at_frame(make_scene(kind, width, height, size.width), frame, size.width);
    if (camera)
        scene = with_camera(scene, *camera);
    auto draw = [&](const GpuTexture& t) { return gpu_render(gpu->context, t, scene, options, render); };

    Image image;
    if (!gpu) {
        image = reference_render(scene, *chain, options, render);
    } else if (streamed) { // decoded into the staging buffer
        image = with_streamed_texture(gpu->context, size.width, size.height,
                                      [&](glm::vec4* texels) { read_level0(source, size, texels); }, draw);
        gpu->finish();
    } else {
        image = with_texture(gpu->context, *chain, sat, source.format, source.build, draw);
        gpu->finish();
    }
    write_image(out, image);
    std::printf("%s\n", out.c_str());
    return 0;
}

} // namespace tf
