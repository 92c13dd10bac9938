// Screenshots read back from the swapchain: the image the window shows, not a second render.
#include "view/viewer.h"
#include "io/image_io.h"
#include "io/output_path.h"
#include "texture/error.h"
#include "vulkan/cleanup.h"
#include <cstdint>

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

} // namespace

void screenshot(Viewer& v, const std::string& requested, bool with_ui)
{
    std::vector<std::string> inputs = v.options.inputs; // the script and the --state file are never written
    inputs.push_back(v.state.texture.name_or_path);
    // Before any work, and again here for a script's (checked before the window opened): a file may have
    // appeared since.
    const std::string path = checked_screenshot_paths(requested, with_ui, inputs, v.written);
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
    remember_written(v.written, path);
    if (!with_ui) {
        std::string lines;
        for (const std::string& line : render_command_lines(v.state, path))
            lines += line + "\n";
        const std::string txt = screenshot_side_file(path, ".txt"), json = screenshot_side_file(path, ".json");
        write_file_atomic(txt, lines);
        remember_written(v.written, txt);
        write_file_atomic(json, state_to_json(v.state));
        remember_written(v.written, json);
    }
    std::printf("%s\n", path.c_str());
    std::fflush(stdout);
}

} // namespace tf
