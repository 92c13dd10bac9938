#pragma once
// A PFM file read as an image (io/image_io.h's read calls, every build): the built-in reader, so that a PFM
// texture is checked the same way with or without OpenImageIO (its header's scale, its length, its texels).
#include "io/image_io.h"
#include <string>

namespace tf {

// The header of the PFM at `path`, checked as read_pfm_header does (missing: "no such file").
ImageHeader read_pfm_image_header(const std::string& path, int max_dimension);

// Its texels. finite: NaN and ±Inf texels are refused, naming the first and their number (texture loads);
// diffs read what is there.
Image read_pfm_image(const std::string& path, int max_dimension, bool finite);

// Into the caller's width x height texels (the header's size: a file that changed meanwhile is an error);
// non-finite texels refused.
void read_pfm_image_into(const std::string& path, int max_dimension, int width, int height, glm::vec4* texels);

} // namespace tf
