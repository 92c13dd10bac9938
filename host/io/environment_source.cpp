#include "io/environment_source.h"

#include "core/cube_textures.h"
#include "core/memory_budget.h"
#include "core/procedural.h"
#include "texture/error.h"

namespace tf {

namespace {

// A procedural environment: `size` a face (lat-long: 2·size x size), checked against the budget first.
void check_procedural_environment(const TextureSource& source, const TextureUse& use)
{
    const int side = source.procedural_size;
    const bool cube = source.env == EnvMap::cube;
    // Six faces, or the cube and its 2:1 resampling (both held while it is made).
    const int width = cube ? side : 3 * side, height = cube ? 6 * side : 2 * side;
    TextureMemory need = estimate_texture_memory(width, height, false, use.device ? TextureLoad::device : TextureLoad::host,
                                                 false, use.device && use.device->host_memory);
    if (use.other_bytes)
        add_other(need, use.other_bytes, use.other_what);
    check_memory_budget("environment " + source.name_or_path, width, height, need,
                        source.memory_budget ? source.memory_budget : default_memory_budget());
    if (use.device)
        check_device_limits("environment " + source.name_or_path, width, height, need, *use.device);
}

} // namespace

EnvironmentMap load_environment(const TextureSource& source, const TextureUse& use)
{
    if (source.format != TextureFormat::rgba32f)
        throw Error("--format " + to_string(source.format) + ": environment maps are uploaded as rgba32f only");
    if (source.build != TextureBuild::cpu)
        throw Error("--build gpu: environment maps are built on the host (use --build cpu)");
    EnvironmentMap env;
    env.map = source.env;
    const std::string& name = source.name_or_path;
    const bool procedural = is_procedural_cube(name) || is_procedural(name);
    if (procedural) {
        if (name == "dynamic" || name == "mipcolors")
            throw Error("texture " + name + ": has no environment form (its levels are made, not downsampled)");
        check_procedural_environment(source, use);
        CubeMap cube = make_procedural_cube(name, source.procedural_size);
        if (env.map == EnvMap::cube)
            env.cube = std::move(cube);
        else
            env.latlong = build_mip_chain(latlong_from_cube(cube, 2 * source.procedural_size));
        return env;
    }
    // An image file: checked from its header, then decoded once as level 0.
    TextureUse level0 = use;
    level0.level0_only = true;
    level0.sat = false;
    MipChain file = load_texture(source, level0);
    if (env.map == EnvMap::latlong)
        env.latlong = build_mip_chain(std::move(file.levels.at(0)));
    else
        env.cube = cube_from_cross(file.levels.at(0), name);
    return env;
}

} // namespace tf
