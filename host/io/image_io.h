#pragma once
// Image files through OpenImageIO (or a stub in builds with TEXFILTER_IMAGE_IO=OFF). OIIO lives in the image
// I/O module texfilter_oiio.so, loaded on the first call that reads or writes an image file (io/oiio_loader.h):
// a process that touches none never pays its third of a second of dynamic loading.
#include "texture/image.h"
#include <string>

namespace tf {

// Whether this build can read and write image files at all (nothing is loaded to say so).
bool image_io_available();

// Loads the image I/O module now: a command that will write an image calls it before any work, so that a
// missing or unloadable module (tf::Error naming its path and dlerror()) fails fast. Reads load it anyway.
void load_image_io();

enum class ColorSpace { automatic, srgb, linear };

struct ImageHeader {
    int width = 0, height = 0, channels = 0;
};

// The size a file claims, from its header alone (no pixels decoded), checked like read_image: missing,
// empty, not an image, a side over max_dimension, or more pixels than the file's bytes can hold (a PNG's
// deflate stream expands at most 1032:1, so a tiny file claiming a huge image is corrupt, not big).
ImageHeader read_image_header(const std::string& path, int max_dimension);

// Reads any file OpenImageIO can (PNG, JPEG, EXR, TIFF, ...; 8/16-bit/half/float; 1-4 channels) into
// linear RGBA. automatic: 8-bit (and 16-bit PNG/JPEG) sources whose colour space is sRGB or unknown
// are decoded from sRGB; float/half sources are taken as linear. linear/srgb force the choice.
// Grey is replicated to RGB; a missing alpha becomes 1. Throws tf::Error naming the path and the
// problem: missing, empty, unreadable/corrupt, truncated (any pixel data the decoder could not read, also
// where OpenImageIO itself would fill it with zeros), or larger than max_dimension on a side, or holding a
// NaN or ±Inf texel (a texture: every filter needs finite texels; the message names the first and the count).
// Messages the image libraries print on their own (libpng) are caught and become part of the one error message.
Image read_image(const std::string& path, ColorSpace space, int max_dimension);

// As read_image, into the caller's width x height texels (the size read_image_header gave; a file that
// changed meanwhile is an error): a GPU upload decodes straight into its staging memory this way.
void read_image_into(const std::string& path, ColorSpace space, int max_dimension, int width, int height,
                     glm::vec4* texels);

// Writes a linear image. .png: 8-bit sRGB-encoded RGBA; .exr: half-float linear RGBA (zip, no DateTime, so
// the same image always gives the same bytes); .pfm:
// float RGB, linear (built in, so also in builds without image I/O).
// Other extensions: tf::Error. Writes to a temporary file beside the target and renames it, so a
// failure never leaves a partial output.
void write_image(const std::string& path, const Image& image);

// The largest side read_image_raw accepts: diffs read whatever they are given, so this only guards against
// absurd headers (the memory budget is the real limit).
constexpr int raw_image_max_dimension = 32768;

// A PNG as stored (no decode), values in [0,1] per channel: what goldens are compared against.
// Also used for any file the diff command reads, whose values are kept as they are, NaN and ±Inf included.
// Throws tf::Error like read_image otherwise.
Image read_image_raw(const std::string& path);

} // namespace tf
