#pragma once
// Golden regression cases: golden/manifest.txt lists scene x texture x filter x options with
// idiff-style thresholds; golden/<name>.png holds the CPU reference's image (8-bit sRGB).
#include "core/diff.h"
#include "core/filter.h"
#include "scene/scene.h"
#include "io/texture_source.h"
#include <istream>
#include <string>
#include <vector>

namespace tf {

struct GoldenCase {
    std::string name;
    SceneKind scene = SceneKind::plane;
    TextureSource texture;
    SamplerOptions sampler;
    RenderOptions render;
    int width = 256, height = 256;
    // In sRGB-encoded units, GPU side not quantised. Default: half an 8-bit step (the golden's own
    // rounding) plus float32 error; no pixel may be further off unless the manifest allows it.
    DiffThresholds thresholds{0.0025, 0.0, 0.0025};
};

// The longest case name: NAME.png (and gpu-build/NAME.png under --out) stays within a file name's 255 bytes.
constexpr size_t max_case_name = 200;

// One case a line: NAME SCENE TEXTURE FILTER [key=value ...] (NAME: letters, digits and . _ + -, starting
// with a letter or digit: a file name, not a path); keys are the render command's flags
// without "--" (wrap, lod-bias, texture-size, band, probes, taps, ...) plus size (WxH), fail,
// failpercent, hardfail. '#' starts a comment. Throws naming file:line.
std::vector<GoldenCase> read_manifest(const std::string& path);
// The same from a stream; `name` stands for the file in messages (the fuzz target reads from memory).
std::vector<GoldenCase> parse_manifest(std::istream& in, const std::string& name);

} // namespace tf
