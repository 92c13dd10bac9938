#pragma once
// texfilter::host: the tables texfilter's GLSL includes sample, built on the CPU. No Vulkan, no image files.
//
//   find_package(texfilter 0.9 REQUIRED)
//   target_link_libraries(app PRIVATE texfilter::host)    // C++20, links glm and Threads
//   #include <texfilter/host.h>
//
// What it builds:
//   - MIP chains in linear light, level sizes by Vulkan's floor rule (max(1, w >> l)), every texel of a level
//     the exact box average of the texels it covers (odd sizes: 3 texels with fractional weights), for
//     texture(), textureLod() and every tf_ filter (upload each level as RGBA32F, level 0 first).
//   - Summed-area tables for tf_sat / tf_sat_assembly (docs/API.md, "sat.glsl"): two integer images
//     (RGBA32UI low words, R32UI high bytes) plus a per-channel offset and scale for the shader.
//   - The sRGB decode of 8-bit texels: filter in linear light, so decode before building anything.
//
// Conventions for every function here:
//   - Images are linear-light RGBA float, row-major, row 0 first (v = 0 is row 0, as Vulkan stores images).
//   - Sizes are in texels; a texel (x, y) covers texture space [x, x+1) x [y, y+1).
//   - Bad input (empty or oversize images, NaN where a table needs finite values, boxes outside the texture)
//     throws tf::Error with a message saying what and why; nothing else is thrown except std::bad_alloc.
//   - Functions are thread-safe on distinct arguments; large MIP levels are built on every core.
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace tf {

// ---- Errors -------------------------------------------------------------------------------------------------

// Every user-facing failure. what() is one line naming the input and the problem.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ---- Images and colour --------------------------------------------------------------------------------------

// width x height texels, row-major. Invariant: texels.size() == width * height.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> texels;

    glm::vec4& at(int x, int y) { return texels[size_t(y) * size_t(width) + size_t(x)]; }
    const glm::vec4& at(int x, int y) const { return texels[size_t(y) * size_t(width) + size_t(x)]; }
};

// A width x height image, every texel `fill`. Throws tf::Error for a negative side (0 gives an empty image).
Image make_image(int width, int height, glm::vec4 fill = glm::vec4(0.0f));

// IEC 61966-2-1 transfer functions on [0, 1], exact piecewise form (not a gamma approximation), in double.
double srgb_to_linear(double encoded);
double linear_to_srgb(double linear);

// Linear image -> sRGB-encoded values in float (clamped to [0,1] first, no quantisation), alpha unchanged:
// the display values goldens and benchmark errors are measured in.
Image encode_srgb(const Image& linear);

// 8-bit code (0..255) -> linear value of that sRGB code, rounded to float: a table of 256 entries.
const std::array<float, 256>& srgb8_decode_table();

// 8-bit texels (what a PNG or JPEG decoder gives) to linear RGBA. Input: width x height pixels of `channels`
// bytes each (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA), tightly packed rows. Colour channels are decoded from
// sRGB (srgb8_decode_table), alpha is linear (code / 255); grey is replicated to RGB and a missing alpha is 1.
// Throws tf::Error for channels outside 1..4 or a negative side.
Image decode_srgb8(const uint8_t* pixels, int width, int height, int channels);

// ---- Finite texels -------------------------------------------------------------------------------------------

// A NaN or ±Inf texel spreads over every footprint that touches it (a 32x32 texture with 3 of them turns
// hundreds of pixels NaN), and a summed-area table cannot hold one: texture loaders refuse them. Counts the
// non-finite channel values of texels scanned in any order (a band of rows at a time, as a decoder fills
// them) and keeps the first in row order (its first non-finite channel).
struct NonFiniteTexels {
    uint64_t count = 0;    // texels with a NaN or ±Inf channel
    size_t first_index = 0; // the first one's texel index (y * width + x); meaningful when count > 0
    int x = -1, y = -1, channel = -1;
    float value = 0.0f;
    // n texels of a width-wide image, the first of them texel index `first`.
    void scan(const glm::vec4* texels, size_t first, size_t n, int width);
};
// Throws tf::Error "WHAT: texel (x, y) is NaN (channel G; N of W*H texels hold NaN or Inf): every filter needs
// finite texels" (+Inf, -Inf likewise) when anything non-finite was found.
void check_finite_texels(const NonFiniteTexels& found, const std::string& what, int width, int height);
void check_finite_texels(const Image& image, const std::string& what);

