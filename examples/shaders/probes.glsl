// probes.glsl — texfilter example: what invocation i of layers, bindless, atlas and virtual.comp.glsl looks up
// (resources.cpp computes the same indices to know the expected colour). Include after texfilter.

layout(push_constant) uniform Params { int count; } pc; // layers, or array elements

struct Probe {
    vec2 uv, dx, dy;
    tf_Sampler s;
};

// Footprints from a tenth of a texel to two texels on the 16x16 level 0 (resources.cpp's bound assumes
// at most two), rotated and sheared, anywhere in the texture.
Probe probe(uint i)
{
    float size = (0.1 + 1.9 * fract(float(i) * 0.618)) / 16.0;
    return Probe(fract(vec2(i) * vec2(0.137, 0.291)), vec2(size, 0.3 * size), vec2(-0.2 * size, size),
                 tf_sampler(TF_WRAP_CLAMP));
}

int probe_index(uint i, int count) { return int(i % uint(count)); }
