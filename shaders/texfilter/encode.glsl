// texfilter/encode.glsl — linear values to the codes an 8-bit, sRGB or half-float image stores, rounded
// exactly as the host rounds them (tf::pack_texels, host/core/texture_format.h), for a compute shader that
// writes such an image through an integer view (build_mip.glsl's chains; any render target you pack).
//
// Use:     uint tf_mip_srgb8(float v);   // 0..255: the sRGB code of clamp(v, 0, 1)
//          uint tf_mip_unorm8(float v);  // 0..255: round(clamp(v, 0, 1)·255), ties to even
//          uint tf_mip_half(float v);    // IEEE binary16 bits, round to nearest even
//          Scalar functions of a value: no texture parameter, so nothing per resource kind or texel source.
// Math:    sRGB: the exact encode (IEC 61966-2-1), code k + 1 from the smallest float the host rounds to k + 1
//          (a 255-entry threshold table, binary search). unorm8: from the float's bits, exact. half: round to
//          nearest even, subnormals included.
// Options: none.
// Needs:   nothing (no extension). Store through an R8G8B8A8_UINT (R16G16B16A16_UINT, ...) view of an image
//          created with VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT and EXTENDED_USAGE: sRGB storage images are not
//          writable on most devices, and a store's own float -> unorm or -> half conversion may round to
//          either neighbour (Vulkan allows both).
// Cost:    unorm8 and half: a dozen integer operations; sRGB8: a binary search of 8 steps in a 255-entry table.
// Degenerate input: srgb8 and unorm8: NaN and −Inf give 0, +Inf 255. half: ±Inf stay ±Inf, NaN a quiet NaN
//          (sign kept), |v| from the midpoint of 65504 and 65536 up gives ±Inf.
// Example: imageStore(codes, p, uvec4(tf_mip_srgb8(c.r), tf_mip_srgb8(c.g), tf_mip_srgb8(c.b), tf_mip_unorm8(c.a)));
#ifndef TF_ENCODE_GLSL
#define TF_ENCODE_GLSL

// Stored codes, rounded exactly as tf::pack_texels rounds (texture_format.h), for stores through an
// integer view of an 8-bit or half-float image (a storage image's own float -> unorm or -> half conversion
// may round either way: Vulkan allows both neighbours).
// unorm8: round(clamp(v)·255), ties to even, from the bits (v·255 is exact in 32-bit integers).
uint tf_mip_unorm8(float v)
{
    v = clamp(v, 0.0, 1.0);
    if (!(v > 0.0)) // 0, and NaN
        return 0u;
    const uint bits = floatBitsToUint(v);
    const int exponent = int(bits >> 23) - 150; // v = mantissa · 2^exponent, exponent ≤ -23
    const uint product = ((bits & 0x7FFFFFu) | 0x800000u) * 255u;
    const int shift = -exponent;
    if (shift >= 32) // v·255 < 1: 1 past the halfway 2^31 of a shift by 32 (v in [2^-9, 2^-8)), else 0
        return shift == 32 && product > 0x80000000u ? 1u : 0u;
    uint q = product >> uint(shift);
    const uint rest = product - (q << uint(shift)), halfway = 1u << uint(shift - 1);
    if (rest > halfway || (rest == halfway && (q & 1u) != 0u))
        ++q;
    return q;
}

