#pragma once
// The image I/O module (texfilter_oiio.so, io/oiio_abi.h), loaded on first use: OpenImageIO and its ~260
// libraries cost a third of a second of dynamic loading, which only a process that reads or writes an
// image file pays.
//
// Where it is looked for, from the executable's own path (/proc/self/exe), first found wins:
//   EXE_DIR/texfilter_oiio.so                   the build tree (build/texfilter)
//   EXE_DIR/../texfilter_oiio.so                the build tree's tests/ executables
//   EXE_DIR/<bin to lib>/texfilter/texfilter_oiio.so  an installed bin/texfilter: PREFIX/lib/texfilter/
// Cost: one dlopen (RTLD_NOW | RTLD_LOCAL) per process, the first time; then a pointer read.
// Example: const tf_oiio_api& api = image_io_module(); api.read_header(...);
#include "io/oiio_abi.h"

namespace tf {

// The module's table, loaded once (thread-safe). Throws tf::Error naming the module's path and dlerror()
// (or every path looked at, when none exists) where it is missing, unloadable or of another ABI version;
// a later call tries again.
const tf_oiio_api& image_io_module();

} // namespace tf
