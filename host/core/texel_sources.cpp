#include "core/texel_sources.h"

#include "core/hash.h"
#include "harness/config.h"
#include "texture/error.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace tf {

namespace {

constexpr int kPage = HARNESS_VIRTUAL_PAGE;
constexpr int kGrid = HARNESS_ATLAS_GRID;

int next_power_of_two(int n)
{
    int p = 1;
    while (p < n)
        p *= 2;
    return p;
}

int level_side(int side, int level) { return std::max(1, side >> level); }
int pages(int side) { return (side + kPage - 1) / kPage; }

// Pages of every level of a width x height chain, and the physical texture's pages a row.
int total_pages(int width, int height)
{
    int n = 0;
    for (int l = 0; l < mip_level_count(width, height); ++l)
        n += pages(level_side(width, l)) * pages(level_side(height, l));
    return n;
}
int pages_a_row(int total) { return std::max(1, int(std::ceil(std::sqrt(double(total))))); }

int32_t word(const SourceBinding& b, size_t i)
{
    if (i >= b.words.size())
        throw Error("texel source: word " + std::to_string(i) + " of " + std::to_string(b.words.size()));
    return b.words[i];
}

void check_level(const SourceBinding& b, int level)
{
    if (level < 0 || level >= source_levels(b))
        throw Error("texel source: level " + std::to_string(level) + " of " + std::to_string(source_levels(b)));
}

} // namespace

glm::vec4 atlas_cell_colour(int cell)
{
    const glm::vec4 colours[] = {{0.9f, 0.1f, 0.1f, 1.0f}, {0.1f, 0.8f, 0.2f, 1.0f}, {0.1f, 0.2f, 0.9f, 1.0f},
                                 {0.9f, 0.8f, 0.1f, 1.0f}};
    return colours[size_t(cell) % std::size(colours)];
}
glm::vec4 atlas_padding_colour() { return {1.0f, 0.0f, 1.0f, 1.0f}; }
glm::vec4 virtual_padding_colour() { return {0.0f, 1.0f, 1.0f, 1.0f}; }

glm::ivec2 source_image_size(Resource kind, int width, int height)
{
    if (width < 1 || height < 1)
        throw Error("texel source: empty texture");
    if (kind == Resource::atlas) {
        const long long side = (long long)kGrid * next_power_of_two(std::max(width, height));
        return glm::ivec2(int(std::min<long long>(side, 1LL << 30)));
    }
    if (kind == Resource::virtual_texture) {
        const int total = total_pages(width, height), row = pages_a_row(total);
        return {row * kPage, (total + row - 1) / row * kPage};
    }
    throw Error("texel source: --resource " + to_string(kind) + " is not one");
}

void check_source_size(Resource kind, int width, int height, int max_side)
{
    const glm::ivec2 size = source_image_size(kind, width, height);
    if (size.x > max_side || size.y > max_side)
        throw Error("--resource " + to_string(kind) + ": a " + std::to_string(width) + "x" + std::to_string(height) +
                    " texture needs " + (kind == Resource::atlas ? "an atlas" : "a physical texture") + " of " +
                    std::to_string(size.x) + "x" + std::to_string(size.y) + " texels, more than " +
                    std::to_string(max_side) + " a side (use a texture of at most " +
                    (kind == Resource::atlas ? std::to_string(max_side / kGrid) + " texels a side"
                                             : std::string("about three quarters of that a side")) +
                    ")");
}

uint64_t source_host_bytes(Resource kind, int width, int height, bool reference, bool device_in_host_memory)
{
    auto chain_bytes = [](int w, int h) {
        uint64_t texels = 0;
        for (int l = 0; l < mip_level_count(w, h); ++l)
            texels += uint64_t(level_side(w, l)) * uint64_t(level_side(h, l));
        return texels * sizeof(glm::vec4);
    };
    const glm::ivec2 size = source_image_size(kind, width, height);
    const uint64_t level0 = uint64_t(size.x) * uint64_t(size.y) * sizeof(glm::vec4);
    const uint64_t image = kind == Resource::atlas ? chain_bytes(size.x, size.y)
                                                   : level0 + uint64_t(total_pages(width, height)) * sizeof(int32_t);
    if (reference)
        return image + chain_bytes(width, height);
    return image + level0 + (device_in_host_memory ? image : 0);
}