// sRGB8: the code of the exact encode (IEC 61966-2-1) of clamp(v), as tf::pack_texels: code k + 1 from the
// smallest float that the host rounds to k + 1 (the table, found by bisection over floats against the host's
// rounding; tests/test_gpu_build.cpp checks it), so a binary search gives the host's code for every float.
const float tfi_srgb8_thresholds[255] = float[255](
    0.000151763496, 0.000455290487, 0.000758817478, 0.00106234453, 0.00136587152, 0.00166939851,
    0.00197292562, 0.00227645249, 0.00257997937, 0.00288350647, 0.00318830111, 0.00350925955,
    0.00384831498, 0.00420574844, 0.00458183279, 0.00497683743, 0.00539102452, 0.0058246511,
    0.00627796957, 0.00675122766, 0.00724466844, 0.00775853079, 0.00829304848, 0.00884845387,
    0.00942497142, 0.0100228265, 0.010642237, 0.0112834219, 0.0119465925, 0.0126319602,
    0.0133397318, 0.0140701123, 0.0148233036, 0.0155995032, 0.0163989104, 0.0172217172,
    0.0180681162, 0.0189382955, 0.0198324434, 0.0207507461, 0.0216933843, 0.0226605386,
    0.0236523915, 0.0246691164, 0.0257108882, 0.026777884, 0.0278702714, 0.0289882217,
    0.0301319025, 0.0313014835, 0.0324971229, 0.0337189883, 0.0349672437, 0.0362420455,
    0.0375435539, 0.038871929, 0.04022732, 0.0416098908, 0.0430197865, 0.0444571637,
    0.045922175, 0.0474149659, 0.048935689, 0.0504844859, 0.0520615093, 0.0536669008,
    0.055300802, 0.0569633618, 0.0586547181, 0.0603750125, 0.0621243864, 0.0639029741,
    0.0657109171, 0.067548357, 0.0694154128, 0.0713122413, 0.0732389614, 0.0751957074,
    0.0771826208, 0.0791998208, 0.0812474489, 0.0833256245, 0.085434489, 0.0875741616,
    0.089744769, 0.0919464454, 0.0941793025, 0.0964434817, 0.098739095, 0.101066276,
    0.103425138, 0.105815805, 0.108238406, 0.110693052, 0.11317987, 0.115698971,
    0.118250489, 0.120834522, 0.123451203, 0.126100644, 0.128782958, 0.131498262,
    0.134246677, 0.137028307, 0.139843285, 0.142691687, 0.145573661, 0.148489311,
    0.151438743, 0.15442206, 0.157439396, 0.160490841, 0.163576499, 0.166696504,
    0.169850945, 0.173039928, 0.176263571, 0.179521978, 0.182815254, 0.186143503,
    0.189506844, 0.192905352, 0.19633916, 0.199808359, 0.203313053, 0.206853345,
    0.210429341, 0.214041144, 0.217688859, 0.221372575, 0.225092396, 0.228848428,
    0.232640773, 0.236469522, 0.240334779, 0.244236648, 0.248175219, 0.252150595,
    0.256162852, 0.260212123, 0.264298499, 0.268422037, 0.272582889, 0.276781112,
    0.281016827, 0.285290092, 0.289601028, 0.293949753, 0.298336297, 0.30276081,
    0.30722338, 0.311724067, 0.31626296, 0.32084021, 0.325455844, 0.330110013,
    0.334802747, 0.339534193, 0.344304383, 0.349113464, 0.353961498, 0.358848572,
    0.363774806, 0.368740231, 0.373744994, 0.378789157, 0.383872777, 0.388996005,
    0.3941589, 0.399361551, 0.404604018, 0.40988642, 0.415208846, 0.420571357,
    0.425974071, 0.431417048, 0.436900377, 0.442424119, 0.447988421, 0.453593343,
    0.459238917, 0.464925319, 0.47065255, 0.47642073, 0.482229948, 0.488080263,
    0.493971765, 0.499904573, 0.505878747, 0.511894345, 0.517951429, 0.524050176,
    0.530190587, 0.536372721, 0.542596757, 0.548862696, 0.555170655, 0.561520696,
    0.567912936, 0.574347377, 0.580824137, 0.587343335, 0.593905032, 0.600509286,
    0.607156157, 0.613845766, 0.62057817, 0.62735343, 0.634171665, 0.641032934,
    0.647937298, 0.654884875, 0.661875665, 0.668909848, 0.675987422, 0.683108449,
    0.690273106, 0.697481394, 0.704733372, 0.712029159, 0.719368875, 0.72675246,
    0.734180093, 0.741651833, 0.74916774, 0.756727874, 0.764332294, 0.77198118,
    0.77967447, 0.787412345, 0.795194805, 0.803021908, 0.810893834, 0.818810582,
    0.826772213, 0.834778845, 0.842830539, 0.850927293, 0.859069288, 0.867256522,
    0.875489116, 0.883767128, 0.892090559, 0.900459588, 0.908874214, 0.917334557,
    0.925840676, 0.934392571, 0.942990422, 0.951634228, 0.960324049, 0.969060004,
    0.977842152, 0.986670554, 0.995545268
);
uint tf_mip_srgb8(float v)
{
    uint code = 0u;
    for (uint step = 128u; step > 0u; step >>= 1u) // the number of thresholds at or below v
        if (code + step <= 255u && v >= tfi_srgb8_thresholds[code + step - 1u])
            code += step;
    return code;
}

// IEEE binary16 bits of v, round to nearest, ties to even (Inf and NaN kept).
uint tf_mip_half(float v)
{
    const uint x = floatBitsToUint(v);
    const uint sign = (x >> 16) & 0x8000u;
    const uint a = x & 0x7FFFFFFFu;
    if (a >= 0x7F800000u)
        return sign | 0x7C00u | (a > 0x7F800000u ? 0x200u : 0u);
    if (a >= 0x477FF000u) // from the midpoint of 65504 and 2^16: Inf
        return sign | 0x7C00u;
    if (a < 0x38800000u) // a subnormal half: round(|v|·2^24), an exact scaling
        return sign | uint(roundEven(uintBitsToFloat(a) * 16777216.0));
    uint h = ((((a >> 23) - 112u) << 10) | ((a & 0x7FFFFFu) >> 13));
    const uint rest = a & 0x1FFFu;
    if (rest > 0x1000u || (rest == 0x1000u && (h & 1u) != 0u))
        ++h;
    return sign | h;
}

#endif // TF_ENCODE_GLSL
