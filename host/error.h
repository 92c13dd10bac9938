#pragma once
// One exception type for every user-facing failure: the CLI prints what() and exits non-zero.
#include <stdexcept>
#include <string>

namespace tf {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace tf
