// The peer in a build without OpenImageIO (TEXFILTER_IMAGE_IO=OFF): host/io/oiio_texture_stub.cpp, compiled here
// as the lean build compiles it, says plainly that it was left out, whatever is asked of it, while the mode names
// still parse (so a lean `sample --backend oiio --oiio-interp X` reaches that message rather than another).
// `texfilter sample --backend oiio` calls load_oiio_texture() before any work: in the lean build it exits 2 with
// this one message.
#include "io/oiio_texture.h"
#include "texture/error.h"

#include <cstdio>
#include <string>

namespace {

// One PASS or FAIL line; a failure counts in `failures`.
void expect(bool ok, const std::string& what, int& failures)
{
    std::printf("%s  %s\n", ok ? "PASS" : "FAIL", what.c_str());
    failures += ok ? 0 : 1;
}

template <typename Call>
void expect_left_out(const char* what, Call call, int& failures)
{
    const std::string wanted = "OpenImageIO's TextureSystem (--backend oiio) was left out of this build (configure "
                               "with -DTEXFILTER_IMAGE_IO=ON)";
    try {
        call();
        expect(false, std::string(what) + ": returned", failures);
    } catch (const tf::Error& e) {
        expect(e.what() == wanted, std::string(what) + ": " + e.what(), failures);
    }
}

} // namespace

int main()
{
    int failures = 0;
    expect(!tf::oiio_texture_available(), "oiio_texture_available() is false", failures);
    expect_left_out("load_oiio_texture", [] { tf::load_oiio_texture(); }, failures);
    expect_left_out("oiio_texture_lookups", [] {
        tf::oiio_texture_lookups(tf::make_image(2, 2), {{0.5, 0.5, 0.1, 0, 0, 0.1}}, tf::Wrap::repeat,
                                 tf::parse_oiio_texture_mode("aniso-smartbicubic"));
    }, failures);
    expect(tf::parse_oiio_interp("smartbicubic") == tf::OiioInterp::smartbicubic, "the names parse", failures);
    return failures == 0 ? 0 : 1;
}
