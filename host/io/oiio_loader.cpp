// Loads texfilter_oiio.so (oiio_loader.h) with dlopen, on the first image file read or written.
#include "io/oiio_loader.h"

#include "texture/error.h"

#include <dlfcn.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

// The module's folder relative to the installed executable's (CMAKE_INSTALL_BINDIR to LIBDIR/texfilter).
#ifndef TF_OIIO_MODULE_FROM_BIN
#define TF_OIIO_MODULE_FROM_BIN "../lib/texfilter"
#endif

namespace tf {
namespace {

namespace fs = std::filesystem;

constexpr const char* module_name = "texfilter_oiio.so";

std::vector<fs::path> module_candidates() {
    std::error_code ec;
    const fs::path exe = fs::canonical("/proc/self/exe", ec);
    if (ec) throw Error(std::string("cannot find the image I/O module ") + module_name +
                        ": /proc/self/exe: " + ec.message());
    const fs::path dir = exe.parent_path();
    return {dir / module_name, dir.parent_path() / module_name,
            (dir / TF_OIIO_MODULE_FROM_BIN / module_name).lexically_normal()};
}

const tf_oiio_api* load() {
    const std::vector<fs::path> candidates = module_candidates();
    const fs::path* found = nullptr;
    for (const fs::path& path : candidates) {
        std::error_code ec;
        if (fs::is_regular_file(path, ec)) {
            found = &path;
            break;
        }
    }
    if (!found) {
        std::string looked;
        for (const fs::path& path : candidates) looked += (looked.empty() ? "" : ", ") + path.string();
        throw Error(std::string("the image I/O module (OpenImageIO) is missing: no ") + module_name + " at " + looked +
                    " (reinstall texfilter, or build its texfilter_oiio target)");
    }
    const std::string path = found->string();
    dlerror(); // clear
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL); // never closed: used until exit
    if (!handle) {
        const char* why = dlerror();
        throw Error(path + ": cannot load the image I/O module: " + (why ? why : "unknown dlopen error"));
    }
    auto entry = reinterpret_cast<tf_oiio_entry>(dlsym(handle, TF_OIIO_ENTRY));
    if (!entry) {
        const char* why = dlerror();
        dlclose(handle);
        throw Error(path + ": not a texfilter image I/O module: " + (why ? why : "no " TF_OIIO_ENTRY));
    }
    const tf_oiio_api* api = entry();
    if (!api || api->abi_version != TF_OIIO_ABI_VERSION) {
        const std::string version = api ? std::to_string(api->abi_version) : "none";
        dlclose(handle);
        throw Error(path + ": image I/O module of ABI version " + version + ", this texfilter needs " +
                    std::to_string(TF_OIIO_ABI_VERSION) + " (a module from another build: reinstall texfilter)");
    }
    return api;
}

} // namespace

const tf_oiio_api& image_io_module() {
    static const tf_oiio_api* api = load(); // a throw leaves it unset: the next call tries again
    return *api;
}

} // namespace tf