// ---- MIP chains ---------------------------------------------------------------------------------------------

struct MipChain {
    std::vector<Image> levels; // levels[0] is the full-resolution texture, the last is 1x1
};

// 1 + floor(log2(max(width, height))): the full chain down to 1x1 (0 for an empty size).
int mip_level_count(int width, int height);

// The level below a width x height level: max(1, width >> 1) x max(1, height >> 1) (Vulkan's floor rule).
// Destination texel i covers source [i*W/W', (i+1)*W/W') on each axis and is its overlap-weighted average:
// 2 texels per axis for even sizes, 3 for odd ones, so no source texel is dropped. Separable; the sums
// are formed in double and rounded to float once, so results do not depend on the thread count.
//
// downsample_into: src holds width x height texels, dst receives the smaller level's texels; dst may be src
// itself (the level is then built in place, overwriting the start of src: what a streaming upload uses to
// need one level's memory) but must not otherwise overlap it. Throws tf::Error for a side below 1.
void downsample_into(const glm::vec4* src, int width, int height, glm::vec4* dst);
Image downsample(const Image& source);

// Level 0 plus every level down to 1x1, each built from the one above by downsample.
// Throws tf::Error for an empty image or one whose texels do not match its size.
MipChain build_mip_chain(Image level0);

// ---- GPU builds (shaders/texfilter/build_mip.glsl, build_sat.glsl) ----------------------------------------------

// One dispatch of build_mip.glsl: levels source_level + 1 .. source_level + levels from source_level, in
// groups_x x groups_y groups (32 x 32 texels of the first of them each); with `tail`, the group that
// finishes last builds every level after those too. Push these fields to tf_build_mip_pass.
struct MipBuildPass {
    int source_level = 0;
    int levels = 0;     // 1..6
    bool tail = false;
    int groups_x = 0, groups_y = 0;
};
// The largest level (in texels) the tail's one group builds alone: TF_MIP_TAIL_TEXELS's default.
constexpr int mip_build_tail_texels = 16384;
// The fewest passes the rule allows: a pass continues below its first level while the level it halves is
// even (or 1 texel) on both axes, up to 6 levels (a 32-texel tile halved to 1), and takes the tail once its
// last level has at most tail_texels texels. A 2^k x 2^k texture up to 8192 is one pass; each odd level
// ends a pass. Empty for a 1x1 texture; throws tf::Error for a side below 1.
std::vector<MipBuildPass> plan_mip_build(int width, int height, int tail_texels = mip_build_tail_texels);

// ---- Summed-area tables (tf_sat, tf_sat_assembly) -----------------------------------------------------------

// Input quantisation, per channel c, over the texture's own range: offset_c = the smallest texel value,
// scale_c = largest − smallest, rounded up to float (0 for a constant channel). A texel value v becomes
// q = round((v − offset_c) / scale_c · 65535) in [0, 65535] (in double; 0 where scale_c = 0), i.e. the value
// offset_c + q · scale_c / 65535. So a box mean from the table is within 0.5/65535 · scale_c of the float
// texels' mean (plus float32 rounding in the shader); texels equal to the channel's minimum are exact.
// Every texel must be finite (NaN and ±Inf are refused) and each channel's span must fit a float.
constexpr uint32_t sat_quantisation_levels = 65535;
// Bit budget: table entries are running sums kept modulo 2^40 per channel, and box sums A - B - C + D are
// formed modulo 2^40 (host and shader alike), which is exact whenever the box's true sum is below 2^40:
// every box of up to 2^24 texels of 16-bit values (24 + 16 = 40 bits), i.e. up to 4096x4096. The shader
// clamps its boxes to the texture's size, so sides up to 4096 keep every lookup exact.
constexpr int sat_max_dimension = 4096;