SourceBinding make_atlas(const MipChain& texture)
{
    const Image& base = texture.levels.at(0);
    const int w = base.width, h = base.height, cell = next_power_of_two(std::max(w, h));
    check_source_size(Resource::atlas, w, h, max_source_side);
    const int side = kGrid * cell;
    const glm::ivec2 origin(HARNESS_ATLAS_CELL_X * cell, HARNESS_ATLAS_CELL_Y * cell);
    SourceBinding b;
    b.kind = Resource::atlas;
    b.words = {origin.x, origin.y, w, h, int(texture.levels.size())};
    static_assert(HARNESS_ATLAS_WORDS == 5 && HARNESS_ATLAS_LEVELS == 4, "config.h's atlas words");
    const int levels = mip_level_count(side, side);
    for (int l = 0; l < levels; ++l) {
        const int s = side >> l, c = cell >> l; // c: a cell's side at this level (0 once cells are sub-texel)
        Image level = l == 0 ? make_image(s, s) : downsample(b.image.levels.back());
        if (c >= 1) {
            for (int y = 0; y < s; ++y)
                for (int x = 0; x < s; ++x) {
                    const int cx = x / c, cy = y / c;
                    if (cx != HARNESS_ATLAS_CELL_X || cy != HARNESS_ATLAS_CELL_Y)
                        level.at(x, y) = atlas_cell_colour(cy * kGrid + cx);
                    else if (l < int(texture.levels.size()))
                        level.at(x, y) = atlas_padding_colour();
                }
            if (l < int(texture.levels.size())) {
                const Image& tile = texture.levels[size_t(l)];
                for (int y = 0; y < tile.height; ++y)
                    for (int x = 0; x < tile.width; ++x)
                        level.at((origin.x >> l) + x, (origin.y >> l) + y) = tile.at(x, y);
            }
        }
        b.image.levels.push_back(std::move(level));
    }
    return b;
}

SourceBinding make_virtual_texture(const MipChain& texture)
{
    const Image& base = texture.levels.at(0);
    check_source_size(Resource::virtual_texture, base.width, base.height, max_source_side);
    const int levels = int(texture.levels.size());
    const int total = total_pages(base.width, base.height), row = pages_a_row(total);
    const int rows = (total + row - 1) / row;
    SourceBinding b;
    b.kind = Resource::virtual_texture;
    // Header: the level count, then each level's words; the page entries after them.
    b.words.assign(size_t(1 + HARNESS_VIRTUAL_LEVEL_WORDS * levels), 0);
    b.words[HARNESS_VIRTUAL_LEVELS] = levels;
    // Slot k of the physical texture is page (k % row, k / row); page n of the texture goes to slot order[n],
    // a Fisher-Yates shuffle driven by the project's hash (deterministic everywhere).
    std::vector<int> order(size_t(row) * size_t(rows));
    std::iota(order.begin(), order.end(), 0);
    for (size_t i = order.size(); i > 1; --i)
        std::swap(order[i - 1], order[mix32(uint32_t(i) * 0x9e3779b9u) % uint32_t(i)]);
    b.image.levels.push_back(make_image(row * kPage, rows * kPage, virtual_padding_colour()));
    Image& physical = b.image.levels[0];
    int n = 0;
    for (int l = 0; l < levels; ++l) {
        const Image& level = texture.levels[size_t(l)];
        const int px = pages(level.width), py = pages(level.height);
        int32_t* header = &b.words[size_t(1 + HARNESS_VIRTUAL_LEVEL_WORDS * l)];
        header[HARNESS_VIRTUAL_WIDTH] = level.width;
        header[HARNESS_VIRTUAL_HEIGHT] = level.height;
        header[HARNESS_VIRTUAL_PAGES_X] = px;
        header[HARNESS_VIRTUAL_FIRST_PAGE] = int32_t(b.words.size());
        for (int j = 0; j < py; ++j)
            for (int i = 0; i < px; ++i, ++n) {
                const int slot = order[size_t(n)], sx = slot % row, sy = slot / row;
                b.words.push_back(sx | (sy << 16));
                for (int y = 0; y < kPage && j * kPage + y < level.height; ++y)
                    for (int x = 0; x < kPage && i * kPage + x < level.width; ++x)
                        physical.at(sx * kPage + x, sy * kPage + y) = level.at(i * kPage + x, j * kPage + y);
            }
    }
    return b;
}

