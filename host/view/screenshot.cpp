// Screenshots read back from the swapchain: the image the window shows, not a second render.
#include "view/viewer.h"
#include "io/image_io.h"
#include "io/output_path.h"
#include "texture/error.h"
#include "vulkan/cleanup.h"
#include <cstdint>
#include <filesystem>

namespace tf {

namespace {

// The swapchain's 8-bit sRGB texels as a linear image: the PNG writer encodes them back to the same bytes.
// with_alpha: the scene's alpha as the composition wrote it (the swapchain's alpha is stored linearly, as a
// PNG's is), so the PNG is the render's RGBA; else 1, the window as it is seen (presented opaque, and the
// UI's blending leaves no meaningful alpha).
Image decode_capture(const Buffer& capture, VkExtent2D extent, VkFormat format, int width, int height, bool with_alpha)
{
    const auto* bytes = static_cast<const uint8_t*>(capture.mapped);
    const bool bgra = format == VK_FORMAT_B8G8R8A8_SRGB;
    Image image = make_image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const uint8_t* p = bytes + (size_t(y) * extent.width + size_t(x)) * 4;
            const int r = bgra ? p[2] : p[0], b = bgra ? p[0] : p[2];
            image.at(x, y) = glm::vec4(float(srgb_to_linear(r / 255.0)), float(srgb_to_linear(p[1] / 255.0)),
                                       float(srgb_to_linear(b / 255.0)), with_alpha ? float(p[3] / 255.0) : 1.0f);
        }
    return image;
}

std::string stem_of(const std::string& path) { return path.substr(0, path.size() - 4); } // checked: ends in .png

bool exists(const std::string& path) { return std::filesystem::symlink_status(path).type() != std::filesystem::file_type::not_found; }

} // namespace

std::string unused_screenshot_path(const std::string& wanted)
{
    const std::string stem = wanted.size() > 4 && wanted.substr(wanted.size() - 4) == ".png" ? stem_of(wanted) : wanted;
    for (int n = 0; n < 10000; ++n) { // bounded: past that, checked_output_path says what is wrong
        const std::string s = n ? stem + "-" + std::to_string(n) : stem;
        if (!exists(s + ".png") && !exists(s + ".txt") && !exists(s + ".json"))
            return s + ".png";
    }
    return wanted;
}

std::string checked_screenshot_paths(const std::string& requested, bool with_ui, const std::vector<std::string>& inputs)
{
    const std::string path = checked_output_path(requested, {".png"}, inputs);
    if (!with_ui) { // the files beside it
        checked_output_path(stem_of(path) + ".txt", {".txt"}, inputs);
        checked_output_path(stem_of(path) + ".json", {".json"}, inputs);
    }
    return path;
}

void screenshot(Viewer& v, const std::string& requested, bool with_ui)
{
    std::vector<std::string> inputs = v.options.inputs; // the script and the --state file are never written
    inputs.push_back(v.state.texture.name_or_path);
    const std::string path = checked_screenshot_paths(requested, with_ui, inputs); // before any work
    if (!with_ui)
        finish_images(v);
    int width = 0, height = 0;
    framebuffer_size(*v.window, width, height);
    if (width == 0 || height == 0)
        throw Error("screenshot " + requested + ": the window is minimised (restore it first)");
    const VkExtent2D extent = v.swapchain.extent;
    Buffer capture = create_host_buffer(v.context, VkDeviceSize(extent.width) * extent.height * 4,
                                        VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    Cleanup cleanup;
    cleanup.add([&] { destroy_buffer(v.context, capture); });
    if (with_ui) // ImGui lays out a frame before it draws it: one frame first, so the panels are whole
        draw_frame(v, true);
    if (!draw_frame(v, with_ui, &capture))
        throw Error("screenshot " + requested + ": nothing was presented (the window is minimised)");
    if (v.swapchain.extent.width != extent.width || v.swapchain.extent.height != extent.height)
        throw Error("screenshot " + requested + ": the window changed size while it was taken; take it again");
    // The scene alone is the scene's size (even sides: the renderer's); the whole window is the window's.
    const int w = with_ui ? int(extent.width) : v.scene_width, h = with_ui ? int(extent.height) : v.scene_height;
    write_image(path, decode_capture(capture, extent, v.swapchain.format, w, h, !with_ui));
    if (!with_ui) {
        std::string lines;
        for (const std::string& line : render_command_lines(v.state, path))
            lines += line + "\n";
        write_file_atomic(stem_of(path) + ".txt", lines);
        write_file_atomic(stem_of(path) + ".json", state_to_json(v.state));
    }
    std::printf("%s\n", path.c_str());
    std::fflush(stdout);
}

} // namespace tf
