#pragma once
// Cube-map textures for the environment scenes (docs/ENVIRONMENT.md): procedural cubes by name, and cubes
// read from a horizontal-cross image. Faces in Vulkan's layer order +X, -X, +Y, -Y, +Z, -Z, each face
// stored in Vulkan's face orientation (texel (i, j): column i along s, row j along t of the spec's table).
//
// Use:   CubeMap cube = make_procedural_cube("cube-labels", 64);
//        CubeMap sky = cube_from_cross(read_image("sky.exr"), "sky.exr");
// Cost:  six faces' texels and MIP chains (8/7 of 6 N^2 RGBA floats); one pass a face to make them.
#include "texture/mip.h"
#include <string>
#include <vector>

namespace tf {

// The cube-only names, then every 2D procedural name (core/procedural.h), for --help text:
//   cube-labels  a checker of its own hue a face, with a white bar along the face's t = 0 edge, a black dot
//                around (s, t) = (0.25, 0.25) and face index + 1 white squares in a row at t = 0.75: a
//                swapped, flipped or rotated face changes many texels, and each face says which it is.
//   cube-hash    every texel of every face its own colour, an integer hash of (face, i, j).
//   cube-smooth  each texel 0.5 (d / |d| + 1) of the direction d through its centre, alpha 1: a smooth
//                function of direction (the seamlessness tests' texture).
//   NAME         (any 2D procedural name) six faces of that pattern, face f multiplied by cube_face_tint(f);
//                mipcolors keeps its flat per-level colours (tinted), every other chain is built by
//                build_cube_map.
const std::vector<std::string>& procedural_cube_names();
bool is_procedural_cube(const std::string& name);

// The colour face f's copy of a 2D pattern is multiplied by: mild, distinct per face (f in 0..5).
glm::vec4 cube_face_tint(int face);

// A cube of `size` x `size` faces with every face's full chain. Throws tf::Error for an unknown name (listing
// the valid ones) or a size outside [1, 16384] (as make_procedural).
CubeMap make_procedural_cube(const std::string& name, int size);

// Where face f sits in a horizontal cross, in faces (column 0..3, row 0..2): row 0 +Y at column 1; row 1
// -X, +Z, +X, -Z; row 2 -Y at column 1. With Vulkan's face orientation this unfolds the cube without flips.
struct CrossCell {
    int column = 0, row = 0;
};
CrossCell cross_cell(int face);

// The six faces of a horizontal cross (4:3, face side width / 4 = height / 3), each copied as it is, and
// their chains. Throws tf::Error naming `name` (the file) for a size that is not such a cross.
CubeMap cube_from_cross(const Image& cross, const std::string& name);

} // namespace tf
