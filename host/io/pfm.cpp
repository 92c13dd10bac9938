#include "io/pfm.h"
#include "texture/error.h"
#include "io/output_path.h"
#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cmath>
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

Image read_pfm(std::istream& in, const std::string& path)
{
    // The magic by its two bytes, not as a word: a big file without whitespace must not become one string.
    char magic[2] = {};
    in.read(magic, 2);
    const bool colour = in && magic[0] == 'P' && magic[1] == 'F' && std::isspace(in.peek());
    long long width = 0, height = 0;
    double scale = 0;
    in >> width >> height >> scale;
    if (!in || !colour)
        throw Error(path + ": not a colour PFM file (expected a \"PF\" header)");
    if (width < 1 || height < 1 || width > max_side || height > max_side || !std::isfinite(scale) || scale == 0)
        throw Error(path + ": bad PFM header (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    in.get(); // the single whitespace byte that ends the header
    // The length first: a tiny file must not make us allocate what its header claims.
    std::streamoff start = in.tellg();
    in.seekg(0, std::ios::end);
    std::streamoff expected = start + std::streamoff(width * height * 12);
    if (in.tellg() != expected)
        throw Error(path + ": " + std::to_string(in.tellg() - start) + " bytes of pixels, a " + std::to_string(width) +
                    "x" + std::to_string(height) + " PFM has " + std::to_string(width * height * 12));
    in.seekg(start);
    bool little = scale < 0;
    Image image = make_image(int(width), int(height));
    std::vector<uint32_t> row(size_t(width) * 3);
    for (long long y = height - 1; y >= 0; --y) {
        if (!in.read(reinterpret_cast<char*>(row.data()), std::streamsize(row.size() * 4)))
            throw Error(path + ": truncated (" + std::to_string(width) + "x" + std::to_string(height) + " expected)");
        for (long long x = 0; x < width; ++x) {
            glm::vec4& t = image.texels[size_t(y) * size_t(width) + size_t(x)];
            for (int c = 0; c < 3; ++c) {
                uint32_t bits = row[size_t(x) * 3 + size_t(c)];
                if (little != (std::endian::native == std::endian::little))
                    bits = swap_bytes(bits);
                t[c] = std::bit_cast<float>(bits);
            }
            t.a = 1.0f;
        }
    }
    return image;
}

} // namespace tf
