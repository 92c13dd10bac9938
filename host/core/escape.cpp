#include "core/escape.h"
#include <cstdio>

namespace tf {

std::string escape_bytes(std::string_view text, Escape which)
{
    std::string out;
    out.reserve(text.size());
    for (char ch : text) {
        const unsigned char c = static_cast<unsigned char>(ch);
        const bool control = c < 0x20 || c == 0x7f;
        const bool other = which == Escape::all_but_ascii && (c >= 0x80 || c == '\\');
        if (!control && !other) {
            out += ch;
            continue;
        }
        char hex[8];
        std::snprintf(hex, sizeof(hex), "\\x%02x", c);
        out += hex;
    }
    return out;
}

} // namespace tf
