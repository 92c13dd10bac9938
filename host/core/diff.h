#pragma once
// idiff-style image comparison: per-pixel fail threshold, allowed failing percentage, hard maximum.
#include "texture/image.h"
#include <string>

namespace tf {

struct DiffThresholds {
    double fail = 1e-6;        // a pixel fails when its largest channel difference exceeds this
    double fail_percent = 0.0; // the comparison passes if at most this percentage of pixels fail ...
    double hard_fail = 1e30;   // ... and no pixel's difference exceeds this
};

struct DiffResult {
    bool pass = false;
    double max_error = 0;      // largest channel difference over all pixels
    int max_x = 0, max_y = 0;  // where it is
    double mean_error = 0;     // mean absolute difference over all pixel channels (RGB + A)
    double rms_error = 0;
    double psnr = 0;           // 20 log10(1 / rms); +inf when identical
    long long fail_count = 0;  // pixels over `fail`
    double fail_percent = 0;
};

// Compares two same-sized images channel by channel (RGBA). Throws tf::Error on a size mismatch.
DiffResult diff_images(const Image& a, const Image& b, const DiffThresholds& thresholds);

// A picture of where they differ: |a-b| scaled by `gain`, clamped to [0,1], alpha 1.
Image diff_image(const Image& a, const Image& b, double gain);

// Multi-line human summary (max with its pixel, mean, RMS, PSNR, count over threshold, PASS/FAIL).
std::string describe(const DiffResult& result, const DiffThresholds& thresholds);

} // namespace tf
