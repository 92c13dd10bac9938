// The image I/O module, texfilter_oiio.so: image files, and the TextureSystem peer (io/oiio_texture.h),
// through OpenImageIO, behind the C table of io/oiio_abi.h. OIIO stays inside this file, which is built only
// into the module (dlopen'ed by oiio_loader.cpp on first use; the fuzz build links it in), so the rest of the
// project never sees its headers and a process that reads and writes no image file never loads it.
#include "io/oiio_abi.h"

#include "texture/error.h"
#include "texture/finite.h"
#include "texture/image.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/parallel.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <cstdio>
#include <unistd.h>

namespace tf {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// OIIO keeps errors in a queue per object (and one global queue); leaving them there makes it
// complain at exit, so every failure path drains the relevant queue into our message.
std::string oiio_message(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    // One message, one line: OIIO joins several library errors with newlines.
    for (size_t at; (at = text.find('\n')) != std::string::npos;) text.replace(at, 1, "; ");
    return text.empty() ? std::string("unknown OpenImageIO error") : text;
}

void check_readable_file(const std::string& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) throw Error(path + ": no such file");
    if (fs::is_directory(status)) throw Error(path + ": is a directory, not an image file");
    // OpenImageIO would say only "cannot open as an image"; the system says why (Permission denied).
    if (std::FILE* file = std::fopen(path.c_str(), "rb"))
        std::fclose(file);
    else
        throw Error(path + ": " + std::strerror(errno));
    const auto size = fs::file_size(path, ec);
    if (ec) throw Error(path + ": cannot read (" + ec.message() + ")");
    if (size == 0) throw Error(path + ": file is empty");
}

bool names_linear(const std::string& color_space) {
    const std::string cs = lower(color_space);
    return cs == "linear" || cs == "scene_linear" || cs == "acescg" || cs.rfind("lin_", 0) == 0;
}

// The automatic rule of image_io.h: 8-bit is sRGB unless it says linear; 16-bit only where the
// format is conventionally sRGB (PNG, JPEG) or the file names a non-linear space; float/half and
// everything else is linear.
bool stored_as_srgb(const OIIO::ImageSpec& spec, const std::string& format_name) {
    const std::string cs = spec.get_string_attribute("oiio:ColorSpace");
    if (names_linear(cs)) return false;
    if (spec.format.basetype == OIIO::TypeDesc::UINT8) return true;
    if (spec.format.basetype == OIIO::TypeDesc::UINT16)
        return format_name == "png" || format_name == "jpeg" || !cs.empty();
    return false;
}

// libpng's default error handler (which OIIO 2.4 keeps) prints "libpng error: ..." to stderr before OIIO
// reports the same failure. While a decoder runs, file descriptor 2 points at an unnamed temporary file;
// what landed there is handed back, so a failure gives one message and a success can pass warnings on.
class StderrCapture {
public:
    StderrCapture()
    {
        std::fflush(stderr);
        capture_ = std::tmpfile();
        saved_ = capture_ ? dup(2) : -1;
        if (saved_ >= 0 && dup2(fileno(capture_), 2) < 0) {
            close(saved_);
            saved_ = -1;
        }
    }
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;
    ~StderrCapture() { finish(); }

    // Restores stderr and returns what was written meanwhile (at most a few KB are kept).
    std::string finish()
    {
        std::string text;
        if (saved_ >= 0) {
            std::fflush(stderr);
            dup2(saved_, 2);
            close(saved_);
            saved_ = -1;
            std::rewind(capture_);
            char buffer[4096];
            const size_t n = std::fread(buffer, 1, sizeof buffer, capture_);
            text.assign(buffer, n);
        }
        if (capture_) {
            std::fclose(capture_);
            capture_ = nullptr;
        }
        return text;
    }

private:
    std::FILE* capture_ = nullptr;
    int saved_ = -1;
};

// What the file holds, from its header: the decode rules of image_io.h apply to it.
struct PixelFormat {
    int width = 0, height = 0, channels = 0;  // channels: 1..4 as read
    bool srgb = false;                        // what the automatic rule says about this file
    int integer_levels = 0;                   // 255 / 65535 for UINT8 / UINT16, else 0
};

// The host's destination gave up (its own reason is kept on its side): unwinds to the entry point.
struct HostGaveUp {};

