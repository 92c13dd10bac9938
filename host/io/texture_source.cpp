#include "io/texture_source.h"
#include "texture/error.h"
#include "core/memory_budget.h"
#include "core/cube_textures.h"
#include "core/procedural.h"
#include "io/text_file.h"
#include "texture/sat.h"
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace tf {

bool is_procedural_texture(const std::string& name) { return is_procedural(name) || is_procedural_cube(name); }

std::string procedural_texture_names()
{
    const std::vector<std::string>& names = procedural_cube_names(); // the cube-only names, then the 2D ones
    std::string list;
    for (size_t i = 0; i < names.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return list;
}

void check_texture_name(const std::string& path)
{
    if (is_procedural_texture(path))
        return;
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found)
        throw Error("unknown texture '" + path + "': not a procedural texture (" + procedural_texture_names() +
                    ") and no such file");
    if (ec)
        throw Error(path + ": " + ec.message());
    if (std::filesystem::is_directory(status))
        return; // the image reader says it is a directory
    refuse_special_file(path, "an image file"); // a device or FIFO is never opened (io/text_file.h)
    // Opened as the reader will open it: the system's reason, not the image library's "cannot open".
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0)
        throw Error(path + ": " + std::strerror(errno));
    ::close(fd);
}

TextureSize check_texture(const TextureSource& source, const TextureUse& use)
{
    const bool procedural = is_procedural(source.name_or_path);
    int width = source.procedural_size, height = source.procedural_size;
    if (!procedural) {
        check_texture_name(source.name_or_path);
        const ImageHeader header = read_image_header(source.name_or_path, max_texture_dimension);
        width = header.width;
        height = header.height;
    }
    const std::string what = procedural ? "texture " + source.name_or_path : source.name_or_path;
    if (source.texture_frame < 0 || source.texture_frame > max_texture_frame)
        throw Error(what + ": texture frame " + std::to_string(source.texture_frame) + " is outside 0.." +
                    std::to_string(max_texture_frame));
    if (source.texture_frame != 0 && !is_dynamic_texture(source))
        throw Error(what + ": --texture-frame " + std::to_string(source.texture_frame) +
                    " applies to the dynamic procedural texture only (--texture dynamic)");
    if (use.sat && (width > sat_max_dimension || height > sat_max_dimension))
        throw Error(what + ": " + std::to_string(width) + "x" + std::to_string(height) +
                    " is larger than the summed-area table allows (" + std::to_string(sat_max_dimension) +
                    " a side: its 40-bit sums are exact only up to 4096x4096 texels of 16 bits)");
    const uint64_t budget = source.memory_budget ? source.memory_budget : default_memory_budget();
    const TextureLoad load = !use.device                 ? TextureLoad::host
                             : use.level0_only            ? TextureLoad::device_level0
                             : use.streamed && !procedural ? TextureLoad::device_streamed
                                                           : TextureLoad::device;
    TextureMemory need = estimate_texture_memory(width, height, use.sat, load, !procedural,
                                                 use.device && use.device->host_memory);
    if (use.other_bytes)
        add_other(need, use.other_bytes, use.other_what);
    check_memory_budget(what, width, height, need, budget);
    if (use.device)
        check_device_limits(what, width, height, need, *use.device);
    return {width, height};
}

bool is_dynamic_texture(const TextureSource& source) { return source.name_or_path == "dynamic"; }

bool streams_level0(const TextureSource& source) { return !is_procedural(source.name_or_path); }

void read_level0(const TextureSource& source, TextureSize size, glm::vec4* texels)
{
    if (!streams_level0(source))
        throw Error("texture " + source.name_or_path + " is procedural: load it whole with load_texture");
    read_image_into(source.name_or_path, source.color, max_texture_dimension, size.width, size.height, texels);
}

MipChain load_texture(const TextureSource& source, const TextureUse& use)
{
    check_texture(source, use);
    MipChain chain;
    if (is_dynamic_texture(source) && use.level0_only) // the device builds the rest
        chain.levels.push_back(dynamic_texture(source.procedural_size, source.texture_frame));
    else if (is_dynamic_texture(source))
        chain = build_mip_chain(dynamic_texture(source.procedural_size, source.texture_frame));
    else if (is_procedural(source.name_or_path))
        chain = make_procedural(source.name_or_path, source.procedural_size);
    else if (use.level0_only)
        chain.levels.push_back(read_image(source.name_or_path, source.color, max_texture_dimension));
    else
        chain = build_mip_chain(read_image(source.name_or_path, source.color, max_texture_dimension));
    if (use.level0_only)
        chain.levels.resize(1);
    if (!use.level0_only) // level 0 alone stays as decoded: the GPU build rounds each level as the host would
        quantise_chain(chain, source.format); // before the table: the SAT sums the texels the format stores
    if (use.sat) // NaN/Inf texels have no place in an integer table: refused here, naming the texture
        check_sat_texels(chain.levels[0], source.name_or_path);
    return chain;
}

} // namespace tf
