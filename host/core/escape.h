#pragma once
// Bytes of a message that a terminal would act on, written as \xNN instead: text from a flag, a script line
// or a file must not move the cursor, clear the screen or start a line that looks like another message.
#include <string>
#include <string_view>

namespace tf {

enum class Escape {
    control,  // bytes below 0x20 and 0x7f: every message texfilter prints (cli/main.cpp)
    all_but_ascii, // those, every byte from 0x80 and the backslash: quoting a file's raw bytes (lookups CSV)
};
std::string escape_bytes(std::string_view text, Escape which);

} // namespace tf