// tf_oiio_call::destination as texels. glm::vec4 is four floats, which is what the table passes.
static_assert(sizeof(glm::vec4) == 4 * sizeof(float) && alignof(glm::vec4) <= alignof(float) * 4);
glm::vec4* destination_texels(const tf_oiio_call& call, int width, int height) {
    float* texels = call.destination ? call.destination(call.context, width, height) : nullptr;
    if (!texels) throw HostGaveUp{};
    return reinterpret_cast<glm::vec4*>(texels);
}

// The first line of a library message, cut to a readable length.
std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    return line.size() > 200 ? line.substr(0, 200) + "..." : line;
}

// Deflate expands at most 1032:1 (258-byte matches coded in 2 bits), so a PNG's filtered rows,
// height x (1 + width x bytes per pixel), can never exceed 1032 times the file's size. The rows are
// counted at the smallest depth PNG has, 1 bit a pixel (1-bit grey or palette; OIIO reports those
// expanded), so no real file is refused. Returns what is wrong, or nothing.
std::string impossible_png_claim(const std::string& path, const OIIO::ImageSpec& spec) {
    std::error_code ec;
    const double file_bytes = double(fs::file_size(path, ec));
    const double row_bytes = 1.0 + std::ceil(double(spec.width) / 8.0);
    if (ec || double(spec.height) * row_bytes <= 1032.0 * file_bytes) return {};
    return "the header claims " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
           " pixels, more than a " + std::to_string(uint64_t(file_bytes)) +
           "-byte PNG can hold (deflate expands at most 1032:1): truncated or corrupt";
}

// OIIO reads a PNM or PFM header's sides into an int that saturates (4294967297 becomes 2147483647): messages
// quote the sides as the header writes them. "" where the header does not read as two words.
std::string netpbm_size_as_written(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[2] = {};
    if (!in.read(magic, 2) || magic[0] != 'P') return "";
    constexpr size_t longest = 24; // a megabyte of digits is quoted in a few dozen characters
    std::string sides[2];
    for (std::string& side : sides) {
        int c = in.get();
        while (c != EOF && (std::isspace(c) || c == '#')) {
            if (c == '#')
                while (c != EOF && c != '\n') c = in.get(); // a PNM comment runs to the end of its line
            c = in.get();
        }
        for (; c != EOF && !std::isspace(c) && side.size() <= longest; c = in.get()) side += char(c);
        if (side.empty()) return "";
        if (side.size() > longest) side = side.substr(0, longest) + "...";
    }
    return sides[0] + "x" + sides[1];
}

// Opens the file and checks what its header claims; the caller reads pixels from the returned input.
std::unique_ptr<OIIO::ImageInput> open_checked(const std::string& path, int max_dimension, StderrCapture& capture) {
    check_readable_file(path);

    // Keep PNG alpha unassociated (as stored): otherwise OIIO premultiplies on read, in the
    // encoded space, and RGB under partial alpha would no longer round-trip.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        const std::string message = oiio_message(OIIO::geterror());
        capture.finish();
        throw Error(path + ": cannot open as an image: " + message);
    }
    const OIIO::ImageSpec& spec = in->spec();
    auto fail = [&](const std::string& what) {
        in->geterror();  // drain
        in->close();
        in->geterror();
        capture.finish();
        throw Error(path + ": " + what);
    };
    auto size = [&] { // for a message only: the header is read again just then
        const std::string as_written = std::string(in->format_name()) == "pnm" ? netpbm_size_as_written(path) : "";
        return !as_written.empty() ? as_written : std::to_string(spec.width) + "x" + std::to_string(spec.height);
    };
    if (spec.width <= 0 || spec.height <= 0 || spec.depth > 1)
        fail("unsupported image size " + size() + (spec.depth > 1 ? "x" + std::to_string(spec.depth) : std::string()));
    if (spec.width > max_dimension || spec.height > max_dimension)
        fail(size() + " exceeds the maximum texture size " + std::to_string(max_dimension));
    if (spec.nchannels <= 0) fail("image has no channels");
    if (std::string(in->format_name()) == "png")
        if (const std::string wrong = impossible_png_claim(path, spec); !wrong.empty()) fail(wrong);
    return in;
}

// Lookup table from stored integer code to linear value, so a large 8/16-bit texture costs no
// pow() per texel.
std::vector<float> srgb_decode_table(int levels) {
    std::vector<float> table(size_t(levels) + 1);
    for (int i = 0; i <= levels; ++i) table[size_t(i)] = float(srgb_to_linear(double(i) / levels));
    return table;
}

