#pragma once
// Portable Float Map (colour "PF"): linear RGB float32 with no library behind it, so that every
// build, the lean one without OpenImageIO included, can write renders and benchmark images.
#include "texture/finite.h"
#include "texture/image.h"
#include <ios>
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

// Whether the file's first bytes are a colour PFM's magic ("PF" and a whitespace), whatever its name: image
// reads (io/image_io.h) take such a file through this reader in every build, never through OpenImageIO.
// Every image read asks this first, so it refuses a device, FIFO or socket before anything opens it
// (refuse_special_file, io/text_file.h): no image read blocks on a FIFO or reads a device without end.
bool is_pfm_file(const std::string& path);

struct PfmHeader {
    int width = 0, height = 0;
    bool little = true;        // the scale's sign: negative is little-endian
    std::streamoff pixels = 0; // where the pixel rows start
};
// Reads and checks the header: a colour PFM, sides 1..max_dimension, a finite non-zero scale (0 or "nan"
// would say nothing about the byte order), and exactly width x height x 12 bytes of pixels after it
// ("truncated" when fewer). Leaves the stream at the first pixel.
PfmHeader read_pfm_header(std::istream& in, const std::string& name, int max_dimension);
// The pixel rows into width x height texels (row 0 first, alpha 1); counts non-finite values into
// `non_finite` where given, a row at a time as they are converted.
void read_pfm_pixels(std::istream& in, const PfmHeader& header, const std::string& name, glm::vec4* texels,
                     NonFiniteTexels* non_finite);

} // namespace tf
