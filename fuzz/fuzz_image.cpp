// libFuzzer target: loading an image file through the project's entry point (tf::read_image in
// host/io/image_io.cpp, OpenImageIO underneath) and building its MIP chain (host/texture/mip.cpp). The input is
// the file's bytes; it is written to a scratch file whose extension follows the content's magic number
// (PNG, JPEG, EXR, TIFF, PFM, else .img), as a user's file would be named.
// Asserts: only tf::Error escapes (naming the path); an accepted image has the size its header gave,
// within the limit asked for, with its full MIP chain by the floor rule; PNG and JPEG (integer formats)
// decode into [0, 1]; finite texels average to finite MIP texels.
// The size limit is 512 (not the CLI's 16384) so that one input stays a few MB: what a tiny file that
// claims a huge image costs is the loader's memory budget's business, tested there.
#include "texture/error.h"
#include "fuzz_common.h"
#include "io/image_io.h"
#include "texture/mip.h"

#include <OpenImageIO/imageio.h>

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;

constexpr int max_side = 512;
fs::path scratch;

void remove_scratch()
{
    std::error_code ec;
    fs::remove_all(scratch, ec);
}

bool starts(const uint8_t* data, size_t size, const char* magic, size_t n)
{
    return size >= n && std::memcmp(data, magic, n) == 0;
}

const char* extension_for(const uint8_t* data, size_t size)
{
    if (starts(data, size, "\x89PNG", 4))
        return ".png";
    if (starts(data, size, "\xff\xd8", 2))
        return ".jpg";
    if (starts(data, size, "\x76\x2f\x31\x01", 4))
        return ".exr";
    if (starts(data, size, "II*\0", 4) || starts(data, size, "MM\0*", 4))
        return ".tif";
    if (starts(data, size, "PF", 2) || starts(data, size, "Pf", 2))
        return ".pfm";
    return ".img";
}

// A crash ends the process without atexit: remove what earlier processes, now gone, left behind.
void remove_stale_scratch(const fs::path& temp, const std::string& prefix)
{
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(temp, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) != 0)
            continue;
        const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
        if (pid > 0 && kill(pid_t(pid), 0) != 0 && errno == ESRCH)
            fs::remove_all(entry.path(), ec);
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    OIIO::attribute("threads", 1); // one thread: reproducible, and no pool growing across inputs
    OIIO::attribute("exr_threads", 1);
    const std::string prefix = "texfilter-fuzz-image-";
    remove_stale_scratch(fs::temp_directory_path(), prefix);
    scratch = fs::temp_directory_path() / (prefix + std::to_string(getpid()));
    fs::create_directories(scratch);
    std::atexit(remove_scratch);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const std::string extension = extension_for(data, size);
    const std::string path = (scratch / ("input" + extension)).string();
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
        FUZZ_CHECK(bool(out), "cannot write " + path);
    }
    tf::Image image;
    try {
        image = tf::read_image(path, tf::ColorSpace::automatic, max_side);
    } catch (const tf::Error& e) {
        FUZZ_CHECK(std::string(e.what()).rfind(path, 0) == 0, e.what());
        std::remove(path.c_str());
        OIIO::geterror(); // nothing may pile up across inputs
        return 0;
    }
    std::remove(path.c_str());
    FUZZ_CHECK(image.width >= 1 && image.height >= 1 && image.width <= max_side && image.height <= max_side,
               std::to_string(image.width) + "x" + std::to_string(image.height));
    FUZZ_CHECK(image.texels.size() == size_t(image.width) * size_t(image.height));
    bool finite = true;
    for (const glm::vec4& t : image.texels)
        finite = finite && std::isfinite(t.r) && std::isfinite(t.g) && std::isfinite(t.b) && std::isfinite(t.a);
    if (extension == ".png" || extension == ".jpg")
        for (const glm::vec4& t : image.texels)
            for (int c = 0; c < 4; ++c)
                FUZZ_CHECK(t[c] >= 0.0f && t[c] <= 1.0f, extension + " texel channel " + std::to_string(t[c]));

    const int w0 = image.width, h0 = image.height;
    const tf::MipChain chain = tf::build_mip_chain(std::move(image));
    FUZZ_CHECK(int(chain.levels.size()) == tf::mip_level_count(w0, h0));
    for (size_t l = 0; l < chain.levels.size(); ++l) {
        const tf::Image& level = chain.levels[l];
        FUZZ_CHECK(level.width == std::max(1, w0 >> l) && level.height == std::max(1, h0 >> l));
        FUZZ_CHECK(level.texels.size() == size_t(level.width) * size_t(level.height));
        if (finite)
            for (const glm::vec4& t : level.texels)
                FUZZ_CHECK(std::isfinite(t.r) && std::isfinite(t.g) && std::isfinite(t.b) && std::isfinite(t.a),
                           "level " + std::to_string(l) + " of finite texels is not finite");
    }
    return 0;
}
