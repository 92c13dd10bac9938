#pragma once
// The benchmark's measures: frame-time summaries, and error and flicker against ground truth. Errors are
// in display units: linear RGB clamped to [0,1] and sRGB-encoded, alpha ignored (what a viewer sees).
#include "texture/image.h"
#include <string>
#include <vector>

namespace tf {

struct TimeSummary {
    double min = 0, median = 0, max = 0; // milliseconds
    int frames = 0;                      // how many were timed
};
TimeSummary summarize_times(std::vector<double> ms); // throws tf::Error on an empty list

// Root-mean-square difference over every pixel and RGB channel, in sRGB-encoded units; NaN when either
// image holds a non-finite value (so the result is reported, as null, rather than clamped away).
double display_rmse(const Image& image, const Image& truth);

// 20 log10(1 / rmse), capped at 99 dB (rmse below 1e-5 is float noise, not a difference worth ranking);
// NaN for NaN.
double psnr_from_rmse(double rmse);

// Temporal flicker: the RMS over frame pairs, pixels and RGB of the change a filter shows from one frame
// of a camera path to the next, minus the change the ground truth shows (display units). Motion itself
// costs nothing; popping, crawling and shimmering that the truth does not have do. NaN as display_rmse.
double display_flicker(const std::vector<Image>& frames, const std::vector<Image>& truth);

// A number as the CSVs write it: %.6g, empty for a non-finite value.
std::string csv_number(double value);
// Today in UTC, YYYY-MM-DD.
std::string utc_date();

} // namespace tf
