// idiff-style comparison. Statistics are accumulated in double so that a 16k² image's mean is exact
// enough to quote.
#include "core/diff.h"

#include "texture/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace tf {
namespace {

void check_same_size(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error("image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
                    std::to_string(b.width) + "x" + std::to_string(b.height));
}

// |a - b|, except that a NaN on one side only counts as an infinite difference: a regression that
// starts producing NaN must fail, not vanish from every statistic. Equal infinities are equal.
double channel_diff(float a, float b) {
    if (a == b) return 0.0;
    if (std::isnan(a) || std::isnan(b))
        return std::isnan(a) && std::isnan(b) ? 0.0 : std::numeric_limits<double>::infinity();
    return std::fabs(double(a) - double(b));
}

// "%.3g" with the exponent's padding removed: 1.2e-4 rather than 1.2e-04.
std::string number(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    std::string s = buf;
    const size_t e = s.find('e');
    if (e != std::string::npos) {
        size_t digits = e + 1;
        if (digits < s.size() && (s[digits] == '-' || s[digits] == '+')) {
            if (s[digits] == '+') s.erase(digits, 1);
            else ++digits;
        }
        while (digits + 1 < s.size() && s[digits] == '0') s.erase(digits, 1);
    }
    return s;
}

} // namespace

DiffResult diff_images(const Image& a, const Image& b, const DiffThresholds& thresholds) {
    check_same_size(a, b);
    DiffResult r;
    double sum = 0, sum_sq = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            double pixel_max = 0;
            for (int c = 0; c < 4; ++c) {
                const double d = channel_diff(a.at(x, y)[c], b.at(x, y)[c]);
                sum += d;
                sum_sq += d * d;
                pixel_max = std::max(pixel_max, d);
            }
            if (pixel_max > r.max_error) {  // strict: the first pixel (row-major) attaining the max
                r.max_error = pixel_max;
                r.max_x = x;
                r.max_y = y;
            }
            if (pixel_max > thresholds.fail) ++r.fail_count;
        }
    }
    const double pixels = double(a.width) * double(a.height);
    const double values = pixels * 4.0;
    if (values > 0) {
        r.mean_error = sum / values;
        r.rms_error = std::sqrt(sum_sq / values);
        r.fail_percent = 100.0 * double(r.fail_count) / pixels;
    }
    r.psnr = r.rms_error == 0 ? std::numeric_limits<double>::infinity() : 20.0 * std::log10(1.0 / r.rms_error);
    r.pass = r.fail_percent <= thresholds.fail_percent && r.max_error <= thresholds.hard_fail;
    return r;
}

Image diff_image(const Image& a, const Image& b, double gain) {
    check_same_size(a, b);
    Image out = make_image(a.width, a.height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    for (size_t i = 0; i < out.texels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = channel_diff(a.texels[i][c], b.texels[i][c]) * gain;
            out.texels[i][c] = float(std::clamp(std::isnan(d) ? 1.0 : d, 0.0, 1.0));  // NaN: 0 * inf gain
        }
    return out;
}

std::string describe(const DiffResult& r, const DiffThresholds& t) {
    std::string s;
    s += "max error " + number(r.max_error) + " at (" + std::to_string(r.max_x) + ", " + std::to_string(r.max_y) +
         ")\n";
    char psnr[32];
    if (std::isinf(r.psnr)) std::snprintf(psnr, sizeof psnr, "%s", r.psnr > 0 ? "inf" : "-inf");
    else std::snprintf(psnr, sizeof psnr, "%.1f", r.psnr);
    s += "mean " + number(r.mean_error) + "  RMS " + number(r.rms_error) + "  PSNR " + psnr + " dB\n";
    s += std::to_string(r.fail_count) + " pixels (" + number(r.fail_percent) + "%) over " + number(t.fail) +
         " (allowed " + number(t.fail_percent) + "%), hard limit " +
         (t.hard_fail >= 1e30 ? std::string("none") : number(t.hard_fail)) + "\n";
    s += r.pass ? "PASS" : "FAIL";
    return s;
}

} // namespace tf
