// Helpers shared by the three translators.
#pragma once

#include <filesystem>
#include <string>

#include <glm/glm.hpp>

#include "import/import.hpp"
#include "import/writer.hpp"

namespace rts::import {

// A path named in the input (relative to the input's folder) as the output must name it.
inline std::string relocate(const std::string& path, const ImportOptions& o) {
  namespace fs = std::filesystem;
  fs::path p(path);
  if (p.is_absolute()) return path;
  fs::path full = (fs::path(o.source_dir) / p).lexically_normal();
  fs::path out_dir = o.output_dir.empty() ? fs::path(".") : fs::path(o.output_dir);
  std::error_code ec;
  fs::path rel = fs::relative(fs::absolute(full, ec), fs::absolute(out_dir, ec), ec);
  return ec || rel.empty() ? full.generic_string() : rel.generic_string();
}

// The extra images the options ask for, as settings properties ("  aov = ..." or empty):
// depth mapped NEAR..FAR to black..white (misses black), normals as (n + 1) / 2 with
// `normal_miss` where nothing is hit.
inline std::string aov_settings(const ImportOptions& o, double normal_miss) {
  std::string out;
  if (!o.aovs.empty()) out += "  aov = " + rts_string(o.aovs);
  if (o.has_depth_range) out += "  depth_range = [" + num(o.depth_near) + ", " + num(o.depth_far) + "]";
  if (o.aovs.find("normal") != std::string::npos && normal_miss != 0) out += "  normal_miss = " + num(normal_miss);
  return out;
}

// Rotation by `radians` about `axis` (right-handed), as a column-vector matrix m[row][col].
inline void axis_angle(glm::dvec3 axis, double radians, double m[4][4]) {
  double len = glm::length(axis);
  if (!(len > 0)) axis = {0, 0, 1}; else axis /= len;
  double c = std::cos(radians), s = std::sin(radians), t = 1 - c;
  double x = axis.x, y = axis.y, z = axis.z;
  double r[4][4] = {{t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0},
                    {t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0},
                    {t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0},
                    {0, 0, 0, 1}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m[i][j] = r[i][j];
}

}  // namespace rts::import
