#include "core/resource.h"

#include "texture/error.h"

#include <algorithm>
#include <utility>

namespace tf {

namespace {

const std::pair<Resource, const char*> kResourceNames[] = {
    {Resource::combined, "combined"}, {Resource::separate, "separate"},
    {Resource::array, "array"},       {Resource::separate_array, "separate-array"},
    {Resource::bindless, "bindless"}, {Resource::shadow, "shadow"},
    {Resource::atlas, "atlas"},       {Resource::virtual_texture, "virtual"},
};

const std::pair<CompareOp, const char*> kCompareNames[] = {
    {CompareOp::never, "never"},
    {CompareOp::less, "less"},
    {CompareOp::equal, "equal"},
    {CompareOp::less_or_equal, "less-or-equal"},
    {CompareOp::greater, "greater"},
    {CompareOp::not_equal, "not-equal"},
    {CompareOp::greater_or_equal, "greater-or-equal"},
    {CompareOp::always, "always"},
};

template <typename Enum, size_t N>
Enum parse_name(const std::pair<Enum, const char*> (&table)[N], const std::string& name, const char* what)
{
    std::string list;
    for (const auto& [value, text] : table) {
        if (name == text)
            return value;
        list += (list.empty() ? "" : ", ") + std::string(text);
    }
    throw Error(std::string("unknown ") + what + " '" + name + "' (expected one of: " + list + ")");
}

template <typename Enum, size_t N>
std::string name_of(const std::pair<Enum, const char*> (&table)[N], Enum value)
{
    for (const auto& [v, text] : table)
        if (v == value)
            return text;
    return "?";
}

} // namespace

Resource parse_resource(const std::string& name) { return parse_name(kResourceNames, name, "resource"); }
std::string to_string(Resource resource) { return name_of(kResourceNames, resource); }
CompareOp parse_compare_op(const std::string& name) { return parse_name(kCompareNames, name, "compare op"); }
std::string to_string(CompareOp op) { return name_of(kCompareNames, op); }

bool is_layered(Resource resource)
{
    return resource == Resource::array || resource == Resource::separate_array || resource == Resource::bindless;
}

bool is_texel_source(Resource resource)
{
    return resource == Resource::atlas || resource == Resource::virtual_texture;
}

double compare_depth(CompareOp op, double dref, double depth)
{
    bool pass = false;
    switch (op) {
    case CompareOp::never: pass = false; break;
    case CompareOp::less: pass = dref < depth; break;
    case CompareOp::equal: pass = dref == depth; break;
    case CompareOp::less_or_equal: pass = dref <= depth; break;
    case CompareOp::greater: pass = dref > depth; break;
    case CompareOp::not_equal: pass = dref != depth; break;
    case CompareOp::greater_or_equal: pass = dref >= depth; break;
    case CompareOp::always: pass = true; break;
    }
    return pass ? 1.0 : 0.0;
}

int texture_index(const ResourceOptions& options, size_t lookup_index)
{
    const int layers = std::max(1, options.layers);
    switch (options.resource) {
    case Resource::array:
    case Resource::separate_array: return std::clamp(options.layer, 0, layers - 1);
    case Resource::bindless: return int((size_t(options.layer) + lookup_index) % size_t(layers));
    default: return 0;
    }
}

} // namespace tf
