#pragma once
// Summed-area tables: declared in the installed header (texfilter::host).
#include <texfilter/host.h>