// Rows of OIIO's float values (channels a pixel) to linear RGBA: decoded from sRGB where asked, grey
// replicated to RGB, a missing alpha 1, alpha as stored.
class RgbaConverter {
public:
    RgbaConverter(const PixelFormat& format, bool decode_srgb) : format_(format), decode_(decode_srgb)
    {
        if (decode_ && format.integer_levels > 0) table_ = srgb_decode_table(format.integer_levels);
        uint8_t codes[256];
        for (int c = 0; c < 256; ++c) codes[c] = uint8_t(c);
        OIIO::convert_pixel_values(OIIO::TypeDesc::UINT8, codes, OIIO::TypeDesc::FLOAT, alpha8_, 256);
        for (int c = 0; c < 256; ++c) colour8_[c] = decode(alpha8_[c]);
    }

    // 8-bit files are read as bytes and take each channel's value from a table of the 256 codes, holding
    // exactly what the float path gives (OIIO's own conversion, then the decode): same values, no per-value
    // rounding or pow.
    void convert(const uint8_t* codes, size_t pixels, glm::vec4* out) const
    {
        convert_with(codes, pixels, out, [&](uint8_t code) { return colour8_[code]; },
                     [&](uint8_t code) { return alpha8_[code]; });
    }

    void convert(const float* values, size_t pixels, glm::vec4* out) const
    {
        convert_with(values, pixels, out, [&](float v) { return decode(v); }, [](float v) { return v; });
    }

private:
    template <typename T, typename Colour, typename Alpha>
    void convert_with(const T* values, size_t pixels, glm::vec4* out, Colour colour, Alpha alpha) const
    {
        const size_t n = size_t(format_.channels);
        for (size_t i = 0; i < pixels; ++i) {
            const T* p = values + i * n;
            switch (n) {
            case 1: {
                const float g = colour(p[0]);
                out[i] = glm::vec4(g, g, g, 1.0f);
                break;
            }
            case 2: {  // grey + alpha
                const float g = colour(p[0]);
                out[i] = glm::vec4(g, g, g, alpha(p[1]));
                break;
            }
            case 3: out[i] = glm::vec4(colour(p[0]), colour(p[1]), colour(p[2]), 1.0f); break;
            default: out[i] = glm::vec4(colour(p[0]), colour(p[1]), colour(p[2]), alpha(p[3])); break;  // alpha as stored
            }
        }
    }

    float decode(float v) const
    {
        if (!decode_) return v;
        if (!table_.empty()) {
            const long code = std::lround(std::clamp(v, 0.0f, 1.0f) * float(format_.integer_levels));
            return table_[size_t(code)];
        }
        return float(srgb_to_linear(double(v)));
    }

    PixelFormat format_;
    bool decode_;
    std::vector<float> table_;
    float colour8_[256], alpha8_[256]; // 8-bit code -> colour value (decoded when asked), alpha value
};

