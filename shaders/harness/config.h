// Shared by the C++ host and the harness shaders (GLSL): binding numbers, filter and scene ids.
// Plain #defines so that one file serves both languages. The ids match tf::Filter, tf::Wrap.
#ifndef TF_HARNESS_CONFIG_H
#define TF_HARNESS_CONFIG_H

// Filter ids, in tf::Filter order.
#define TF_FILTER_NEAREST 0
#define TF_FILTER_BILINEAR 1
#define TF_FILTER_TRILINEAR 2
#define TF_FILTER_NEAREST_MIP 3
#define TF_FILTER_BILINEAR_MIP 4
#define TF_FILTER_HW_NEAREST 5
#define TF_FILTER_HW_BILINEAR 6
#define TF_FILTER_HW_TRILINEAR 7
#define TF_FILTER_HW_ANISO 8

// Scene kinds: a textured plane or quad (plane, zoom, minify, slanted) and a cylinder (tunnel).
#define TF_SCENE_PLANE 0
#define TF_SCENE_CYLINDER 1

// Descriptor set 0.
#define TF_BINDING_TEXTURE 0 // combined image sampler: the MIP chain (texelFetch ignores the sampler)
#define TF_BINDING_SCENE 1   // uniform buffer: tf_SceneParams (render)
#define TF_BINDING_LOOKUPS 1 // storage buffer: 6 floats a lookup (sample)
#define TF_BINDING_RESULTS 2 // storage buffer: vec4 a lookup (sample)

#define TF_SAMPLE_LOCAL_SIZE 64

#endif
