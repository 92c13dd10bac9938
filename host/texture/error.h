#pragma once
// One exception type for every user-facing failure: the CLI prints what() and exits non-zero. It lives in
// the lowest layer because the installed texture library (MIP chains, SATs) throws it too.
#include <stdexcept>
#include <string>

namespace tf {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace tf