// Opens, validates and decodes the first subimage into the host's destination, a band of rows at a time
// (a few MB of float values), so no whole-image float copy is ever held. Files with more than four channels
// (EXR with extra layers, say) contribute their first four: OIIO orders R, G, B, A first. raw: no colour
// decode at all (read_image_raw); else `space` (TF_OIIO_*) decides as image_io.h says, and a NaN or ±Inf
// texel is refused once every band is read (texture/finite.h: the count and the first in the message).
void read_rgba(const std::string& path, int max_dimension, bool raw, int space, const tf_oiio_call& call) {
    StderrCapture capture;
    auto in = open_checked(path, max_dimension, capture);
    const OIIO::ImageSpec spec = in->spec();
    const std::string format_name = in->format_name();
    auto fail = [&](const std::string& what) {
        in->geterror();  // drain
        in->close();
        in->geterror();
        capture.finish();  // libpng's own line said the same as OIIO's message
        throw Error(path + ": " + what);
    };

    PixelFormat format;
    format.width = spec.width;
    format.height = spec.height;
    format.channels = std::min(spec.nchannels, 4);
    format.srgb = stored_as_srgb(spec, format_name);
    if (spec.format.basetype == OIIO::TypeDesc::UINT8) format.integer_levels = 255;
    if (spec.format.basetype == OIIO::TypeDesc::UINT16) format.integer_levels = 65535;
    const bool decode = !raw && (space == TF_OIIO_SRGB || (space == TF_OIIO_AUTOMATIC && format.srgb));
    const RgbaConverter converter(format, decode);

    glm::vec4* texels = nullptr;
    const size_t row_values = size_t(format.width) * size_t(format.channels);
    const int band_rows = int(std::clamp<size_t>((size_t(1) << 20) / row_values, 1, size_t(format.height)));
    const bool bytes = format.integer_levels == 255;
    std::vector<float> band;
    std::vector<uint8_t> byte_band;
    NonFiniteTexels non_finite;
    try {
        texels = destination_texels(call, format.width, format.height);
        if (bytes)
            byte_band.resize(size_t(band_rows) * row_values);
        else
            band.resize(size_t(band_rows) * row_values);
    } catch (const std::bad_alloc&) {
        fail("out of memory for " + std::to_string(format.width) + "x" + std::to_string(format.height) + " pixels");
    }

    for (int y0 = 0; y0 < format.height; y0 += band_rows) {
        const int y1 = std::min(format.height, y0 + band_rows);
        bool ok = false;
        std::string oiio_error;
        try {
            ok = bytes ? in->read_scanlines(0, 0, y0, y1, 0, 0, format.channels, OIIO::TypeDesc::UINT8, byte_band.data())
                       : in->read_scanlines(0, 0, y0, y1, 0, 0, format.channels, OIIO::TypeDesc::FLOAT, band.data());
        } catch (const std::exception& e) {
            // Some format plugins report corrupt data by throwing; the contract is a tf::Error.
            oiio_error = e.what();
        }
        if (!ok) {
            if (oiio_error.empty()) oiio_error = in->geterror();
            fail("cannot read pixels (corrupt or truncated file?): " + oiio_message(oiio_error));
        }
        // OIIO 2.4 returns success for a JPEG cut short ("Premature end of JPEG file") or a TIFF strip that
        // ends early, with the missing pixels zero, and only leaves the decoder's complaint in the error
        // queue: any message there means pixels were not read.
        if (const std::string pending = in->geterror(); !pending.empty())
            fail("incomplete pixel data (truncated or corrupt file): " + first_line(pending));
        const size_t pixels = size_t(y1 - y0) * size_t(format.width);
        glm::vec4* out = texels + size_t(y0) * size_t(format.width);
        bytes ? converter.convert(byte_band.data(), pixels, out) : converter.convert(band.data(), pixels, out);
        if (!raw && !bytes) // 8-bit codes are finite; float, half and 16-bit bands are counted while in cache
            non_finite.scan(out, size_t(y0) * size_t(format.width), pixels, format.width);
    }
    if (non_finite.count) { // a texture load: refused, naming the first bad texel (texture/finite.h)
        in->close();
        in->geterror();
        capture.finish();
        check_finite_texels(non_finite, path, format.width, format.height);
    }
    if (!in->close()) fail("cannot read: " + oiio_message(in->geterror()));
    // A successful read can still have warnings of the library's own (libpng: "iCCP: known incorrect sRGB
    // profile"): pass them on, named, one line each.
    const std::string printed = capture.finish();
    for (size_t start = 0; start < printed.size();) {
        const size_t end = std::min(printed.find('\n', start), printed.size());
        if (end > start) std::fprintf(stderr, "texfilter: %s: warning: %s\n", path.c_str(),
                                      printed.substr(start, std::min<size_t>(end - start, 200)).c_str());
        start = end + 1;
    }
}

uint8_t encode_png_channel(float linear, bool is_alpha) {
    double v = std::isnan(linear) ? 0.0 : std::clamp(double(linear), 0.0, 1.0);
    if (!is_alpha) v = linear_to_srgb(v);
    return uint8_t(std::lround(v * 255.0));
}

tf_oiio_header read_header(const std::string& path, int max_dimension) {
    StderrCapture capture;
    auto in = open_checked(path, max_dimension, capture);
    const tf_oiio_header header{in->spec().width, in->spec().height, std::min(in->spec().nchannels, 4)};
    in->close();
    in->geterror();
    capture.finish();
    return header;
}

