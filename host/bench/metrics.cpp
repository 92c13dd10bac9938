#include "bench/metrics.h"
#include "texture/error.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace tf {

namespace {

void check_same_size(const Image& a, const Image& b)
{
    if (a.width != b.width || a.height != b.height || a.texels.size() != b.texels.size())
        throw Error("benchmark: images of different sizes compared (" + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" + std::to_string(b.height) + ")");
}

// A filter that writes NaN or Inf must not pass for black or white (the display transform clamps).
bool all_finite(const Image& image)
{
    for (const glm::vec4& t : image.texels)
        if (!std::isfinite(t.r) || !std::isfinite(t.g) || !std::isfinite(t.b))
            return false;
    return true;
}

} // namespace

TimeSummary summarize_times(std::vector<double> ms)
{
    if (ms.empty())
        throw Error("benchmark: no frame times to summarize");
    std::sort(ms.begin(), ms.end());
    size_t n = ms.size();
    double median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
    return {ms.front(), median, ms.back(), int(n)};
}

double display_rmse(const Image& image, const Image& truth)
{
    check_same_size(image, truth);
    if (!all_finite(image) || !all_finite(truth))
        return NAN;
    Image a = encode_srgb(image), b = encode_srgb(truth);
    double sum = 0;
    for (size_t i = 0; i < a.texels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double d = double(a.texels[i][c]) - double(b.texels[i][c]);
            sum += d * d;
        }
    return std::sqrt(sum / (3.0 * double(a.texels.size())));
}

double psnr_from_rmse(double rmse)
{
    if (!std::isfinite(rmse))
        return NAN;
    return rmse < 1e-5 ? 99.0 : std::min(99.0, -20.0 * std::log10(rmse));
}

double display_flicker(const std::vector<Image>& frames, const std::vector<Image>& truth)
{
    if (frames.size() != truth.size() || frames.size() < 2)
        throw Error("benchmark: flicker needs two or more frames of the filter and of the truth, as many of each");
    std::vector<Image> f, g;
    for (size_t t = 0; t < frames.size(); ++t) {
        check_same_size(frames[t], truth[t]);
        if (!all_finite(frames[t]) || !all_finite(truth[t]))
            return NAN;
        f.push_back(encode_srgb(frames[t]));
        g.push_back(encode_srgb(truth[t]));
    }
    double sum = 0;
    size_t count = 0;
    for (size_t t = 0; t + 1 < f.size(); ++t)
        for (size_t i = 0; i < f[t].texels.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                double change = double(f[t + 1].texels[i][c]) - double(f[t].texels[i][c]);
                double truth_change = double(g[t + 1].texels[i][c]) - double(g[t].texels[i][c]);
                sum += (change - truth_change) * (change - truth_change);
                ++count;
            }
    return std::sqrt(sum / double(count));
}

// %.6g, as the CSV has always been written; empty for a non-finite value.
std::string csv_number(double value)
{
    if (!std::isfinite(value))
        return "";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::string utc_date()
{
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
    return text;
}

} // namespace tf
