#pragma once
// tf::Image, make_image, the sRGB transfer functions: declared in the installed header (texfilter::host).
#include <texfilter/host.h>
