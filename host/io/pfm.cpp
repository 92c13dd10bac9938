#include "io/pfm.h"
#include "io/text_file.h"
#include "texture/error.h"
#include "io/output_path.h"
#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace tf {

namespace {

const int max_side = 1 << 15;

uint32_t swap_bytes(uint32_t x) { return (x >> 24) | ((x >> 8) & 0xff00u) | ((x << 8) & 0xff0000u) | (x << 24); }

} // namespace

bool is_pfm_path(const std::string& path)
{
    if (path.size() < 4)
        return false;
    std::string ext = path.substr(path.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".pfm";
}

void write_pfm(const std::string& path, const Image& image)
{
    if (image.width <= 0 || image.height <= 0 || image.texels.size() != size_t(image.width) * size_t(image.height))
        throw Error(path + ": cannot write an empty or inconsistent " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " image");
    std::string header = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    std::string data(header.size() + size_t(image.width) * size_t(image.height) * 12, '\0');
    std::memcpy(data.data(), header.data(), header.size());
    char* out = data.data() + header.size();
    for (int y = image.height - 1; y >= 0; --y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4& t = image.texels[size_t(y) * size_t(image.width) + size_t(x)];
            for (int c = 0; c < 3; ++c) {
                uint32_t bits = std::bit_cast<uint32_t>(t[c]);
                if constexpr (std::endian::native == std::endian::big)
                    bits = swap_bytes(bits);
                std::memcpy(out, &bits, 4);
                out += 4;
            }
        }
    write_file_atomic(path, data);
}

Image read_pfm(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error(path + ": cannot open (" + std::strerror(errno) + ")");
    return read_pfm(in, path);
}

bool is_pfm_file(const std::string& path)
{
    refuse_special_file(path, "an image file"); // before anything opens it: every image read starts here
    std::ifstream in(path, std::ios::binary);
    char magic[3] = {};
    return in.read(magic, 3) && magic[0] == 'P' && magic[1] == 'F' && std::isspace(static_cast<unsigned char>(magic[2]));
}

PfmHeader read_pfm_header(std::istream& in, const std::string& path, int max_dimension)
{
    // The magic by its two bytes, not as a word: a big file without whitespace must not become one string.
    char magic[2] = {};
    in.read(magic, 2);
    const bool colour = in && magic[0] == 'P' && magic[1] == 'F' && std::isspace(in.peek());
    if (!colour)
        throw Error(path + ": not a colour PFM file (expected a \"PF\" header)");
    // Each field as a word of at most a few dozen characters, quoted as written: "nan" must be read to be
    // refused, and a side past any integer must not wrap.
    auto word = [&] {
        std::string text;
        in >> std::ws;
        for (int c = in.peek(); c != EOF && !std::isspace(c) && text.size() <= 24; c = in.peek())
            text += char(in.get());
        return text.size() > 24 ? text.substr(0, 24) + "..." : text;
    };
    const std::string width_text = word(), height_text = word(), scale_text = word();
    auto side = [](const std::string& text) {
        char* end = nullptr;
        const long long value = std::strtoll(text.c_str(), &end, 10);
        const bool digits = !text.empty() && end == text.c_str() + text.size() && std::isdigit(text[0]);
        return !digits ? -1LL : value; // strtoll saturates: an absurd side stays absurd
    };
    const long long width = side(width_text), height = side(height_text);
    const std::string size = width_text + "x" + height_text;
    if (width < 1 || height < 1)
        throw Error(path + ": bad PFM header: size '" + size + "' (expected two positive integers)");
    if (width > max_dimension || height > max_dimension)
        throw Error(path + ": " + size + " exceeds the maximum texture size " + std::to_string(max_dimension));
    char* end = nullptr;
    const double scale = std::strtod(scale_text.c_str(), &end);
    if (scale_text.empty() || end != scale_text.c_str() + scale_text.size() || !std::isfinite(scale) || scale == 0)
        throw Error(path + ": bad PFM header: scale '" + scale_text +
                    "' (a finite number other than 0: its sign gives the byte order)");
    if (!std::isspace(in.get())) // the single whitespace byte that ends the header
        throw Error(path + ": bad PFM header: no whitespace after the scale");
    // The length first: a tiny file must not make us allocate what its header claims.
    PfmHeader header{int(width), int(height), scale < 0, in.tellg()};
    in.seekg(0, std::ios::end);
    const std::streamoff have = in.tellg() - header.pixels, need = std::streamoff(width * height * 12);
    if (have < need)
        throw Error(path + ": truncated: " + std::to_string(have) + " bytes of pixels, a " + size + " PFM has " +
                    std::to_string(need));
    if (have > need)
        throw Error(path + ": " + std::to_string(have - need) + " bytes after the pixels of a " + size +
                    " PFM (not a PFM file, or a corrupt one)");
    in.seekg(header.pixels);
    return header;
}

void read_pfm_pixels(std::istream& in, const PfmHeader& header, const std::string& path, glm::vec4* texels,
                     NonFiniteTexels* non_finite)
{
    const size_t width = size_t(header.width);
    std::vector<uint32_t> row(width * 3);
    for (long long y = header.height - 1; y >= 0; --y) {
        if (!in.read(reinterpret_cast<char*>(row.data()), std::streamsize(row.size() * 4)))
            throw Error(path + ": truncated (" + std::to_string(header.width) + "x" + std::to_string(header.height) +
                        " expected)");
        glm::vec4* out = texels + size_t(y) * width;
        for (size_t x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c) {
                uint32_t bits = row[x * 3 + size_t(c)];
                if (header.little != (std::endian::native == std::endian::little))
                    bits = swap_bytes(bits);
                out[x][c] = std::bit_cast<float>(bits);
            }
            out[x].a = 1.0f;
        }
        if (non_finite)
            non_finite->scan(out, size_t(y) * width, width, header.width);
    }
}

Image read_pfm(std::istream& in, const std::string& path)
{
    const PfmHeader header = read_pfm_header(in, path, max_side);
    Image image = make_image(header.width, header.height);
    read_pfm_pixels(in, header, path, image.texels.data(), nullptr);
    return image;
}

} // namespace tf
