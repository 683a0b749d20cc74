// Error of an image against a reference, in linear RGB over all pixels and channels, and the
// least-squares slope used to read convergence curves.
#pragma once

#include <vector>

#include "render/image/image.hpp"

namespace rts::render {

struct ImageError {
  double mse = 0;      // mean of (x - ref)^2
  double rmse = 0;
  double rel_mse = 0;  // mean of (x - ref)^2 / (ref^2 + kRelMseEpsilon)
  double psnr = 0;     // 10 log10(1 / mse), peak 1 (linear); +inf when equal
};

// Throws RenderError when the sizes differ.
ImageError image_error(const Image& image, const Image& reference);

// Least-squares slope of log(y) against log(x) over the points with x, y > 0; NaN with
// fewer than two such points.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

// y at x on the piecewise log-log line through (xs, ys) (xs ascending after sorting by x);
// NaN outside [min x, max x].
double log_log_interpolate(std::vector<double> xs, std::vector<double> ys, double x);

}  // namespace rts::render
