// height_field { file | function resolution  smooth  water_level }: POV-Ray's meaning of the
// image (its bottom row at z = 0, its top row at z = 1; brightness is height) so scenes and
// images carry over unchanged.
#include "render/builder/height_field_builder.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "render/geometry/function/compiled_function.hpp"
#include "render/geometry/shapes/height_field.hpp"
#include "render/image/image.hpp"
#include "render/scene/resource_limits.hpp"

namespace rts::render {

namespace {

// A side of the grid: at most this many samples (a 16384 x 16384 grid is 1 GiB of floats).
constexpr long long kMaxSide = 16384;

// Samples along x and z from `resolution`: a whole number n (n x n) or a list [nx, nz].
void resolution_of(ParamSet& ps, int& nx, int& nz) {
  nx = nz = 256;
  const ParamValue* v = ps.value("resolution");
  if (!v) return;
  auto bad = [&](const std::string& got) {
    throw SceneError(loc_of(ps, "resolution"),
                     fmt::format("property 'resolution' of height_field must be a whole number from 2 to {} or a "
                                 "list [nx, nz] of them, got {}",
                                 kMaxSide, got));
  };
  auto side = [&](double x) {
    if (!(x >= 2.0 && x <= kMaxSide && x == std::floor(x))) bad(fmt::format("{}", x));
    return static_cast<int>(x);
  };
  if (const double* n = std::get_if<double>(v)) {
    nx = nz = side(*n);
  } else if (const auto* l = std::get_if<std::vector<double>>(v); l && l->size() == 2) {
    nx = side((*l)[0]);
    nz = side((*l)[1]);
  } else {
    bad(fmt::format("a {}", param_type_name(*v)));
  }
}

}  // namespace

HeightField build_height_field(ParamSet& ps, const std::string& path, std::size_t max_memory) {
  HeightField g;
  g.smooth = ps.boolean("smooth", g.smooth);
  g.water_level = ps.number("water_level", g.water_level);
  require(ps, "water_level", g.water_level >= 0.0 && g.water_level <= 1.0, "from 0 to 1", g.water_level);
  const bool has_file = ps.has("file"), has_function = ps.has("function");
  if (has_file == has_function)
    ps.fail_block(has_file ? "height_field takes either 'file' or 'function', not both"
                           : "height_field needs property 'file' (an image) or 'function' (a macro of a point, e.g. "
                             "macro h(p) { return 0.5 + 0.3 * sin(10 * p.x) })");
  int nx = 0, nz = 0;
  std::vector<float> heights;
  auto fits = [&](long long w, long long h) {
    std::size_t bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * (sizeof(float) + (g.smooth ? 12 : 0));
    if (!memory_fits(max_memory, bytes))
      ps.fail_block(fmt::format("height_field: a {} x {} grid needs {} MB, more than --max-memory leaves", w, h,
                                bytes >> 20));
  };
  if (has_file) {
    if (ps.has("resolution"))
      throw SceneError(loc_of(ps, "resolution"),
                       "property 'resolution' of height_field goes with 'function' (an image has its own size)");
    ps.string("file", "");
    // Linear: a pixel's code is its height (no sRGB decoding).
    // An unreadable image is a located scene error here, as a bad parameter is: the image is
    // read while the scene is evaluated, where only scene errors become diagnostics (fuzz_eval
    // found a missing file escaping as an unlocated 'internal error').
    Image img;
    try {
      img = read_image(path, loc_of(ps, "file"), Encoding::Linear, max_memory);
    } catch (const RenderError& e) {
      throw SceneError(loc_of(ps, "file"), e.what());
    }
    if (img.width < 2 || img.height < 2 || img.width > kMaxSide || img.height > kMaxSide)
      throw SceneError(loc_of(ps, "file"), fmt::format("height_field image '{}' is {} x {} pixels: it needs 2 to {} "
                                                       "on each side",
                                                       path, img.width, img.height, kMaxSide));
    fits(img.width, img.height);
    nx = img.width;
    nz = img.height;
    // Grey images give their grey level; colour images POV-Ray's 8-bit rule, red the high byte
    // and green the low byte of a 16-bit height.
    bool grey = true;
    for (std::size_t i = 0; grey && i < img.rgb.size(); i += 3)
      grey = img.rgb[i] == img.rgb[i + 1] && img.rgb[i] == img.rgb[i + 2];
    heights.resize(static_cast<std::size_t>(nx) * nz);
    for (int iz = 0; iz < nz; ++iz)
      for (int ix = 0; ix < nx; ++ix) {
        const float* px = img.at(ix, nz - 1 - iz);  // the image's bottom row is z = 0
        float h = grey ? px[0]
                       : static_cast<float>((std::round(std::clamp(px[0], 0.0f, 1.0f) * 255.0) * 256.0 +
                                             std::round(std::clamp(px[1], 0.0f, 1.0f) * 255.0)) /
                                            65535.0);
        heights[static_cast<std::size_t>(iz) * nx + ix] = std::clamp(h, 0.0f, 1.0f);
      }
  } else {
    const ParamValue* f = ps.value("function");
    auto* ref = std::get_if<FunctionRef>(f);
    if (!ref || !ref->function)
      throw SceneError(loc_of(ps, "function"),
                       fmt::format("property 'function' of height_field expects a macro of one point, got a {}",
                                   param_type_name(*f)));
    resolution_of(ps, nx, nz);
    fits(nx, nz);
    heights.resize(static_cast<std::size_t>(nx) * nz);
    for (int iz = 0; iz < nz; ++iz)
      for (int ix = 0; ix < nx; ++ix) {
        double h = ref->function->eval(glm::dvec3(static_cast<double>(ix) / (nx - 1), 0.0,
                                                  static_cast<double>(iz) / (nz - 1)));
        heights[static_cast<std::size_t>(iz) * nx + ix] = static_cast<float>(std::isfinite(h) ? std::clamp(h, 0.0, 1.0) : 0.0);
      }
  }
  g.data = make_height_field_data(nx, nz, std::move(heights), g.smooth);
  return g;
}

}  // namespace rts::render
