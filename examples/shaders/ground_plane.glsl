// ground_plane.glsl — texfilter example: the scene both pipelines draw, shared so that the fragment
// and compute images come from the same math: a checkerboard on an endless ground plane seen from a
// pinhole camera one unit above it. Include after texfilter/texfilter.glsl.

// Which texfilter filter to use; main.cpp sets it for both pipelines (specialization constant 0).
#define FILTER_TRILINEAR 0
#define FILTER_EWA 1
layout(constant_id = 0) const int FILTER = FILTER_EWA;

layout(set = 0, binding = 0) uniform sampler2D checker; // RGBA8 with a full MIP chain
layout(push_constant) uniform Params { ivec2 imageSize; } params;

const vec3 SKY = vec3(0.45, 0.62, 0.85); // linear RGB
const float HORIZON_NDC = -0.6;          // the horizon's height in NDC (y down): the top 20% is sky
const float UNITS_PER_REPEAT = 4.0;      // ground units covered by one copy of the texture

// Texture coordinates of the ground seen through a pixel centre (in pixels); z is 1 where the ray
// hits the ground and 0 above the horizon. Rays above the horizon are bent to just below it, so uv
// stays finite there: quads that straddle the horizon get large but finite gradients, and the
// filters read coarse MIP levels, which is what that footprint needs.
vec3 ground_uv(vec2 pixelCentre)
{
    vec2 ndc = 2.0 * pixelCentre / vec2(params.imageSize) - 1.0;
    // Camera looking along +z, 90 degree field of view; the lens is shifted so that the horizon
    // sits at HORIZON_NDC rather than in the middle of the image.
    vec3 dir = vec3(ndc.x, ndc.y - HORIZON_NDC, 1.0);
    float drop = max(dir.y, 1.0 / 1024.0);  // the ground is one unit below the camera
    vec2 hit = dir.xz / drop;               // (x, z) where the ray meets it
    return vec3(hit / UNITS_PER_REPEAT, dir.y > 0.0 ? 1.0 : 0.0);
}

// The colour of a pixel (linear RGB) from its ground_uv() and the uv gradients of its 2x2 quad.
vec4 shade(vec3 ground, tf_Gradients g)
{
    if (ground.z == 0.0)
        return vec4(SKY, 1.0);
    tf_Sampler s = tf_sampler(TF_WRAP_REPEAT);
    vec4 c = FILTER == FILTER_TRILINEAR ? tf_trilinear(checker, ground.xy, g.dUVdx, g.dUVdy, s)
                                        : tf_ewa(checker, ground.xy, g.dUVdx, g.dUVdy, s, 2.0, 16.0);
    return vec4(c.rgb, 1.0);
}
