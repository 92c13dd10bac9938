#pragma once
// NaN and ±Inf texels: declared in the installed header (texfilter::host).
#include <texfilter/host.h>
