// Harness only: the filter (a specialization constant) and the push constants every harness pass shares
// (filter_select.glsl for 2D textures, env_select.glsl for environment maps).
#ifndef HARNESS_PUSH_CONSTANTS_GLSL
#define HARNESS_PUSH_CONSTANTS_GLSL

#include "config.h"

// The filter is a specialization constant, so each pipeline holds one filter's code: with a run-time
// switch every family's texture calls stayed in the shader, and lavapipe generated its anisotropic
// sampling code for all of them (hw-aniso renders ran ~30x slower).
layout(constant_id = HARNESS_SPEC_FILTER) const int FILTER_ID = 0;
// trilinear, aniso, ewa: level 0's reconstruction, the includes' TF_MAGNIFY (filter_select.glsl); a constant,
// so a pipeline that does not magnify with a cubic has none of its code.
layout(constant_id = HARNESS_SPEC_MAGNIFY) const int MAGNIFY_ID = HARNESS_RECONSTRUCT_BILINEAR;
// bilinear, trilinear, aniso, ewa: 1 = their one-texel stochastic forms (--stochastic), a constant so that the
// deterministic pipelines hold none of that code.
layout(constant_id = HARNESS_SPEC_STOCHASTIC) const int STOCHASTIC_ID = 0;
// render: the debug view and the gradients, constants too, so that a frame runs only the code it shows: as
// push constants, lavapipe (which runs every side of every if) computed the debug views' footprint (60 % of
// a no-texture frame) and every gradient form (ray differentials, cones) in every frame, and the views'
// fetch counters cost manual filters ~8 % more (docs/BENCHMARKS.md).
layout(constant_id = HARNESS_SPEC_VIEW) const int VIEW_ID = HARNESS_VIEW_COLOR;
layout(constant_id = HARNESS_SPEC_GRADIENTS) const int GRADIENTS_ID = HARNESS_GRADIENTS_FINE;
// Lookups a pixel: the mean of LOOKUPS_ID lookups spread over the pixel (filter_select.glsl, harness_shade); 1 but
// for bench --lookups-per-pixel, which times a GPU's filters above the harness's own per-pixel cost.
layout(constant_id = HARNESS_SPEC_LOOKUPS) const int LOOKUPS_ID = 1;

// tf::PushConstants (host/scene/shader_interface.h): both sides take the offsets from config.h.
layout(push_constant) uniform PushConstants {
    layout(offset = HARNESS_PUSH_WRAP_MODE) int wrapMode;
    layout(offset = HARNESS_PUSH_LOD_BIAS) float lodBias;
    layout(offset = HARNESS_PUSH_LOD_MIN) float lodMin;
    layout(offset = HARNESS_PUSH_LOD_MAX) float lodMax;
    layout(offset = HARNESS_PUSH_COUNT) uint count;           // sample: number of lookups
    layout(offset = HARNESS_PUSH_BAND) float band;            // brilinear
    layout(offset = HARNESS_PUSH_PROBES) int probes;          // aniso
    layout(offset = HARNESS_PUSH_ANISO_SHAPE) int anisoShape; // aniso: TF_ANISO_GPU / TF_ANISO_FELINE
    layout(offset = HARNESS_PUSH_TAPS) int taps;              // aniso, ewa: TF_TAPS_MANUAL / TF_TAPS_HARDWARE
    layout(offset = HARNESS_PUSH_ALPHA) float alpha;          // ewa
    layout(offset = HARNESS_PUSH_MAX_ANISO) float maxAniso;   // ewa
    layout(offset = HARNESS_PUSH_BOXES) int boxes;            // sat-assembly
    layout(offset = HARNESS_PUSH_TRUTH_SIDE) int truthSide;   // ground-truth: samples a pixel = side^2
    layout(offset = HARNESS_PUSH_PIXEL_FILTER) int pixelFilter; // ground-truth: HARNESS_PIXEL_FILTER_*
    // sat: per channel, the value of quantisation level 0 and the span of levels 0..65535
    // (SatTable::offset, ::scale; see sat.glsl)
    layout(offset = HARNESS_PUSH_SAT_OFFSET) vec4 satOffset;
    layout(offset = HARNESS_PUSH_SAT_SCALE) vec4 satScale;
    layout(offset = HARNESS_PUSH_TRUTH_FIRST) int truthFirst; // ground-truth: samples [first, first + count)
    layout(offset = HARNESS_PUSH_TRUTH_COUNT) int truthCount; // of the grid; 0 = from first to the end
    // render: the gradients times this. 1, but in the viewer's previews, rendered at 1/k of the size: 1/k, so
    // each preview pixel is filtered with the footprint of a full-size pixel (the same LOD and cost a lookup).
    layout(offset = HARNESS_PUSH_GRADIENT_SCALE) float gradientScale;
    layout(offset = HARNESS_PUSH_LAYER) int layer;         // sample: array layer, first bindless index
    layout(offset = HARNESS_PUSH_COMPARE_OP) int compareOp; // sample, shadow: VkCompareOp (manual filters)
    layout(offset = HARNESS_PUSH_DREF) float dref;          // sample, shadow: the reference depth
    layout(offset = HARNESS_PUSH_TRUTH_ANALYTIC) int truthAnalytic; // ground-truth: HARNESS_ANALYTIC_*
    layout(offset = HARNESS_PUSH_STOCHASTIC) int stochastic; // --stochastic: frame * 4 + HARNESS_NOISE_*
} pc;

#endif
