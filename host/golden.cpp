#include "golden.h"
#include "args.h"
#include "error.h"
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace tf {

namespace {

double number(const std::string& where, const std::string& key, const std::string& text)
{
    char* end = nullptr;
    double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0')
        throw Error(where + ": bad value for " + key + ": '" + text + "'");
    return value;
}

} // namespace

std::vector<GoldenCase> read_manifest(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw Error(path + ": cannot open the golden manifest");
    std::vector<GoldenCase> cases;
    std::string line;
    for (int number_line = 1; std::getline(in, line); ++number_line) {
        if (size_t hash = line.find('#'); hash != std::string::npos)
            line.resize(hash);
        std::stringstream tokens(line);
        std::vector<std::string> words;
        for (std::string w; tokens >> w;)
            words.push_back(w);
        if (words.empty())
            continue;
        std::string where = path + ":" + std::to_string(number_line);
        if (words.size() < 4)
            throw Error(where + ": expected NAME SCENE TEXTURE FILTER [key=value ...]");
        GoldenCase c;
        c.name = words[0];
        try {
            c.scene = parse_scene(words[1]);
            c.texture.name_or_path = words[2];
            c.sampler.filter = parse_filter(words[3]);
        } catch (const Error& e) {
            throw Error(where + ": " + e.what());
        }
        for (size_t i = 4; i < words.size(); ++i) {
            size_t eq = words[i].find('=');
            if (eq == std::string::npos)
                throw Error(where + ": expected key=value, got '" + words[i] + "'");
            std::string key = words[i].substr(0, eq), value = words[i].substr(eq + 1);
            if (key == "wrap")
                c.sampler.wrap = parse_wrap(value);
            else if (key == "lod-bias")
                c.sampler.lod_bias = float(number(where, key, value));
            else if (key == "lod-min")
                c.sampler.lod_min = float(number(where, key, value));
            else if (key == "lod-max")
                c.sampler.lod_max = float(number(where, key, value));
            else if (key == "texture-size")
                c.texture.procedural_size = int(number(where, key, value));
            else if (key == "size")
                std::tie(c.width, c.height) = parse_size(where + ": size", value, 2, 4096);
            else if (key == "fail")
                c.thresholds.fail = number(where, key, value);
            else if (key == "failpercent")
                c.thresholds.fail_percent = number(where, key, value);
            else if (key == "hardfail")
                c.thresholds.hard_fail = number(where, key, value);
            else
                throw Error(where + ": unknown key '" + key + "'");
        }
        for (const GoldenCase& other : cases)
            if (other.name == c.name)
                throw Error(where + ": case name '" + c.name + "' used twice");
        cases.push_back(c);
    }
    return cases;
}

Image encode_srgb(const Image& linear)
{
    Image out = linear;
    for (glm::vec4& t : out.texels)
        for (int c = 0; c < 3; ++c)
            t[c] = float(linear_to_srgb(std::min(1.0, std::max(0.0, double(t[c])))));
    return out;
}

} // namespace tf
