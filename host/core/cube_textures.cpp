#include "core/cube_textures.h"
#include "core/hash.h"
#include "core/procedural.h"
#include "texture/error.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <cstdint>

namespace tf {

namespace {

constexpr int max_size = 16384; // as make_procedural

// Opposite faces complementary hues: +X red, -X cyan, +Y green, -Y magenta, +Z blue, -Z yellow.
const glm::vec4 face_hue[cube_face_count] = {{1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 1.0f, 1.0f},
                                             {0.0f, 1.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 1.0f, 1.0f},
                                             {0.0f, 0.0f, 1.0f, 1.0f}, {1.0f, 1.0f, 0.0f, 1.0f}};

// Texel (i, j)'s centre in face coordinates.
double centre(int i, int size) { return (i + 0.5) / size; }

glm::vec4 label_texel(int face, int i, int j, int size)
{
    const glm::vec4 white(1.0f), black(0.0f, 0.0f, 0.0f, 1.0f);
    const double s = centre(i, size), t = centre(j, size);
    if (j * 16 < size) // the bar along t = 0: at least one row
        return white;
    if ((s - 0.25) * (s - 0.25) + (t - 0.25) * (t - 0.25) < 1.0 / 144.0) // the dot, radius 1/12
        return black;
    if (t >= 0.70 && t < 0.80) // face + 1 squares, 0.06 wide every 0.1 from s = 0.3
        for (int k = 0; k <= face; ++k)
            if (s >= 0.30 + 0.1 * k && s < 0.36 + 0.1 * k)
                return white;
    const int cx = i * 8 / size, cy = j * 8 / size;
    const glm::vec4 hue = face_hue[face];
    glm::vec4 texel = (cx + cy) % 2 == 0 ? 0.8f * hue + 0.1f : 0.25f * hue + 0.02f;
    texel.a = 1.0f;
    return texel;
}

// mix32 is a bijection of 32-bit words and the key is injective for sides up to 16384 (6 * 2^28 keys),
// so every texel of the cube gets its own 32 bits: 11 for red, 11 for green, 10 for blue, each exact in
// float.
glm::vec4 hash_texel(int face, int i, int j)
{
    const uint32_t key = (uint32_t(face) * uint32_t(max_size) + uint32_t(j)) * uint32_t(max_size) + uint32_t(i);
    const uint32_t h = mix32(key);
    return {float(h >> 21) / 2048.0f, float((h >> 10) & 2047u) / 2048.0f, float(h & 1023u) / 1024.0f, 1.0f};
}

glm::vec4 smooth_texel(int face, int i, int j, int size)
{
    const glm::dvec3 d = glm::normalize(cube_face_direction(face, centre(i, size), centre(j, size)));
    return {float(0.5 * (d.x + 1.0)), float(0.5 * (d.y + 1.0)), float(0.5 * (d.z + 1.0)), 1.0f};
}

template <typename TexelOf>
CubeMap cube_of(int size, TexelOf texel_of)
{
    std::array<Image, cube_face_count> faces;
    for (int f = 0; f < cube_face_count; ++f) {
        faces[f] = make_image(size, size);
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i)
                faces[f].at(i, j) = texel_of(f, i, j);
    }
    return build_cube_map(std::move(faces));
}

Image tinted(const Image& image, glm::vec4 tint)
{
    Image out = image;
    for (glm::vec4& texel : out.texels)
        texel *= tint;
    return out;
}

CubeMap tinted_pattern(const std::string& name, int size)
{
    const MipChain pattern = make_procedural(name, size);
    if (name == "mipcolors") { // flat colours a level, not a downsample: keep them, tinted
        CubeMap cube;
        for (int f = 0; f < cube_face_count; ++f)
            for (const Image& level : pattern.levels)
                cube.faces[f].levels.push_back(tinted(level, cube_face_tint(f)));
        return cube;
    }
    std::array<Image, cube_face_count> faces;
    for (int f = 0; f < cube_face_count; ++f)
        faces[f] = tinted(pattern.levels[0], cube_face_tint(f));
    return build_cube_map(std::move(faces));
}

std::string name_list()
{
    std::string list;
    for (const std::string& name : procedural_cube_names())
        list += (list.empty() ? "" : ", ") + name;
    return list;
}

} // namespace

const std::vector<std::string>& procedural_cube_names()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all = {"cube-labels", "cube-hash", "cube-smooth"};
        for (const std::string& name : procedural_names())
            all.push_back(name);
        return all;
    }();
    return names;
}

bool is_procedural_cube(const std::string& name)
{
    for (const std::string& n : procedural_cube_names())
        if (n == name)
            return true;
    return false;
}

glm::vec4 cube_face_tint(int face)
{
    // The face's hue mixed 3:1 with white: every face differs, none darkens a pattern much.
    const glm::vec4 tint = 0.25f * face_hue[face] + 0.75f;
    return {tint.r, tint.g, tint.b, 1.0f};
}

CubeMap make_procedural_cube(const std::string& name, int size)
{
    if (!is_procedural_cube(name))
        throw Error("unknown procedural cube texture '" + name + "' (expected one of: " + name_list() + ")");
    if (size < 1 || size > max_size)
        throw Error("procedural cube texture " + name + ": face size " + std::to_string(size) +
                    " out of range [1, " + std::to_string(max_size) + "]");
    if (name == "cube-labels")
        return cube_of(size, [size](int f, int i, int j) { return label_texel(f, i, j, size); });
    if (name == "cube-hash")
        return cube_of(size, [](int f, int i, int j) { return hash_texel(f, i, j); });
    if (name == "cube-smooth")
        return cube_of(size, [size](int f, int i, int j) { return smooth_texel(f, i, j, size); });
    return tinted_pattern(name, size);
}

CrossCell cross_cell(int face)
{
    static const CrossCell cells[cube_face_count] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
    if (face < 0 || face >= cube_face_count)
        throw Error("cube face " + std::to_string(face) + " out of range [0, 5]");
    return cells[face];
}

CubeMap cube_from_cross(const Image& cross, const std::string& name)
{
    const int w = cross.width, h = cross.height;
    if (w <= 0 || h <= 0 || w % 4 != 0 || h % 3 != 0 || w / 4 != h / 3)
        throw Error("cube map " + name + ": " + std::to_string(w) + "x" + std::to_string(h) +
                    " is not a horizontal cross (4:3, faces of width / 4 = height / 3 texels a side)");
    if (cross.texels.size() != size_t(w) * size_t(h))
        throw Error("cube map " + name + ": the image holds " + std::to_string(cross.texels.size()) +
                    " texels, not " + std::to_string(w) + "x" + std::to_string(h));
    const int size = w / 4;
    std::array<Image, cube_face_count> faces;
    for (int f = 0; f < cube_face_count; ++f) {
        const CrossCell cell = cross_cell(f);
        faces[f] = make_image(size, size);
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i)
                faces[f].at(i, j) = cross.at(cell.column * size + i, cell.row * size + j);
    }
    return build_cube_map(std::move(faces));
}

} // namespace tf