SourceBinding make_source_binding(const MipChain& texture, Resource kind)
{
    if (kind == Resource::atlas)
        return make_atlas(texture);
    if (kind == Resource::virtual_texture)
        return make_virtual_texture(texture);
    throw Error("texel source: --resource " + to_string(kind) + " is not one");
}

int source_levels(const SourceBinding& b)
{
    return word(b, b.kind == Resource::atlas ? HARNESS_ATLAS_LEVELS : HARNESS_VIRTUAL_LEVELS);
}

glm::ivec2 source_size(const SourceBinding& b, int level)
{
    check_level(b, level);
    if (b.kind == Resource::atlas)
        return {level_side(word(b, HARNESS_ATLAS_WIDTH), level), level_side(word(b, HARNESS_ATLAS_HEIGHT), level)};
    const size_t header = size_t(1 + HARNESS_VIRTUAL_LEVEL_WORDS * level);
    return {word(b, header + HARNESS_VIRTUAL_WIDTH), word(b, header + HARNESS_VIRTUAL_HEIGHT)};
}

glm::vec4 source_fetch(const SourceBinding& b, glm::ivec2 texel, int level)
{
    const glm::ivec2 size = source_size(b, level);
    if (texel.x < 0 || texel.y < 0 || texel.x >= size.x || texel.y >= size.y)
        throw Error("texel source: texel (" + std::to_string(texel.x) + ", " + std::to_string(texel.y) +
                    ") outside level " + std::to_string(level));
    if (b.kind == Resource::atlas) {
        const glm::ivec2 origin(word(b, HARNESS_ATLAS_ORIGIN_X), word(b, HARNESS_ATLAS_ORIGIN_Y));
        return b.image.levels.at(size_t(level)).at((origin.x >> level) + texel.x, (origin.y >> level) + texel.y);
    }
    const size_t header = size_t(1 + HARNESS_VIRTUAL_LEVEL_WORDS * level);
    const glm::ivec2 page = texel / kPage;
    const int32_t entry = word(b, size_t(word(b, header + HARNESS_VIRTUAL_FIRST_PAGE)) +
                                      size_t(page.y * word(b, header + HARNESS_VIRTUAL_PAGES_X) + page.x));
    const glm::ivec2 at = glm::ivec2(entry & 0xffff, entry >> 16) * kPage + texel % kPage;
    return b.image.levels.at(0).at(at.x, at.y);
}

MipChain read_source(const SourceBinding& b)
{
    MipChain chain;
    for (int l = 0; l < source_levels(b); ++l) {
        const glm::ivec2 size = source_size(b, l);
        Image level = make_image(size.x, size.y);
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                level.at(x, y) = source_fetch(b, {x, y}, l);
        chain.levels.push_back(std::move(level));
    }
    return chain;
}

Lookup atlas_lookup(const SourceBinding& atlas, const Lookup& lookup)
{
    const Image& level0 = atlas.image.levels.at(0);
    const double sx = double(word(atlas, HARNESS_ATLAS_WIDTH)) / level0.width;
    const double sy = double(word(atlas, HARNESS_ATLAS_HEIGHT)) / level0.height;
    Lookup l = lookup;
    l.u = double(word(atlas, HARNESS_ATLAS_ORIGIN_X)) / level0.width + lookup.u * sx;
    l.v = double(word(atlas, HARNESS_ATLAS_ORIGIN_Y)) / level0.height + lookup.v * sy;
    l.dudx *= sx, l.dudy *= sx;
    l.dvdx *= sy, l.dvdy *= sy;
    return l;
}

} // namespace tf
