#pragma once
// Image files through OpenImageIO (or a stub in builds with TEXFILTER_IMAGE_IO=OFF).
#include "image.h"
#include <string>

namespace tf {

// Whether this build can read and write image files at all.
bool image_io_available();

enum class ColorSpace { automatic, srgb, linear };

// Reads any file OpenImageIO can (PNG, JPEG, EXR, TIFF, ...; 8/16-bit/half/float; 1-4 channels) into
// linear RGBA. automatic: 8-bit (and 16-bit PNG/JPEG) sources whose colour space is sRGB or unknown
// are decoded from sRGB; float/half sources are taken as linear. linear/srgb force the choice.
// Grey is replicated to RGB; a missing alpha becomes 1. Throws tf::Error naming the path and the
// problem: missing, empty, unreadable/corrupt, or larger than max_dimension on a side.
Image read_image(const std::string& path, ColorSpace space, int max_dimension);

// Writes a linear image. .png: 8-bit sRGB-encoded RGBA; .exr: half-float linear RGBA (zip); .pfm:
// float RGB, linear (built in, so also in builds without image I/O).
// Other extensions: tf::Error. Writes to a temporary file beside the target and renames it, so a
// failure never leaves a partial output.
void write_image(const std::string& path, const Image& image);

// A PNG as stored (no decode), values in [0,1] per channel: what goldens are compared against.
// Also used for any file the diff command reads. Throws tf::Error like read_image.
Image read_image_raw(const std::string& path);

} // namespace tf
