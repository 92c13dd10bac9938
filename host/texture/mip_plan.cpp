// The passes of the GPU MIP build (build_mip.glsl): which levels each dispatch makes.
#include "texture/mip.h"

#include "texture/error.h"

#include <algorithm>
#include <string>

namespace tf {

namespace {

int side_at(int side0, int level) { return std::max(1, side0 >> level); }

// A tile's next level comes from this one alone when the level halves exactly on both axes.
bool halves(int width, int height) { return (width % 2 == 0 || width == 1) && (height % 2 == 0 || height == 1); }

constexpr int tile = 32;      // destination texels a side of a group's first level
constexpr int max_levels = 6; // 32 -> 1

} // namespace

std::vector<MipBuildPass> plan_mip_build(int width, int height, int tail_texels)
{
    if (width < 1 || height < 1)
        throw Error("MIP build plan of an empty " + std::to_string(width) + "x" + std::to_string(height) + " texture");
    const int last = mip_level_count(width, height) - 1;
    std::vector<MipBuildPass> passes;
    for (int source = 0; source < last;) {
        MipBuildPass pass;
        pass.source_level = source;
        pass.levels = 1;
        while (pass.levels < max_levels && source + pass.levels < last &&
               halves(side_at(width, source + pass.levels), side_at(height, source + pass.levels)))
            ++pass.levels;
        const int end = source + pass.levels;
        pass.groups_x = (side_at(width, source + 1) + tile - 1) / tile;
        pass.groups_y = (side_at(height, source + 1) + tile - 1) / tile;
        pass.tail = end < last && int64_t(side_at(width, end)) * side_at(height, end) <= tail_texels;
        passes.push_back(pass);
        if (pass.tail)
            break;
        source = end;
    }
    return passes;
}

} // namespace tf
