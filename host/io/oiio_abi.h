#pragma once
// The C table between the io layer (image_io.cpp) and the image I/O module texfilter_oiio.so
// (oiio_module.cpp), which alone links OpenImageIO. OIIO and the ~260 libraries it pulls in cost a
// third of a second of dynamic loading per process start, so the module is dlopen'ed on the first image
// file read or written (oiio_loader.h), and a command that touches none never pays for it.
//
// Only C types cross: ints, floats, C strings, function pointers, a void* context. Nothing is thrown
// across: every entry returns 1 on success, or 0 after handing the whole tf::Error text (path included)
// to call->fail. Texels are linear RGBA, four floats each (glm::vec4's layout), rows top to bottom.
//
// Besides image files, the module runs OpenImageIO's TextureSystem on a batch of lookups (texture_lookups):
// the project's peer, io/oiio_texture.h.
//
// Use (image_io.cpp): tf_oiio_call call{&state, fail, destination};
//                     if (!api.read_rgba(path, max_side, 0, TF_OIIO_AUTOMATIC, &call)) throw Error(state.message);
// Cost: nothing per call beyond OIIO's own work; the module is loaded once per process.
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

// Bumped whenever the table or a call's meaning changes: the loader refuses any other.
#define TF_OIIO_ABI_VERSION 3
// The one symbol the module exports: tf_oiio_api_v1() returns its table.
#define TF_OIIO_ENTRY "tf_oiio_api_v1"

// image_io.h's ColorSpace, as passed to read_rgba.
enum { TF_OIIO_AUTOMATIC = 0, TF_OIIO_SRGB = 1, TF_OIIO_LINEAR = 2 };

// texture_lookups' modes, each an OIIO TextureOpt value (the module maps them): wrap, mipmode, interpmode.
enum { TF_OIIO_WRAP_PERIODIC = 0, TF_OIIO_WRAP_CLAMP = 1, TF_OIIO_WRAP_MIRROR = 2 };
enum { TF_OIIO_MIP_TRILINEAR = 0, TF_OIIO_MIP_ANISO = 1 };
enum { TF_OIIO_INTERP_CLOSEST = 0, TF_OIIO_INTERP_BILINEAR = 1, TF_OIIO_INTERP_BICUBIC = 2,
       TF_OIIO_INTERP_SMARTBICUBIC = 3 };

// One batch of TextureSystem lookups on one texture.
struct tf_oiio_texture_job {
    // A directory only this process can write (mode 0700), made and removed by the host: the module writes the
    // MIP-mapped texture file there (ImageBufAlgo::make_texture, which also stages its own temporary beside it)
    // for the TextureSystem to read, and leaves it there.
    const char* directory;
    int width, height;
    const float* rgba;      // level 0: width x height texels, 4 floats each, rows top to bottom
    int wrap, mip, interp;  // TF_OIIO_WRAP_*, TF_OIIO_MIP_*, TF_OIIO_INTERP_*
    const double* lookups;  // count x 6: u, v, dudx, dvdx, dudy, dvdy (tf::Lookup's layout); OIIO takes floats
    int64_t count;
    float* colors;          // count x 4: RGBA a lookup, written by the module
};

struct tf_oiio_header {
    int width, height, channels; // channels: 1..4 (a file's first four)
};

// What the host hands each call.
struct tf_oiio_call {
    void* context;
    // The call failed: message is the tf::Error's whole text. Called at most once per call.
    void (*fail)(void* context, const char* message);
    // read_rgba only: where the width x height texels go (4 floats each), asked for once the header is
    // checked; null gives up (the host keeps its own reason: the module then reports nothing).
    float* (*destination)(void* context, int width, int height);
};

struct tf_oiio_api {
    uint32_t abi_version; // TF_OIIO_ABI_VERSION
    // image_io.h's read_image_header.
    int (*read_header)(const char* path, int max_dimension, struct tf_oiio_header* header,
                       const struct tf_oiio_call* call);
    // read_image/read_image_into/read_image_raw: raw != 0 decodes nothing (read_image_raw), else
    // space (TF_OIIO_*) decides as image_io.h says.
    int (*read_rgba)(const char* path, int max_dimension, int raw, int space, const struct tf_oiio_call* call);
    // write_image's .png (png != 0: 8-bit sRGB) or .exr (half linear) into fd, the open temporary file the
    // host created (never reopened by name); messages name path. The caller closes and renames it.
    int (*write_rgba)(const char* path, int fd, int png, int width, int height,
                      const float* rgba, const struct tf_oiio_call* call);
    // OpenImageIO's TextureSystem on job->count lookups (io/oiio_texture.h); messages name no file (the
    // texture is the host's, the file a private detail).
    int (*texture_lookups)(const struct tf_oiio_texture_job* job, const struct tf_oiio_call* call);
};

typedef const struct tf_oiio_api* (*tf_oiio_entry)(void);
// The entry itself: dlsym'ed by name (oiio_loader.cpp); the fuzz build, which links the module's code in,
// calls it directly (fuzz/oiio_linked.cpp).
const struct tf_oiio_api* tf_oiio_api_v1(void);

#ifdef __cplusplus
}
#endif
