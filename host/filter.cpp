#include "filter.h"

#include "error.h"

#include <utility>

namespace tf {

namespace {

// One table per enum keeps parse, to_string and the error message in step.
const std::pair<Filter, const char*> kFilterNames[] = {
    {Filter::nearest, "nearest"},
    {Filter::bilinear, "bilinear"},
    {Filter::trilinear, "trilinear"},
    {Filter::nearest_mip, "nearest-mip"},
    {Filter::bilinear_mip, "bilinear-mip"},
    {Filter::hw_nearest, "hw-nearest"},
    {Filter::hw_bilinear, "hw-bilinear"},
    {Filter::hw_trilinear, "hw-trilinear"},
    {Filter::hw_aniso, "hw-aniso"},
};

const std::pair<Wrap, const char*> kWrapNames[] = {
    {Wrap::repeat, "repeat"},
    {Wrap::clamp, "clamp"},
    {Wrap::mirror, "mirror"},
};

template <typename Table>
std::string name_list(const Table& table) {
    std::string list;
    for (const auto& entry : table) {
        if (!list.empty()) list += ", ";
        list += entry.second;
    }
    return list;
}

} // namespace

Filter parse_filter(const std::string& name) {
    for (const auto& [filter, text] : kFilterNames)
        if (name == text) return filter;
    throw Error("unknown filter '" + name + "' (expected one of: " + name_list(kFilterNames) + ")");
}

std::string to_string(Filter filter) {
    for (const auto& [f, text] : kFilterNames)
        if (f == filter) return text;
    throw Error("invalid Filter value " + std::to_string(int(filter)));
}

const std::vector<Filter>& all_filters() {
    static const std::vector<Filter> filters = [] {
        std::vector<Filter> list;
        for (const auto& entry : kFilterNames) list.push_back(entry.first);
        return list;
    }();
    return filters;
}

bool is_hardware(Filter filter) {
    switch (filter) {
    case Filter::hw_nearest:
    case Filter::hw_bilinear:
    case Filter::hw_trilinear:
    case Filter::hw_aniso:
        return true;
    default:
        return false;
    }
}

Wrap parse_wrap(const std::string& name) {
    for (const auto& [wrap, text] : kWrapNames)
        if (name == text) return wrap;
    throw Error("unknown wrap mode '" + name + "' (expected one of: " + name_list(kWrapNames) + ")");
}

std::string to_string(Wrap wrap) {
    for (const auto& [w, text] : kWrapNames)
        if (w == wrap) return text;
    throw Error("invalid Wrap value " + std::to_string(int(wrap)));
}

} // namespace tf
