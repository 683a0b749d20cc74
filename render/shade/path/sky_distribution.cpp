#include "render/shade/path/sky_distribution.hpp"

#include <algorithm>
#include <cmath>

namespace rts::render::path {

Vec3 SkyDistribution::direction(double theta, double phi) {
  double s = std::sin(theta);
  return {s * std::cos(phi), std::cos(theta), s * std::sin(phi)};
}

SkyDistribution::SkyDistribution(const std::function<double(const Vec3&)>& luminance, int columns, int rows,
                                 double uniform_share)
    : columns_(columns), rows_(rows), uniform_share_(uniform_share) {
  const std::size_t cells = static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
  prob_.assign(cells, 0.0);
  cdf_.assign(cells, 0.0);
  const double dtheta = kPi / rows, dphi = 2.0 * kPi / columns;
  double total = 0.0;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      // The mean of a 2x2 set of lookups inside the cell, times the cell's solid angle.
      double sum = 0.0;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          double l = luminance(direction((r + 0.25 + 0.5 * j) * dtheta, (c + 0.25 + 0.5 * i) * dphi));
          if (std::isfinite(l) && l > 0.0) sum += l;
        }
      double solid_angle = dphi * (std::cos(r * dtheta) - std::cos((r + 1) * dtheta));
      double w = 0.25 * sum * solid_angle;
      std::size_t k = static_cast<std::size_t>(r) * columns + c;
      prob_[k] = w;
      total += w;
      cdf_[k] = total;
    }
  if (!(total > 0.0) || !std::isfinite(total)) {
    uniform_share_ = 1.0;   // a black sky: nothing to prefer
    return;
  }
  for (std::size_t k = 0; k < cells; ++k) {
    prob_[k] /= total;
    cdf_[k] /= total;
  }
}

int SkyDistribution::cell_of(const Vec3& d) const {
  double theta = std::acos(std::clamp(d.y, -1.0, 1.0));
  double phi = std::atan2(d.z, d.x);
  if (phi < 0.0) phi += 2.0 * kPi;
  int r = std::min(rows_ - 1, static_cast<int>(theta / kPi * rows_));
  int c = std::min(columns_ - 1, static_cast<int>(phi / (2.0 * kPi) * columns_));
  return r * columns_ + c;
}

double SkyDistribution::grid_pdf(int cell, double sin_theta) const {
  // Uniform in (theta, phi) within the cell: density prob / (dtheta dphi sin theta).
  const double dtheta = kPi / rows_, dphi = 2.0 * kPi / columns_;
  if (!(sin_theta > 1e-12)) return 0.0;
  return prob_[static_cast<std::size_t>(cell)] / (dtheta * dphi * sin_theta);
}

Vec3 SkyDistribution::sample(glm::dvec2 u, double& pdf_out) const {
  Vec3 d;
  if (u.x < uniform_share_) {
    d = uniform_sphere({u.x / uniform_share_, u.y});
  } else {
    double v = (u.x - uniform_share_) / (1.0 - uniform_share_);
    auto it = std::lower_bound(cdf_.begin(), cdf_.end(), v);
    std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(it - cdf_.begin()), cdf_.size() - 1);
    while (k + 1 < cdf_.size() && prob_[k] <= 0.0) ++k;   // land on a cell that has weight
    double lo = k == 0 ? 0.0 : cdf_[k - 1];
    double within = prob_[k] > 0.0 ? std::clamp((v - lo) / prob_[k], 0.0, 1.0) : 0.5;
    int r = static_cast<int>(k) / columns_, c = static_cast<int>(k) % columns_;
    const double dtheta = kPi / rows_, dphi = 2.0 * kPi / columns_;
    d = direction((r + within) * dtheta, (c + u.y) * dphi);
  }
  pdf_out = pdf(d);
  return d;
}

double SkyDistribution::pdf(const Vec3& d) const {
  double uniform = uniform_share_ / (4.0 * kPi);
  if (uniform_share_ >= 1.0) return uniform;
  double sin_theta = std::sqrt(std::max(0.0, 1.0 - d.y * d.y));
  return uniform + (1.0 - uniform_share_) * grid_pdf(cell_of(d), sin_theta);
}

}  // namespace rts::render::path
