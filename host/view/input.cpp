// Mouse and keys: fly (WASD, Q/E down/up, wheel forward), drag with the right button to turn (or, in orbit
// mode, to swing around the point the centre of the view looks at), R resets, space toggles the animation,
// T the dynamic texture's animation, ',' and '.' step its frame back and forward (pausing it), L the loupe,
// F12 takes a screenshot. Only when the UI does not want the input.
#include "view/viewer.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace tf {

void handle_input(Viewer& v, double seconds)
{
    const ImGuiIO& io = ImGui::GetIO();
    if (!v.options.script.empty())
        return; // a script drives the camera; the person's mouse must not make its frames differ
    GLFWwindow* w = v.window->handle;
    const SceneParams scene = current_scene(v);
    Camera c = v.controls.camera_set ? v.controls.camera : camera_of(scene);
    bool moved = false;
    if (!io.WantCaptureKeyboard) {
        // World units a second: a tenth of the way to what the view looks at, so near and far both work.
        const double speed = std::max(0.05, glm::length(look_target(scene) - glm::dvec3(scene.origin))) * 0.5;
        glm::dvec3 move(0.0);
        move.x = (glfwGetKey(w, GLFW_KEY_D) == GLFW_PRESS) - (glfwGetKey(w, GLFW_KEY_A) == GLFW_PRESS);
        move.y = (glfwGetKey(w, GLFW_KEY_E) == GLFW_PRESS) - (glfwGetKey(w, GLFW_KEY_Q) == GLFW_PRESS);
        move.z = (glfwGetKey(w, GLFW_KEY_W) == GLFW_PRESS) - (glfwGetKey(w, GLFW_KEY_S) == GLFW_PRESS);
        if (move != glm::dvec3(0.0)) {
            c = fly(c, scene, move * speed * std::min(seconds, 0.1));
            moved = true;
        }
        if (ImGui::IsKeyPressed(GLFW_KEY_SPACE))
            v.controls.animate = !v.controls.animate;
        if (ImGui::IsKeyPressed(GLFW_KEY_R)) {
            v.controls.camera_set = false;
            scene_changed(v);
            return;
        }
        if (ImGui::IsKeyPressed(GLFW_KEY_T))
            v.controls.texture_animate = !v.controls.texture_animate;
        const int step = ImGui::IsKeyPressed(GLFW_KEY_PERIOD) - ImGui::IsKeyPressed(GLFW_KEY_COMMA);
        if (step != 0 && is_dynamic_texture(v.state.texture)) {
            v.controls.texture_animate = false;
            const int frame = v.state.texture.texture_frame + step;
            const int wrapped = frame < 0 ? max_texture_frame : frame % (max_texture_frame + 1);
            v.controls.message = problem_of([&] { set_viewer_texture_frame(v, wrapped); });
        }
        if (ImGui::IsKeyPressed(GLFW_KEY_L))
            v.controls.loupe = !v.controls.loupe;
        if (ImGui::IsKeyPressed(GLFW_KEY_F12))
            v.controls.pending_screenshot = v.controls.screenshot_field.data();
    }
    if (!io.WantCaptureMouse) {
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
            const double yaw = io.MouseDelta.x * 0.2, pitch = -io.MouseDelta.y * 0.2;
            c = v.controls.orbit ? orbit(c, scene, look_target(scene), yaw, pitch) : turn(c, yaw, pitch);
            moved = true;
        }
        if (io.MouseWheel != 0) {
            const double step = std::max(0.05, glm::length(look_target(scene) - glm::dvec3(scene.origin))) * 0.1;
            c = fly(c, scene, {0.0, 0.0, io.MouseWheel * step});
            moved = true;
        }
    }
    if (moved) {
        v.controls.camera = c;
        v.controls.camera_set = true;
        scene_changed(v);
    }
}

} // namespace tf
