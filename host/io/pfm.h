#pragma once
// Portable Float Map (colour "PF"): linear RGB float32 with no library behind it, so that every
// build, the lean one without OpenImageIO included, can write renders and benchmark images.
#include "texture/image.h"
#include <istream>
#include <string>

namespace tf {

bool is_pfm_path(const std::string& path); // ends in .pfm (any case)

// Linear RGB (alpha dropped), little-endian, bottom row first as the format says; written through a
// temporary file and a rename, so a failure leaves nothing behind.
void write_pfm(const std::string& path, const Image& image);

// Reads what write_pfm writes (any PF file: either byte order); alpha 1. Throws tf::Error naming the
// path and the problem (missing, not a colour PFM, truncated, absurd size).
Image read_pfm(const std::string& path);
// The same from a seekable binary stream; `name` stands for the file in messages (the fuzz target reads
// from memory).
Image read_pfm(std::istream& in, const std::string& name);

} // namespace tf
