#version 450
#extension GL_GOOGLE_include_directive : require
// Viewer: puts the rendered scene on the window. Each window pixel shows one pixel of filter A's image left
// of the divider and of B's right of it (nearest: a preview rendered at a fraction of the size is shown
// blocky, never blurred), magnified under the loupe, or as the error heat map against the ground truth.
// The images are the renderer's own RGBA32F pixels, unchanged; the sRGB swapchain encodes them.
#include "texfilter/debug.glsl"

layout(set = 0, binding = 0, std430) readonly buffer ImageA { vec4 a[]; };
layout(set = 0, binding = 1, std430) readonly buffer ImageB { vec4 b[]; };
layout(set = 0, binding = 2, std430) readonly buffer Truth { vec4 truth[]; };

// tf::ComposeParams (host/view/compose.h).
layout(push_constant) uniform Compose {
    ivec2 sizeA;       // pixels of A's image (smaller than full while previewing)
    ivec2 sizeB;
    ivec2 sizeTruth;
    ivec2 full;        // the scene's size in window pixels; beyond it (an odd last column or row): black
    ivec2 loupeCenter; // window pixel
    int loupeRadius;   // half side of the loupe square in window pixels; 0: no loupe
    int loupeZoom;     // window pixels a magnified pixel
    int divider;       // the first window column of B; >= full.x: A only
    int mode;          // 0: the images; 1: error heat map against the truth
    float errorMax;    // the error (max over RGB, linear) shown as the top of the heat scale
    int pad;
} pc;

layout(location = 0) out vec4 outColor;

// Window pixel to image pixel: the pixel whose span holds the window pixel's centre (identity at full size).
// In float: an integer division a lane is slow on a CPU rasterizer, and the products are exact below 2^24.
ivec2 image_pixel(ivec2 q, ivec2 size)
{
    return min(ivec2((vec2(q) + 0.5) * (vec2(size) / vec2(pc.full))), size - 1);
}

vec4 fetch_image(int which, ivec2 q)
{
    ivec2 size = which == 0 ? pc.sizeA : pc.sizeB;
    ivec2 p = image_pixel(q, size);
    int i = p.y * size.x + p.x;
    return which == 0 ? a[i] : b[i];
}

vec4 fetch_truth(ivec2 q)
{
    ivec2 p = image_pixel(q, pc.sizeTruth);
    return truth[p.y * pc.sizeTruth.x + p.x];
}

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (pc.loupeRadius > 0 && all(lessThan(abs(p - pc.loupeCenter), ivec2(pc.loupeRadius)))) {
        // floor division, so that the pixel under the centre stays under it
        ivec2 d = p - pc.loupeCenter;
        p = pc.loupeCenter + ivec2(floor(vec2(d) / float(pc.loupeZoom) + 0.5));
    }
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, pc.full))) {
        outColor = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    int which = p.x < pc.divider ? 0 : 1;
    vec4 c = fetch_image(which, p);
    if (pc.mode == 1) {
        vec3 e = abs(c.rgb - fetch_truth(p).rgb);
        c = vec4(tf_debug_heat(max(e.r, max(e.g, e.b)), pc.errorMax), 1.0);
    }
    outColor = c;
}
