#pragma once
// texfilter view: the window, its swapchain and UI, the scene images, and the loop that ties them. One
// frame in flight: the scene renders synchronously (render_frame), then the composition and the UI are
// recorded, submitted and presented. The dynamic texture (--texture dynamic --build gpu) is rebuilt on the
// device first, in its own submission, for each new texture frame (SceneImages::dynamic).
#include "view/compose.h"
#include "view/imgui_layer.h"
#include "view/scene_images.h"
#include "view/screenshot_files.h"
#include "view/script.h"
#include "view/swapchain.h"
#include "view/view_state.h"
#include "view/window.h"
#include "scene/camera.h"
#include <array>
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tf {

struct ViewOptions {
    ViewState state;
    ContextOptions device;
    std::vector<ScriptAction> script; // empty: interactive
    std::string script_name;
    std::string frame_log; // --frame-log: every frame's times as CSV (the viewer benchmark)
    std::vector<std::string> inputs; // the files it reads besides the texture (--script, --state): never written
    bool preview = true;   // --no-preview: every frame at full size (the benchmark's baseline)
};

// What the person (or the script) looks at, beyond ViewState: the UI's own state.
struct ViewControls {
    Camera camera;
    bool camera_set = false; // false: the scene's own camera
    bool animate = false;
    // The dynamic texture (--texture dynamic --build gpu) steps one texture frame a drawn frame, rebuilt on the
    // device each time; off: it stays at its frame (nothing rebuilt).
    bool texture_animate = true;
    bool truth = false;       // B is the ground truth, accumulated progressively
    bool ui = true;           // panels shown
    bool loupe = false;
    glm::ivec2 loupe_center{0};
    int loupe_radius = 96, loupe_zoom = 8;
    glm::ivec2 cursor{-1};    // the pixel the footprint overlay follows; -1: the mouse
    bool footprint = true;
    float error_max = 0.1f;
    bool orbit = false;       // mouse drag orbits the look target instead of turning
    std::string message;      // the last problem (a texture that did not load): shown in the UI
    std::string pending_screenshot; // asked for in the UI: taken after the frame, under a name no file has
    std::array<char, 512> texture_field{};      // the panel's text fields
    std::string texture_shown;                  // the texture the field was last filled with
    std::array<char, 512> screenshot_field{"texfilter-view.png"};
};

struct FrameStats {
    double frame_ms = 0, render_ms = 0;
    double texture_ms = 0; // the dynamic texture's rebuild this frame (0: none)
    int preview_scale = 1; // 1: full size
    double fetches_per_pixel = -1; // A's, measured when the view settles with the HUD shown
    bool fetches_measured = false;
};

struct Viewer {
    ViewOptions options;
    ViewState state;
    ViewControls controls;
    VulkanContext context;
    Window* window = nullptr;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    Swapchain swapchain;
    ComposePass compose;
    SceneImages images;
    VkSemaphore acquired = VK_NULL_HANDLE;
    VkFence frame_done = VK_NULL_HANDLE;
    VkCommandPool command_pool = VK_NULL_HANDLE; // its own: the frame's command buffer is reset and reused
    VkCommandBuffer command_buffer = VK_NULL_HANDLE;
    FrameStats stats;
    int preview_scale = 1;
    bool compose_stale = true; // the halves' images changed since they were copied for the composition pass
    std::chrono::steady_clock::time_point last_move{};
    bool quit = false;
    int scene_width = 0, scene_height = 0; // even: the framebuffer's size rounded down
    WrittenFiles written; // the screenshots' files: the only existing files a screenshot replaces
};

// The files below call one way only, so a change followed from the CLI, a key or a script line enters each
// file once: viewer.cpp (the lifetime and the loop) -> input.cpp, script_runner.cpp -> screenshot.cpp ->
// frame.cpp -> ui.cpp -> viewer_state.cpp -> scene_images.cpp and vulkan/.

// viewer.cpp: checks, window, device, the loop, teardown.
int run_viewer(const ViewOptions& options);
void take_dropped_files(Viewer& viewer); // a file dropped onto the window becomes the texture
// The acquire semaphore, the frame fence, the command pool and buffer; destroyed by `cleanup`.
void create_frame_objects(Viewer& viewer, Cleanup& cleanup);

// viewer_state.cpp: the state applied and queried; calls none of the files above it.
SceneParams current_scene(const Viewer& viewer);
void scene_changed(Viewer& viewer); // camera, frame, size or scene: images start over, the camera counts as moving
// The view layer's one error style: what the viewer refuses throws tf::Error (a texture that does not load,
// a sat filter on the dynamic texture, a texture without frames), with the previous state kept. Before the
// window opens the error ends the viewer; afterwards the callers that go on (the UI, keys, a dropped file,
// the script) show its message: problem_of.
// Applies a new ViewState (scene, texture, filters).
void apply_state(Viewer& viewer, const ViewState& next);
// Runs `change`: its tf::Error's message, or "" when it went through.
std::string problem_of(const std::function<void()>& change);
std::string view_title(const Viewer& viewer);
// The dynamic texture made and built on the device, frame by frame (the viewer's SceneImages::dynamic).
bool rebuilt_on_device(const TextureSource& texture);
bool texture_animates(const Viewer& viewer); // rebuilt on the device and animating
// The next texture frame (after max_texture_frame, 0 again): the halves re-render at the next draw_frame.
void advance_texture_frame(Viewer& viewer);
// Throws tf::Error when the texture has no frames.
void set_viewer_texture_frame(Viewer& viewer, int frame);
bool moving_now(const Viewer& viewer);      // the camera moved within the settle time, or it or the texture animates
bool images_complete(const Viewer& viewer); // every half at full size with all its samples

// frame.cpp: one frame drawn.
// Renders and presents one frame; with_ui false: the scene alone (screenshots). Returns false when there
// was nothing to present to (minimised).
// capture (or null): the presented image is also copied there (screenshots).
bool draw_frame(Viewer& viewer, bool with_ui, const Buffer* capture = nullptr);
// Renders every half to completion at full size (screenshots).
void finish_images(Viewer& viewer);
void upload_compose_images(Viewer& viewer); // the halves' images into the composition pass's buffers

// screenshot.cpp: the frame just presented (the scene alone, or with_ui the whole window) to PNG, and beside a
// scene screenshot PATH.txt (the texfilter render lines) and PATH.json (the state, for --state). Refused,
// naming the file, where one of them exists and is not in viewer.written (screenshot_files.h).
void screenshot(Viewer& viewer, const std::string& path, bool with_ui);

// script_runner.cpp: runs actions until one needs frames to pass. Returns false when the script is over.
struct ScriptRun {
    size_t next = 0;
    int wait_frames = 0;
    std::chrono::steady_clock::time_point hold_until{};
};
bool run_script_step(Viewer& viewer, ScriptRun& run);

// ui.cpp: the panels; changes go through apply_state / scene_changed.
void build_ui(Viewer& viewer);
// input.cpp: mouse and keys move the camera (when the UI does not want them).
void handle_input(Viewer& viewer, double seconds);

} // namespace tf
