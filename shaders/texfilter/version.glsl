// texfilter/version.glsl — the version of these includes, as macros (no functions, no types).
//
// Use:     #include "texfilter/version.glsl"   (common.glsl, and so every include, pulls it in)
//          TF_VERSION_MAJOR, TF_VERSION_MINOR, TF_VERSION_PATCH, and
//          TF_VERSION = MAJOR·10000 + MINOR·100 + PATCH (0.7.0 → 700), usable in #if. It is the CMake
//          project's version too (CMakeLists.txt refuses to configure when they differ).
// Options: none.
// Needs:   nothing.
// Cost:    none (preprocessor only).
// Degenerate input: none (no functions).
// Example: #if TF_VERSION < 200   // before 0.2.0
//          #error "texfilter 0.2 or newer needed"
//          #endif
#ifndef TF_VERSION_GLSL
#define TF_VERSION_GLSL

#define TF_VERSION_MAJOR 0
#define TF_VERSION_MINOR 9
#define TF_VERSION_PATCH 0
#define TF_VERSION (TF_VERSION_MAJOR * 10000 + TF_VERSION_MINOR * 100 + TF_VERSION_PATCH)

#endif