// Upload low as a (width+1) x (height+1) VK_FORMAT_R32G32B32A32_UINT image (satLow) and high as the same
// size in VK_FORMAT_R32_UINT (satHigh); pass offset and scale to tf_sat.
struct SatTable {
    int width = 0, height = 0; // the texture's size; the table is (width + 1) x (height + 1), row 0 and column 0 zero
    glm::vec4 offset{0.0f};    // per channel: the value of quantisation level 0 (the smallest texel value)
    glm::vec4 scale{0.0f};     // per channel: level 65535 minus level 0 (largest − smallest, rounded up)
    std::vector<uint32_t> low; // 4 words a table entry (RGBA), bits 0..31 of each channel's running sum mod 2^40
    std::vector<uint32_t> high; // 1 word a table entry: bits 32..39 of R, G, B, A in bytes 0..3
};

// Throws tf::Error "texture NAME: texel (i, j) is NaN: sat needs finite texels" (or +Inf, -Inf; the first
// such texel in row order) or, where a channel's span max − min overflows float, says so. An empty name
// says "summed-area table" instead.
void check_sat_texels(const Image& level0, const std::string& texture_name = "");

// The table of level 0 (the full-resolution texture, linear values; build it after any sRGB decode).
// Throws tf::Error for a texture larger than sat_max_dimension on a side, and as check_sat_texels.
SatTable build_sat(const Image& level0);

// build_sat.glsl's range words (TF_SAT_RANGE): the initial values to clear them to before its range pass,
// and what they mean once it ran. Keys are order-preserving encodings of floats.
constexpr int sat_range_words = 9;
std::array<uint32_t, sat_range_words> sat_range_initial();
// The table's offset and scale from the range words: as build_sat computes them from the texels. Throws
// tf::Error "texture NAME: texel (i, j) is NaN: sat needs finite texels (channel R)" (as check_sat_texels)
// when word 8 names a non-finite texel of a width-wide texture, and for a span that overflows float.
void sat_range_offset_scale(const std::array<uint32_t, sat_range_words>& words, int width,
                            const std::string& texture_name, glm::vec4& offset, glm::vec4& scale);

// Exact sum of the quantised texels (levels 0..65535) in [x0, x1) x [y0, y1), per channel RGBA, computed from
// the table with the same modular arithmetic the shader uses. Divide by the box's texel count and by 65535,
// multiply by scale and add offset for the box mean in texel units. Throws tf::Error for a box that is
// inverted or not inside the texture.
std::array<uint64_t, 4> sat_box_sum(const SatTable& table, int x0, int y0, int x1, int y1);

// ---- Cube maps (shaders/texfilter/cube.glsl; docs/ENVIRONMENT.md) ----------------------------------------------

// Six square faces in Vulkan's layer order: +X, -X, +Y, -Y, +Z, -Z (face index = array layer).
constexpr int cube_face_count = 6;

// Every face's full MIP chain, all faces the same square size (the floor rule per face).
struct CubeMap {
    std::array<MipChain, cube_face_count> faces;
    int size() const { return faces[0].levels.empty() ? 0 : faces[0].levels[0].width; }
};

// The faces' level 0 given, each face's chain built by build_mip_chain. Throws tf::Error when a face is
// empty or not square, or the faces differ in size.
CubeMap build_cube_map(std::array<Image, cube_face_count> faces);

// Vulkan's "Cube Map Face Selection": the face of the direction's major axis (ties: x before y before z,
// and +0 counts as positive) and the face coordinates s, t in [0, 1] where the direction meets it
// (s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2 with the spec's sc, tc, ma). A zero direction gives
// face +X at its centre.
struct CubeFacePoint {
    int face = 0;
    double s = 0.5, t = 0.5;
};
CubeFacePoint cube_face_point(const glm::dvec3& direction);
// The inverse on the face plane: the direction (not normalised, |ma| = 1) through face coordinates (s, t)
// of `face`; s, t outside [0, 1] extend the face's plane.
glm::dvec3 cube_face_direction(int face, double s, double t);

} // namespace tf
