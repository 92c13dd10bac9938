#include "texture/mip.h"

#include <cmath>
#include <string>

namespace tf {

CubeMap build_cube_map(std::array<Image, cube_face_count> faces)
{
    static const char* const names[cube_face_count] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    const int size = faces[0].width;
    for (int f = 0; f < cube_face_count; ++f) {
        const Image& face = faces[f];
        if (face.width <= 0 || face.height <= 0)
            throw Error("cube map: face " + std::string(names[f]) + " is empty");
        if (face.width != face.height)
            throw Error("cube map: face " + std::string(names[f]) + " is " + std::to_string(face.width) + "x" +
                        std::to_string(face.height) + ": faces must be square");
        if (face.width != size)
            throw Error("cube map: face " + std::string(names[f]) + " is " + std::to_string(face.width) +
                        " a side but face +X is " + std::to_string(size) + ": faces must have the same size");
    }
    CubeMap cube;
    for (int f = 0; f < cube_face_count; ++f)
        cube.faces[f] = build_mip_chain(std::move(faces[f]));
    return cube;
}

// The spec's table (Vulkan, "Cube Map Face Selection"): per face the major axis and the sc, tc it reads.
CubeFacePoint cube_face_point(const glm::dvec3& d)
{
    const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    double sc = 0, tc = 0, ma = 0;
    int face = 0;
    if (ax >= ay && ax >= az) {
        face = std::signbit(d.x) ? 1 : 0;
        sc = face == 0 ? -d.z : d.z;
        tc = -d.y;
        ma = ax;
    } else if (ay >= az) {
        face = std::signbit(d.y) ? 3 : 2;
        sc = d.x;
        tc = face == 2 ? d.z : -d.z;
        ma = ay;
    } else {
        face = std::signbit(d.z) ? 5 : 4;
        sc = face == 4 ? d.x : -d.x;
        tc = -d.y;
        ma = az;
    }
    if (!(ma > 0.0))
        return {};
    return {face, 0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0)};
}

glm::dvec3 cube_face_direction(int face, double s, double t)
{
    const double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
    switch (face) {
    case 0: return {1.0, -tc, -sc};
    case 1: return {-1.0, -tc, sc};
    case 2: return {sc, 1.0, tc};
    case 3: return {sc, -1.0, -tc};
    case 4: return {sc, -tc, 1.0};
    default: return {-sc, -tc, -1.0};
    }
}

} // namespace tf