// write_image's OIIO half: the host has checked the path, the format and the image, created the temporary
// file `fd` is open on, and renames it. OIIO writes through an I/O proxy on that descriptor: it never opens
// a path itself, so nothing put in the temporary's place can be written.
void write_rgba(const std::string& path, int fd, bool png, int width, int height, const glm::vec4* texels) {
    const size_t count = size_t(width) * size_t(height);
    // Created by format name, because the temporary file's extension is not .png/.exr.
    auto out = OIIO::ImageOutput::create(png ? "png" : "openexr");
    if (!out) throw Error(path + ": cannot create a writer: " + oiio_message(OIIO::geterror()));

    OIIO::ImageSpec spec(width, height, 4, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::HALF);
    spec.channelnames = {"R", "G", "B", "A"};
    spec.alpha_channel = 3;
    std::vector<uint8_t> bytes;
    const void* data = texels;
    OIIO::TypeDesc data_type = OIIO::TypeDesc::FLOAT;
    if (png) {
        spec.attribute("oiio:ColorSpace", "sRGB");
        spec.attribute("oiio:UnassociatedAlpha", 1);  // our alpha is straight; don't let OIIO divide
        bytes.resize(count * 4);
        for (size_t i = 0; i < count; ++i)
            for (int c = 0; c < 4; ++c) bytes[i * 4 + size_t(c)] = encode_png_channel(texels[i][c], c == 3);
        data = bytes.data();
        data_type = OIIO::TypeDesc::UINT8;
    } else {
        spec.attribute("oiio:ColorSpace", "Linear");
        spec.attribute("compression", "zip");
        spec.attribute("DateTime", "");  // an empty value keeps OIIO from stamping the time: same image, same bytes
    }

    const int own = dup(fd);  // fclose closes this copy; the host closes fd
    FILE* file = own >= 0 ? fdopen(own, "wb") : nullptr;
    if (!file) {
        if (own >= 0) close(own);
        throw Error(path + ": cannot write the file (" + std::strerror(errno) + ")");
    }
    OIIO::Filesystem::IOFile proxy(file, OIIO::Filesystem::IOProxy::Write);
    bool ok = false;
    std::string oiio_error;
    try {
        out->set_ioproxy(&proxy);
        ok = out->open(path, spec);
        if (ok) ok = out->write_image(data_type, data);
        if (ok) ok = out->close();
    } catch (const std::exception& e) {
        oiio_error = e.what();
        ok = false;
    }
    if (!ok && oiio_error.empty()) oiio_error = out->geterror();
    out.reset();
    const bool flushed = std::fflush(file) == 0 && !std::ferror(file);
    const int flush_error = errno;
    std::fclose(file);
    if (!ok) throw Error(path + ": cannot write: " + oiio_message(oiio_error));
    if (!flushed) throw Error(path + ": cannot write the file (" + std::strerror(flush_error) + ")");
}

OIIO::TextureOpt texture_options(const tf_oiio_texture_job& job) {
    OIIO::TextureOpt options; // everything else as OIIO's defaults: anisotropic 32, conservative_filter on
    switch (job.wrap) {
    case TF_OIIO_WRAP_PERIODIC: options.swrap = OIIO::TextureOpt::WrapPeriodic; break;
    case TF_OIIO_WRAP_CLAMP: options.swrap = OIIO::TextureOpt::WrapClamp; break;
    case TF_OIIO_WRAP_MIRROR: options.swrap = OIIO::TextureOpt::WrapMirror; break;
    default: throw Error("texture lookups: unknown wrap mode " + std::to_string(job.wrap));
    }
    options.twrap = options.swrap;
    switch (job.mip) {
    case TF_OIIO_MIP_TRILINEAR: options.mipmode = OIIO::TextureOpt::MipModeTrilinear; break;
    case TF_OIIO_MIP_ANISO: options.mipmode = OIIO::TextureOpt::MipModeAniso; break;
    default: throw Error("texture lookups: unknown MIP mode " + std::to_string(job.mip));
    }
    switch (job.interp) {
    case TF_OIIO_INTERP_CLOSEST: options.interpmode = OIIO::TextureOpt::InterpClosest; break;
    case TF_OIIO_INTERP_BILINEAR: options.interpmode = OIIO::TextureOpt::InterpBilinear; break;
    case TF_OIIO_INTERP_BICUBIC: options.interpmode = OIIO::TextureOpt::InterpBicubic; break;
    case TF_OIIO_INTERP_SMARTBICUBIC: options.interpmode = OIIO::TextureOpt::InterpSmartBicubic; break;
    default: throw Error("texture lookups: unknown interpolation " + std::to_string(job.interp));
    }
    return options;
}

