#pragma once
// The C++ side of the harness shaders' interface, checked against shaders/harness/config.h, where every
// id, offset and size is written once: the push constants every pass shares, sample's records, and (with
// scene.h) the scene block. Each static_assert below names the shader declaration it guards, so that a
// reordered enum or a moved member stops the build instead of running another filter or reading garbage.
#include "core/filter.h"
#include "core/lookup_stats.h"
#include "harness/config.h"
#include "scene/scene.h"
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

namespace tf {

// PushConstants in shaders/harness/filter_select.glsl (std430, explicit offsets from config.h).
struct PushConstants {
    int32_t wrap_mode; // HARNESS_WRAP_* (tf::Wrap)
    float lod_bias;
    float lod_min;
    float lod_max;
    uint32_t count;
    float band;
    int32_t probes;
    int32_t aniso_shape; // HARNESS_ANISO_* (tf::AnisoShape)
    int32_t taps;        // HARNESS_TAPS_* (tf::Taps)
    float alpha;
    float max_aniso;
    int32_t boxes;
    int32_t free_48;      // free: the gradients are a specialization constant (tf::FilterVariant)
    int32_t truth_side;   // ground-truth: samples a pixel = side^2
    int32_t pixel_filter; // HARNESS_PIXEL_FILTER_* (tf::PixelFilter)
    int32_t free_60;      // free: the debug view is a specialization constant; the vec4s then start 16-byte aligned
    float sat_offset[4];  // sat: SatTable::offset, ::scale (per channel)
    float sat_scale[4];
    int32_t truth_first;      // ground-truth: samples [first, first + count) of the grid (the viewer's
    int32_t truth_count;      // progressive accumulation); 0 = every sample from first on
    float gradient_scale;     // render: uv gradients times this (1; the viewer's previews: their fraction)
    int32_t layer;            // sample: the array layer (array kinds), the first bindless index
    int32_t compare_op;       // sample, shadow kind: VkCompareOp of the manual filters' comparison
    float dref;               // sample, shadow kind: the reference depth
    int32_t truth_analytic;   // ground-truth: HARNESS_ANALYTIC_* (tf::AnalyticKind; NONE: the texels)
    int32_t stochastic;       // --stochastic: frame * 4 + HARNESS_NOISE_* (stochastic_push); 0 off. The last slot:
                              // HARNESS_PUSH_SIZE is 128
};
static_assert(offsetof(PushConstants, wrap_mode) == HARNESS_PUSH_WRAP_MODE);
static_assert(offsetof(PushConstants, lod_bias) == HARNESS_PUSH_LOD_BIAS);
static_assert(offsetof(PushConstants, lod_min) == HARNESS_PUSH_LOD_MIN);
static_assert(offsetof(PushConstants, lod_max) == HARNESS_PUSH_LOD_MAX);
static_assert(offsetof(PushConstants, count) == HARNESS_PUSH_COUNT);
static_assert(offsetof(PushConstants, band) == HARNESS_PUSH_BAND);
static_assert(offsetof(PushConstants, probes) == HARNESS_PUSH_PROBES);
static_assert(offsetof(PushConstants, aniso_shape) == HARNESS_PUSH_ANISO_SHAPE);
static_assert(offsetof(PushConstants, taps) == HARNESS_PUSH_TAPS);
static_assert(offsetof(PushConstants, alpha) == HARNESS_PUSH_ALPHA);
static_assert(offsetof(PushConstants, max_aniso) == HARNESS_PUSH_MAX_ANISO);
static_assert(offsetof(PushConstants, boxes) == HARNESS_PUSH_BOXES);
static_assert(offsetof(PushConstants, free_48) == HARNESS_PUSH_FREE_48);
static_assert(offsetof(PushConstants, truth_side) == HARNESS_PUSH_TRUTH_SIDE);
static_assert(offsetof(PushConstants, pixel_filter) == HARNESS_PUSH_PIXEL_FILTER);
static_assert(offsetof(PushConstants, free_60) == HARNESS_PUSH_FREE_60);
static_assert(offsetof(PushConstants, sat_offset) == HARNESS_PUSH_SAT_OFFSET);
static_assert(offsetof(PushConstants, sat_scale) == HARNESS_PUSH_SAT_SCALE);
static_assert(offsetof(PushConstants, truth_first) == HARNESS_PUSH_TRUTH_FIRST);
static_assert(offsetof(PushConstants, truth_count) == HARNESS_PUSH_TRUTH_COUNT);
static_assert(offsetof(PushConstants, gradient_scale) == HARNESS_PUSH_GRADIENT_SCALE);
static_assert(offsetof(PushConstants, layer) == HARNESS_PUSH_LAYER);
static_assert(offsetof(PushConstants, compare_op) == HARNESS_PUSH_COMPARE_OP);
static_assert(offsetof(PushConstants, dref) == HARNESS_PUSH_DREF);
static_assert(offsetof(PushConstants, truth_analytic) == HARNESS_PUSH_TRUTH_ANALYTIC);
static_assert(offsetof(PushConstants, stochastic) == HARNESS_PUSH_STOCHASTIC);
static_assert(sizeof(PushConstants) == HARNESS_PUSH_SIZE);

// SceneBlock in shaders/harness/scene.glsl (std140: vec4 members and vec4 arrays, 16 bytes each).
static_assert(offsetof(SceneParams, origin) == 0 * 16 && offsetof(SceneParams, forward) == 1 * 16 &&
              offsetof(SceneParams, right) == 2 * 16 && offsetof(SceneParams, up) == 3 * 16 &&
              offsetof(SceneParams, p0) == 4 * 16 && offsetof(SceneParams, axis_u) == 5 * 16 &&
              offsetof(SceneParams, axis_v) == 6 * 16 && offsetof(SceneParams, extent) == 7 * 16 &&
              offsetof(SceneParams, background) == 8 * 16 && offsetof(SceneParams, kind_size) == 9 * 16,
              "SceneParams: the members of scene.glsl's SceneParams, in order, one vec4 each");
static_assert(offsetof(SceneParams, positions) == HARNESS_SCENE_POSITIONS);
static_assert(offsetof(SceneParams, uvs) == HARNESS_SCENE_UVS);
static_assert(sizeof(SceneParams) == HARNESS_SCENE_SIZE);
static_assert(sizeof(glm::vec4) == 16 && sizeof(glm::ivec4) == 16, "std140 vec4 and ivec4");

// sample.comp.glsl's buffers: a lookup is HARNESS_LOOKUP_FLOATS floats, a result a vec4, stats a uvec2.
struct LookupRecord {
    float u, v, dudx, dvdx, dudy, dvdy;
};
static_assert(sizeof(LookupRecord) == HARNESS_LOOKUP_FLOATS * sizeof(float));
static_assert(sizeof(glm::vec4) == HARNESS_RESULT_FLOATS * sizeof(float));
static_assert(offsetof(LookupStats, texel_fetches) == 0 && offsetof(LookupStats, hardware_lookups) == 4 &&
              sizeof(LookupStats) == HARNESS_STATS_UINTS * sizeof(uint32_t),
              "LookupStats: uvec2(fetches, hardware lookups)");

// Every enum value a shader compares with an id (the enums take their values from config.h; these fail
// if one is renumbered by hand).
static_assert(int(Filter::nearest) == HARNESS_FILTER_NEAREST && int(Filter::bilinear) == HARNESS_FILTER_BILINEAR &&
              int(Filter::trilinear) == HARNESS_FILTER_TRILINEAR &&
              int(Filter::nearest_mip) == HARNESS_FILTER_NEAREST_MIP &&
              int(Filter::bilinear_mip) == HARNESS_FILTER_BILINEAR_MIP &&
              int(Filter::hw_nearest) == HARNESS_FILTER_HW_NEAREST &&
              int(Filter::hw_bilinear) == HARNESS_FILTER_HW_BILINEAR &&
              int(Filter::hw_trilinear) == HARNESS_FILTER_HW_TRILINEAR &&
              int(Filter::hw_aniso) == HARNESS_FILTER_HW_ANISO && int(Filter::brilinear) == HARNESS_FILTER_BRILINEAR &&
              int(Filter::aniso) == HARNESS_FILTER_ANISO && int(Filter::ewa) == HARNESS_FILTER_EWA &&
              int(Filter::sat) == HARNESS_FILTER_SAT && int(Filter::sat_assembly) == HARNESS_FILTER_SAT_ASSEMBLY &&
              int(Filter::ground_truth) == HARNESS_FILTER_GROUND_TRUTH && int(Filter::none) == HARNESS_FILTER_NONE &&
              int(Filter::bspline) == HARNESS_FILTER_BSPLINE && int(Filter::catmull_rom) == HARNESS_FILTER_CATMULL_ROM &&
              int(Filter::ewa_fast) == HARNESS_FILTER_EWA_FAST,
              "tf::Filter: the specialization constant of filter_select.glsl");
static_assert(int(Wrap::repeat) == HARNESS_WRAP_REPEAT && int(Wrap::clamp) == HARNESS_WRAP_CLAMP &&
              int(Wrap::mirror) == HARNESS_WRAP_MIRROR, "tf::Wrap: PushConstants.wrapMode");
static_assert(int(AnisoShape::gpu) == HARNESS_ANISO_GPU && int(AnisoShape::feline) == HARNESS_ANISO_FELINE,
              "tf::AnisoShape: PushConstants.anisoShape");
static_assert(int(Taps::manual) == HARNESS_TAPS_MANUAL && int(Taps::hardware) == HARNESS_TAPS_HARDWARE,
              "tf::Taps: PushConstants.taps");
static_assert(int(PixelFilter::box) == HARNESS_PIXEL_FILTER_BOX &&
              int(PixelFilter::gaussian) == HARNESS_PIXEL_FILTER_GAUSSIAN,
              "tf::PixelFilter: PushConstants.pixelFilter");
static_assert(int(AnalyticKind::none) == HARNESS_ANALYTIC_NONE && int(AnalyticKind::checker) == HARNESS_ANALYTIC_CHECKER &&
              int(AnalyticKind::zoneplate) == HARNESS_ANALYTIC_ZONEPLATE && int(AnalyticKind::grid) == HARNESS_ANALYTIC_GRID,
              "tf::AnalyticKind: PushConstants.truthAnalytic");
static_assert(int(Gradients::fine) == HARNESS_GRADIENTS_FINE && int(Gradients::coarse) == HARNESS_GRADIENTS_COARSE &&
              int(Gradients::ray) == HARNESS_GRADIENTS_RAY && int(Gradients::cone) == HARNESS_GRADIENTS_CONE,
              "tf::Gradients: HARNESS_SPEC_GRADIENTS");
static_assert(int(DebugView::color) == HARNESS_VIEW_COLOR && int(DebugView::lod) == HARNESS_VIEW_LOD &&
              int(DebugView::anisotropy) == HARNESS_VIEW_ANISOTROPY &&
              int(DebugView::fetches) == HARNESS_VIEW_FETCHES && int(DebugView::data) == HARNESS_VIEW_DATA,
              "tf::DebugView: HARNESS_SPEC_VIEW");

} // namespace tf
