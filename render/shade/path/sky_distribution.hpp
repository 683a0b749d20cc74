// Importance sampling of the sky (an environment map, or any direction-dependent sky): a
// piecewise-constant density over a latitude-longitude grid of directions, each cell weighted
// by the sky's mean luminance there times its solid angle, mixed with a uniform share so no
// direction the grid under-estimates has a vanishing density. It reads the sky only through
// a direction lookup, so cube maps and rotated maps are sampled the same way.
#pragma once

#include <functional>
#include <vector>

#include "render/shade/path/warp.hpp"

namespace rts::render::path {

class SkyDistribution {
 public:
  // `luminance(direction)` of the sky; `uniform_share` of the samples ignore the grid.
  SkyDistribution(const std::function<double(const Vec3&)>& luminance, int columns = 128, int rows = 64,
                  double uniform_share = 0.1);

  // A direction for the unit square point u, and its solid-angle density.
  Vec3 sample(glm::dvec2 u, double& pdf) const;
  double pdf(const Vec3& direction) const;

 private:
  // (theta, phi) grid: theta from +y (0) to -y (pi), phi about y from +x.
  static Vec3 direction(double theta, double phi);
  int cell_of(const Vec3& direction) const;
  double grid_pdf(int cell, double sin_theta) const;

  int columns_, rows_;
  double uniform_share_;
  std::vector<double> cdf_;    // over cells, row-major, cdf_[k] = sum of weights up to k
  std::vector<double> prob_;   // each cell's probability
};

}  // namespace rts::render::path
