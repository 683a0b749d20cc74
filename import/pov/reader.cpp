#include "import/pov/reader.hpp"

#include <cstdlib>
#include <set>

#include <fmt/format.h>

#include "import/pov/reader_parser.hpp"

namespace rts::import::pov {

namespace detail {

bool is_raw_block(const std::string& kind) {
  static const std::set<std::string> raw = {"function", "spline", "sphere_sweep", "polygon", "bicubic_patch",
                                            "julia_fractal", "parametric", "ovus", "lemon", "polynomial"};
  return raw.count(kind) > 0;
}

bool is_builtin_value(const std::string& n) {
  static const std::set<std::string> names = {
      "x", "y", "z", "t", "u", "v", "pi", "tau", "true", "false", "yes", "no", "on", "off", "clock", "clock_delta",
      "clock_on", "frame_number", "initial_clock", "final_clock", "initial_frame", "final_frame", "image_width",
      "image_height", "version", "now", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft", "color",
      "colour", "array", "abs", "acos", "acosh", "asc", "asin", "asinh", "atan", "atan2", "atanh", "bitwise_and",
      "bitwise_or", "bitwise_xor", "ceil", "chr", "concat", "cos", "cosh", "datetime", "defined", "degrees",
      "dimension_size", "dimensions", "div", "exp", "file_exists", "floor", "int", "inside", "ln", "log", "max",
      "min", "mod", "pow", "prod", "radians", "rand", "seed", "select", "sin", "sinh", "sqr", "sqrt", "str",
      "strcmp", "strlen", "strlwr", "strupr", "substr", "sum", "tan", "tanh", "trace", "val", "vaxis_rotate",
      "vcross", "vdot", "vlength", "vnormalize", "vrotate", "vstr", "vturbulence", "min_extent", "max_extent",
      "eval_pigment", "internal"};
  return names.count(n) > 0;
}

bool all_lowercase(const std::string& n) {
  for (char c : n)
    if (c >= 'A' && c <= 'Z') return false;
  return true;
}

std::vector<Item> Reader::items(const Block* in_block, std::set<std::string> stops) {
  std::vector<Item> out;
  while (true) {
    const Token& t = peek();
    if (t.kind == Token::End) break;
    if (t.kind == Token::Punct && t.text == "}") break;
    if (t.kind == Token::Directive && stops.count(t.text)) break;
    if (accept(";") || accept(",")) continue;
    out.push_back(item(in_block));
  }
  return out;
}

Item Reader::item(const Block* in_block) {
  const Token& t = peek();
  Deeper d(*this, t.loc);
  Item it;
  it.loc = t.loc;
  it.comments = t.comments;
  if (t.kind == Token::Directive) return directive();
  if (t.kind == Token::Name && t.text == "function") {
    // function { ... }, function(x, y) { ... }, function 300, 300 { ... } (height fields)
    next();
    it.kind = Item::Nested;
    it.name = "function";
    it.block = std::make_shared<Block>();
    it.block->kind = "function";
    it.block->loc = t.loc;
    function_header(*it.block);
    if (is_punct("{")) function_body(*it.block);
    return it;
  }
  if (t.kind == Token::Name && is_punct("{", 1)) {
    it.kind = Item::Nested;
    it.name = t.text;
    it.block = block();
    return it;
  }
  if (t.kind == Token::Name && !name_is_value(t.text)) {
    it.kind = Item::Keyword;
    it.name = next().text;
    // A few keywords take a value that is itself a keyword-led item (`image_map { png "f" }`
    // has its own block); here only plain values.
    if (starts_value()) {
      // `matrix <a, ..., l>` has 12 components (the translation checks the count).
      const bool saved_long = long_vectors_;
      if (it.name == "matrix") long_vectors_ = true;
      it.args.push_back(expr());
      long_vectors_ = saved_long;
      // area_light's four values may go without commas: <4 0 0> <0 0 4> 10 10.
      const bool spaced = it.name == "area_light";
      while (is_punct(",") || (spaced && it.args.size() < 4 && starts_value())) {
        std::size_t save = pos_;
        accept(",");
        if (!starts_value()) {
          pos_ = save;
          break;
        }
        it.args.push_back(expr());
      }
    }
    return it;
  }
  if (t.kind == Token::Punct && t.text == "[" && in_block) {
    // A map entry: `[0.5 color Red]`, `[0.3, 0.6 color A color B]`.
    Loc open = next().loc;
    it.kind = Item::MapEntry;
    it.block = std::make_shared<Block>();
    it.block->kind = "entry";
    it.block->loc = open;
    while (!is_punct("]")) {
      if (peek().kind == Token::End) fail(open, "unterminated map entry: '[' without ']'");
      if (accept(",") || accept(";")) continue;
      it.block->items.push_back(item(it.block.get()));
    }
    next();
    return it;
  }
  if (t.kind == Token::Punct && t.text == "}") fail(t.loc, "unexpected '}'");
  if (!starts_value()) {
    if (t.kind == Token::Punct) fail(t.loc, fmt::format("unexpected '{}'", t.text));
    fail(t.loc, fmt::format("unexpected {}", describe(t)));
  }
  it.kind = Item::Value;
  it.args.push_back(expr());
  return it;
}

std::shared_ptr<Block> Reader::block() {
  auto b = std::make_shared<Block>();
  Token kind = next();
  b->kind = kind.text;
  b->loc = kind.loc;
  Loc open = peek().loc;
  expect("{", "to open the block");
  if (is_raw_block(b->kind)) {
    // Skip to the matching brace: function/spline syntax and the shapes rts does not have
    // are not read (the writer warns).
    --pos_;
    skip_braces();
    return b;
  }
  // A poly's, quartic's or cubic's coefficients are one vector of up to 84 components.
  const bool saved_long = long_vectors_;
  long_vectors_ = b->kind == "poly" || b->kind == "quartic" || b->kind == "cubic";
  b->items = items(b.get(), {});
  long_vectors_ = saved_long;
  if (!accept("}"))
    fail(peek().loc, fmt::format("expected '}}' to close the '{}' block opened at line {}, got {}", b->kind,
                                 open.line, describe(peek())));
  return b;
}

void Reader::function_header(Block& f) {
  if (is_punct("(")) {
    Item params;
    params.kind = Item::Keyword;
    params.name = "params";
    params.loc = next().loc;
    while (peek().kind == Token::Name) {
      auto n = std::make_shared<Expr>();
      n->kind = Expr::Name;
      n->loc = peek().loc;
      n->text = next().text;
      for (const ExprPtr& p : params.args)
        if (p->text == n->text) fail(n->loc, fmt::format("the function's parameter '{}' is named twice", n->text));
      params.args.push_back(n);
      if (!accept(",")) break;
    }
    if (accept(")")) f.items.push_back(std::move(params));
  } else if (starts_value()) {
    std::size_t save = pos_;
    try {
      Item res;
      res.kind = Item::Keyword;
      res.name = "resolution";
      res.loc = peek().loc;
      res.args.push_back(expr());
      if (accept(",")) res.args.push_back(expr());
      f.items.push_back(std::move(res));
    } catch (const SyntaxError&) {
      pos_ = save;
    }
  }
  while (!is_punct("{") && peek().kind != Token::End && !is_punct("}")) next();
}

void Reader::function_body(Block& f) {
  const std::size_t save = pos_;
  const int save_paren = paren_;
  try {
    next();  // {
    Item body;
    body.kind = Item::Value;
    body.loc = peek().loc;
    ++paren_;  // comparisons and ?: read as in parentheses, as POV-Ray's functions allow
    body.args.push_back(expr());
    --paren_;
    if (accept("}")) {
      f.items.push_back(std::move(body));
      return;
    }
  } catch (const SyntaxError&) {
  }
  paren_ = save_paren;
  pos_ = save;
  skip_braces();
}

void Reader::skip_braces() {
  Loc open = peek().loc;
  next();
  int depth = 1;
  while (depth > 0) {
    const Token& t = next();
    if (t.kind == Token::End) fail(open, "'{' never closed");
    if (t.kind == Token::Punct && t.text == "{") ++depth;
    if (t.kind == Token::Punct && t.text == "}") --depth;
  }
}

}  // namespace detail

bool is_statement_keyword(const std::string& n) {
  // POV-Ray's keywords that never begin a value. Names not listed here (user identifiers,
  // colour names from colors.inc, x/y/z, pi, rgb, functions) may.
  static const std::set<std::string> k = {
      "adaptive", "agate", "agate_turb", "all", "all_intersections", "alpha", "altitude", "ambient",
      "ambient_light", "angle", "aperture", "arc_angle", "area_light", "assumed_gamma", "average", "b_spline",
      "background", "bezier_spline", "bicubic_patch", "black_hole", "blob", "blur_samples", "bounded_by", "box",
      "boxed", "bozo", "brick", "brick_size", "brightness", "brilliance", "bump_map", "bump_size", "bumps",
      "camera", "caustics", "cells", "checker", "circular", "clipped_by", "collect", "color", "colour",
      "color_map", "colour_map", "component", "composite", "cone", "confidence", "conic_sweep",
      "conserve_energy", "contained_by", "control0", "control1", "crackle", "crand", "cube", "cubic",
      "cubic_spline", "cubic_wave", "cutaway_textures", "cylinder", "cylindrical", "density", "density_file",
      "density_map", "dents", "difference", "diffuse", "direction", "disc", "dispersion",
      "dispersion_samples", "dist_exp", "distance", "double_illuminate", "eccentricity", "emission",
      "error_bound", "evaluate", "exponent", "extinction", "face_indices", "facets", "fade_color",
      "fade_colour", "fade_distance", "fade_power", "falloff", "falloff_angle", "filter", "finish", "fisheye",
      "flatness", "flip", "focal_point", "fog", "fog_alt", "fog_offset", "fog_type", "form", "fresnel",
      "frequency", "gather", "global_lights", "global_settings", "gradient", "granite", "gray_threshold",
      "height_field", "hexagon", "hf_gray_16", "hierarchy", "hollow", "hypercomplex", "image_map",
      "image_pattern", "interior", "interior_texture", "interpolate", "intersection", "intervals", "inverse",
      "ior", "irid", "irid_wavelength", "isosurface", "jitter", "jpeg", "julia", "julia_fractal", "lambda",
      "lathe", "leopard", "light_group", "light_source", "linear_spline", "linear_sweep", "load_file",
      "location", "look_at", "looks_like", "low_error_factor", "magnet", "major_radius", "mandel", "map_type",
      "marble", "material", "material_map", "matrix", "max_extent", "max_gradient", "max_intersections",
      "max_iteration", "max_sample", "max_trace", "max_trace_level", "media", "media_attenuation",
      "media_interaction", "merge", "mesh", "mesh2", "metallic", "method", "metric", "min_extent",
      "minimum_reuse", "mm_per_unit", "mortar", "natural_spline", "nearest_count", "no", "no_bump_scale",
      "no_image", "no_radiosity", "no_reflection", "no_shadow", "noise_generator", "normal", "normal_indices",
      "normal_map", "normal_vectors", "number_of_waves", "object", "octaves", "offset", "omega",
      "omnimax", "once", "onion", "open", "orient", "orientation", "orthographic", "panoramic", "parallel",
      "parametric", "pass_through", "pattern", "perspective", "pgm", "phase", "phong", "phong_size",
      "photons", "pigment", "pigment_map", "pigment_pattern", "planar", "plane", "png", "point_at", "poly",
      "poly_wave", "polygon", "ppm", "precision", "precompute", "pretrace_end", "pretrace_start", "prism",
      "projected_through", "quadratic_spline", "quadric", "quartic", "quaternion", "quick_color",
      "quick_colour", "quilted", "radial", "radiosity", "radius", "ramp_wave", "ratio", "recursion_limit",
      "reflection", "reflection_exponent", "refraction", "repeat", "right", "ripples", "rotate", "roughness",
      "samples", "save_file", "scale", "scallop_wave", "scattering", "shadowless", "sine_wave", "sky",
      "sky_sphere", "slice", "slope", "slope_map", "smooth", "smooth_triangle", "solid", "sor", "spacing",
      "specular", "sphere", "sphere_sweep", "spherical", "spiral1", "spiral2", "spotlight", "spotted",
      "sturm", "superellipsoid", "tga", "thickness", "threshold", "tiff", "tightness", "tile2", "tiles",
      "tolerance", "toroidal", "torus", "transform", "translate", "transmit", "triangle", "triangle_wave",
      "triangular", "ttf", "turb_depth", "turbulence", "type", "u_steps", "ultra_wide_angle", "up",
      "use_alpha", "use_color", "use_colour", "use_index", "uv_indices", "uv_mapping", "uv_vectors",
      "v_steps", "variance", "vertex_vectors", "warp", "water_level", "waves", "width", "wood", "wrinkles",
      "texture", "texture_list", "texture_map", "text", "union", "cubic", "photons", "split_union",
      "max_trace_level", "adc_bailout", "number_of_waves", "charset", "hf_gray_16", "irid", "noise_generator",
      "subsurface", "mm_per_unit", "inside_vector", "bounded_by", "ovus", "lemon", "hollow", "double_illuminate",
      "radiosity", "importance", "nearest_count", "always_sample", "count", "error_bound", "gray_threshold",
      "recursion_limit", "emission", "albedo", "collect", "gather", "spacing", "jitter", "autostop",
      "expand_thresholds", "target", "reflection", "refraction", "pass_through", "split_union",
      "sys", "uv_mapping", "shadowless", "media_attenuation", "media_interaction", "fade_colour"};
  return k.count(n) > 0;
}

Program read_program(const std::string& text, const std::string& file, std::set<std::string>& declared) {
  detail::Reader r(text, declared);
  return r.program(file);
}

}  // namespace rts::import::pov
