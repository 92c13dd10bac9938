// Harness only: the ground truth a filtered pixel is judged against. The pixel integrates the level-0
// texture (bilinear reconstruction; or, with pc.truthAnalytic, the procedural texture's analytic definition
// at level 0's size: analytic_texture.glsl) over the scene itself under a pixel filter, by stratified
// supersampling: a side x side grid of strata jittered by an integer hash of (pixel, sample), the
// pattern of host/reference/ground_truth.cpp (the CPU twin, in double). Box: uniform over the pixel. Gaussian:
// sigma HARNESS_GROUND_TRUTH_SIGMA pixels about the centre, Box-Muller on the stratified unit square.
// A frame may take a range of the samples (pc.truthFirst, pc.truthCount) and return their mean.
// Needs scene.glsl and filter_select.glsl (u_texture, pc) or env_select.glsl included first.
#ifndef HARNESS_GROUND_TRUTH_GLSL
#define HARNESS_GROUND_TRUTH_GLSL

#include "analytic_texture.glsl"

#include "hash.glsl" // harness_mix32, harness_unit

vec2 truth_sample(ivec2 pixel, int i, int side, int pixelFilter)
{
    uint h = harness_mix32(uint(i) + harness_mix32(uint(pixel.y) + harness_mix32(uint(pixel.x))));
    float a = (float(i % side) + harness_unit(h)) / float(side);
    float b = (float(i / side) + harness_unit(harness_mix32(h))) / float(side);
    if (pixelFilter != HARNESS_PIXEL_FILTER_GAUSSIAN)
        return vec2(pixel) + vec2(a, b);
    float r = HARNESS_GROUND_TRUTH_SIGMA * sqrt(-2.0 * log(1.0 - a)); // 1 - a in (0, 1]: finite
    float angle = 6.283185307179586 * b;
    return vec2(pixel) + 0.5 + r * vec2(cos(angle), sin(angle));
}

// The samples a frame takes: [first, first + count) of the side x side grid (count 0: from first to the end),
// so that the viewer can accumulate the truth a few samples a frame: chunk means weighted by their counts
// give the mean of the whole grid. The range is clamped into the grid (at least one sample), so the loop
// is bounded and the mean finite whatever the host sends; the host refuses a range past the grid.
void truth_samples(out int side, out int first, out int count)
{
    side = clamp(pc.truthSide, 1, HARNESS_MAX_TRUTH_SIDE); // bounded loop whatever the host sends
    int total = side * side;
    first = clamp(pc.truthFirst, 0, total - 1);
    count = pc.truthCount <= 0 ? total - first : min(pc.truthCount, total - first);
}

#ifdef HARNESS_TEX // 2D scenes (env_select.glsl has the environment maps' twin)
// The mean of the frame's samples (truth_samples) of the level-0 texture over the scene.
vec4 ground_truth(ivec2 pixel)
{
    int side, first, count;
    truth_samples(side, first, count);
    tf_Sampler s = tf_sampler(pc.wrapMode);
    int analytic = pc.truthAnalytic, size = HARNESS_SIZE0.x; // uniform: the branch below does not diverge
    vec4 sum = vec4(0.0);
    [[dont_unroll]] for (int i = first; i < first + count; ++i) {
        Hit h = scene_hit(scene, truth_sample(pixel, i, side, pc.pixelFilter));
        if (!h.hit)
            sum += scene.background;
        else if (analytic != HARNESS_ANALYTIC_NONE)
            sum += analytic_value(analytic, size, h.uv, pc.wrapMode);
        else
            sum += tf_bilinear(HARNESS_TEX, h.uv HARNESS_X, s);
    }
    return sum / float(count);
}
#endif

#endif
