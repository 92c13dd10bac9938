#pragma once
// The image I/O module (texfilter_oiio.so, io/oiio_abi.h), loaded on first use: OpenImageIO and its ~260
// libraries cost a third of a second of dynamic loading, which only a process that reads or writes an
// image file (or runs OpenImageIO's TextureSystem, io/oiio_texture.h) pays.
//
// Where it is looked for, from the executable's own path (/proc/self/exe), first found wins:
//   EXE_DIR/texfilter_oiio.so                   the build tree (build/texfilter)
//   EXE_DIR/../texfilter_oiio.so                the build tree's tests/ executables
//   EXE_DIR/<bin to lib>/texfilter/texfilter_oiio.so  an installed bin/texfilter: PREFIX/lib/texfilter/
// Cost: one dlopen (RTLD_NOW | RTLD_LOCAL) per process, the first time; then a pointer read.
// Example: const tf_oiio_api& api = image_io_module(); api.read_header(...);
#include "io/oiio_abi.h"
#include "texture/error.h"

#include <glm/vec4.hpp>

#include <exception>
#include <functional>
#include <new>
#include <string>

namespace tf {

// The module's table, loaded once (thread-safe). Throws tf::Error naming the module's path and dlerror()
// (or every path looked at, when none exists) where it is missing, unloadable or of another ABI version;
// a later call tries again.
const tf_oiio_api& image_io_module();

// One call into the module: its error message, and (read_rgba) where decoded texels go.
// Example: ModuleCall call; call.check(api.read_header(path, max_side, &header, &call.c));
struct ModuleCall {
    std::string message;                                          // the module's (or the destination's) tf::Error text
    std::function<glm::vec4*(int width, int height)> destination; // throws tf::Error to refuse
    tf_oiio_call c{this, &ModuleCall::fail, &ModuleCall::texels};

    ModuleCall() = default;
    ModuleCall(const ModuleCall&) = delete; // c points at this object
    ModuleCall& operator=(const ModuleCall&) = delete;

    static void fail(void* self, const char* message) { static_cast<ModuleCall*>(self)->message = message; }

    // No exception may cross into the module: a refusal or an allocation failure is kept here, null returned.
    static float* texels(void* self, int width, int height)
    {
        ModuleCall& call = *static_cast<ModuleCall*>(self);
        try {
            return reinterpret_cast<float*>(call.destination(width, height));
        } catch (const std::bad_alloc&) {
            call.message = "out of memory for " + std::to_string(width) + "x" + std::to_string(height) + " pixels";
        } catch (const std::exception& e) {
            call.message = e.what();
        }
        return nullptr;
    }

    // Throws tf::Error with the module's message where ok is 0.
    void check(int ok) const
    {
        if (!ok) throw Error(message.empty() ? std::string("image I/O module failed without a message") : message);
    }
};

} // namespace tf