struct TextureSystemDeleter {
    void operator()(OIIO::TextureSystem* system) const { OIIO::TextureSystem::destroy(system); }
};

// The TextureSystem reads files only: level 0 becomes a tiled, MIP-mapped file as `maketx` makes it (its
// defaults: box-filtered levels, each half the one above, rounded down; float texels kept as float; 64x64 tiles;
// no compression)
// in the host's private directory, and every lookup is one TextureSystem::texture call on it, spread over OIIO's
// thread pool. The TextureSystem is private to the call and destroyed (its file closed) before it returns.
void texture_lookups(const tf_oiio_texture_job& job) {
    if (!job.directory || job.width <= 0 || job.height <= 0 || !job.rgba || job.count < 0 ||
        (job.count > 0 && (!job.lookups || !job.colors)))
        throw Error("texture lookups: an empty or inconsistent job");
    OIIO::TextureOpt options = texture_options(job);
    const std::string file = std::string(job.directory) + "/texture.tx";

    const OIIO::ImageSpec spec(job.width, job.height, 4, OIIO::TypeDesc::FLOAT);
    const OIIO::ImageBuf level0(spec, const_cast<float*>(job.rgba)); // read only: make_texture copies
    // maketx's defaults but for the file's compression: zip is lossless, so it changes no texel, and it took
    // 12 of the 14.6 s a 4096² texture needed (2.1 s without, the module's load included).
    OIIO::ImageSpec config;
    config.attribute("compression", "none");
    std::ostringstream log;
    if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, level0, file, config, &log))
        throw Error("OpenImageIO's make_texture failed: " + oiio_message(OIIO::geterror()));

    const std::unique_ptr<OIIO::TextureSystem, TextureSystemDeleter> system(OIIO::TextureSystem::create(false));
    OIIO::TextureSystem::TextureHandle* handle = system->get_texture_handle(OIIO::ustring(file));
    if (!handle) throw Error("OpenImageIO's TextureSystem cannot open its texture: " + oiio_message(system->geterror()));
    std::atomic<bool> failed{false};
    OIIO::parallel_for(int64_t(0), job.count, [&](int64_t i) {
        OIIO::TextureOpt own = options; // texture() may change its options (the stochastic modes)
        const double* l = job.lookups + 6 * i;
        if (!system->texture(handle, system->get_perthread_info(), own, float(l[0]), float(l[1]), float(l[2]),
                             float(l[3]), float(l[4]), float(l[5]), 4, job.colors + 4 * i))
            failed = true;
    });
    if (failed) throw Error("OpenImageIO's TextureSystem failed: " + oiio_message(system->geterror()));
}

// Runs one entry's work: 1, or 0 with the error handed to the host (nothing is thrown across the table).
template <typename Work>
int guarded(const tf_oiio_call* call, Work work) {
    const char* message = nullptr;
    std::string text;
    try {
        work();
        return 1;
    } catch (const HostGaveUp&) {
        return 0;
    } catch (const std::bad_alloc&) {
        message = "out of memory in the image I/O module";
    } catch (const std::exception& e) {
        text = e.what();
        message = text.c_str();
    } catch (...) {
        message = "unknown error in the image I/O module";
    }
    if (call && call->fail) call->fail(call->context, message);
    return 0;
}

int api_read_header(const char* path, int max_dimension, tf_oiio_header* header, const tf_oiio_call* call) {
    return guarded(call, [&] { *header = read_header(path, max_dimension); });
}

int api_read_rgba(const char* path, int max_dimension, int raw, int space, const tf_oiio_call* call) {
    return guarded(call, [&] { read_rgba(path, max_dimension, raw != 0, space, *call); });
}

int api_write_rgba(const char* path, int fd, int png, int width, int height, const float* rgba,
                   const tf_oiio_call* call) {
    return guarded(call, [&] {
        write_rgba(path, fd, png != 0, width, height, reinterpret_cast<const glm::vec4*>(rgba));
    });
}

int api_texture_lookups(const tf_oiio_texture_job* job, const tf_oiio_call* call) {
    return guarded(call, [&] { texture_lookups(*job); });
}

const tf_oiio_api api = {TF_OIIO_ABI_VERSION, api_read_header, api_read_rgba, api_write_rgba, api_texture_lookups};

} // namespace
} // namespace tf

extern "C" __attribute__((visibility("default"))) const tf_oiio_api* tf_oiio_api_v1(void) { return &tf::api; }
