// tint.glsl: the caller's include; tests/shader_package.sh edits TINT to check that sky.frag.glsl rebuilds.
#ifndef TINT_GLSL
#define TINT_GLSL
#define TINT 0.75
vec4 sky_tint() { return vec4(TINT, TINT, 1.0, 1.0); }
#endif
