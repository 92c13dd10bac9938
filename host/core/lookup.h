#pragma once
// One point lookup, the unit every filter answers: what the GPU harness, the CPU reference and the
// lookups CSV all exchange.

namespace tf {

// uv in [0,1] texture space, gradients per pixel (d(u,v)/dx and d(u,v)/dy) in uv units.
struct Lookup {
    double u = 0, v = 0;
    double dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
};

} // namespace tf
