// The fuzz build links the image I/O module's code in (host/io/oiio_module.cpp, instrumented with the rest)
// instead of dlopen'ing texfilter_oiio.so: this stands in for host/io/oiio_loader.cpp.
#include "io/oiio_loader.h"

namespace tf {

const tf_oiio_api& image_io_module() { return *tf_oiio_api_v1(); }

} // namespace tf
