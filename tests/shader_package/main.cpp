// main.cpp: prints the word count of every embedded module (the test compares them with the .spv files)
// and fails unless each starts with the SPIR-V magic number and the two blur modules differ.
#include "a/blur_comp.h"
#include "b/blur_comp.h"
#include "sky_frag.h"

#include <cstdio>
#include <cstring>

std::uint32_t sky_frag_first_word(); // embed_alone.cpp

int main()
{
    const std::uint32_t magic = 0x07230203;
    std::printf("a/blur.comp %zu\nb/blur.comp %zu\nsky.frag %zu\n", sizeof a_blur_comp / 4, sizeof b_blur_comp / 4,
                sizeof sky_frag / 4);
    bool ok = a_blur_comp[0] == magic && b_blur_comp[0] == magic && sky_frag[0] == magic && sky_frag_first_word() == magic;
    bool differ = sizeof a_blur_comp != sizeof b_blur_comp || std::memcmp(a_blur_comp, b_blur_comp, sizeof a_blur_comp) != 0;
    if (!ok || !differ) {
        std::fprintf(stderr, "consumer: %s\n", ok ? "a/blur.comp and b/blur.comp embedded the same module" : "no SPIR-V magic");
        return 1;
    }
    return 0;
}
