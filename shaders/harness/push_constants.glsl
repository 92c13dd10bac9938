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

// tf::PushConstants (host/scene/shader_interface.h): both sides take the offsets from config.h. The members
// sit at their natural std430 offsets, in config.h's order with its free words as padding members, rather
// than under layout(offset = ...): Slang's GLSL front end refuses member offsets, and std430 is the layout
// both compilers give a push_constant block. tests/slang_check.py checks each member's Offset in the SPIR-V
// of glslang and of slangc against HARNESS_PUSH_* (the member's name in upper case with underscores).
layout(push_constant, std430) uniform PushConstants {
    int wrapMode;
    float lodBias;
    float lodMin;
    float lodMax;
    uint count;       // sample: number of lookups
    float band;       // brilinear
    int probes;       // aniso
    int anisoShape;   // aniso: TF_ANISO_GPU / TF_ANISO_FELINE
    int taps;         // aniso, ewa: TF_TAPS_MANUAL / TF_TAPS_HARDWARE
    float alpha;      // ewa
    float maxAniso;   // ewa
    int boxes;        // sat-assembly
    int free_48;      // HARNESS_PUSH_FREE_48: unused
    int truthSide;    // ground-truth: samples a pixel = side^2
    int pixelFilter;  // ground-truth: HARNESS_PIXEL_FILTER_*
    int free_60;      // HARNESS_PUSH_FREE_60: unused
    // sat: per channel, the value of quantisation level 0 and the span of levels 0..65535
    // (SatTable::offset, ::scale; see sat.glsl)
    vec4 satOffset;
    vec4 satScale;
    int truthFirst;   // ground-truth: samples [first, first + count)
    int truthCount;   // of the grid; 0 = from first to the end
    // render: the gradients times this. 1, but in the viewer's previews, rendered at 1/k of the size: 1/k, so
    // each preview pixel is filtered with the footprint of a full-size pixel (the same LOD and cost a lookup).
    float gradientScale;
    int layer;        // sample: array layer, first bindless index
    int compareOp;    // sample, shadow: VkCompareOp (manual filters)
    float dref;       // sample, shadow: the reference depth
    int truthAnalytic; // ground-truth: HARNESS_ANALYTIC_*
    int stochastic;   // --stochastic: frame * 4 + HARNESS_NOISE_*
} pc;

#endif
