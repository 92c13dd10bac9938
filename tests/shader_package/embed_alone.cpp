// embed_alone.cpp: an EMBED header as the first and only include of a translation unit, so it must bring
// what it uses (<cstdint>) itself.
#include "sky_frag.h"

std::uint32_t sky_frag_first_word() { return sky_frag[0]; }
