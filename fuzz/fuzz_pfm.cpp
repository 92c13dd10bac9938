// libFuzzer target: the PFM reader (host/io/pfm.cpp), from memory. Asserts: only tf::Error escapes, naming
// the file; an accepted file is exactly its header plus width x height x 12 bytes, gives that many texels
// with alpha 1, and never needs more memory than the input's size says (the length is checked first).
#include "texture/error.h"
#include "fuzz_common.h"
#include "io/pfm.h"

#include <cstdint>
#include <sstream>

namespace {
const std::string name = "fuzz.pfm";
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size), std::ios::binary);
    tf::Image image;
    try {
        image = tf::read_pfm(in, name);
    } catch (const tf::Error& e) {
        FUZZ_CHECK(std::string(e.what()).rfind(name + ": ", 0) == 0, e.what());
        return 0;
    }
    FUZZ_CHECK(image.width >= 1 && image.height >= 1);
    const size_t texels = size_t(image.width) * size_t(image.height);
    FUZZ_CHECK(image.texels.size() == texels);
    FUZZ_CHECK(texels * 12 < size, "the pixels are in the input");
    for (const glm::vec4& t : image.texels)
        FUZZ_CHECK(t.a == 1.0f);
    return 0;
}
