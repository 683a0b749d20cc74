#include "import/pov/reader.hpp"

#include <cstdlib>
#include <set>

#include <fmt/format.h>

namespace rts::import::pov {

namespace {

// Blocks and directives nest at most this deep: the reader and the writer recurse, and a
// hostile file must not exhaust the stack.
constexpr int kMaxNesting = 200;

// Blocks whose contents are POV-Ray's function or spline syntax: skipped as a whole (the
// writer warns), never read as items.
bool is_raw_block(const std::string& kind) {
  static const std::set<std::string> raw = {"function", "spline", "text", "sphere_sweep", "polygon", "bicubic_patch",
                                            "julia_fractal", "parametric", "quadric", "poly", "cubic", "quartic",
                                            "ovus", "lemon", "polynomial"};
  return raw.count(kind) > 0;
}

// Names that begin a value without being declared: constants and built-in functions.
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

}  // namespace

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

namespace {

class Reader {
 public:
  Reader(const std::string& text, std::set<std::string>& declared) : toks_(tokenize(text)), declared_(declared) {}

  Program program(const std::string& file) {
    Program p;
    p.file = file;
    p.items = items(nullptr, {});
    if (peek().kind != Token::End) {
      const Token& t = peek();
      if (t.kind == Token::Directive) fail(t.loc, fmt::format("'#{}' without a matching directive before it", t.text));
      fail(t.loc, fmt::format("unexpected '{}'", t.text));
    }
    p.trailing_comments = peek().comments;
    return p;
  }

 private:
  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  std::set<std::string>& declared_;  // names declared so far (this file and earlier ones)
  int depth_ = 0;
  // Inside parentheses (a condition, a call's arguments, an index): POV-Ray reads comparisons,
  // & | and ?: only there, so `box { <a> <b> }` is two vectors, not a comparison. A vector's
  // components are outside again.
  int paren_ = 0;

  // ---- tokens ----
  const Token& peek(std::size_t ahead = 0) const {
    std::size_t i = std::min(pos_ + ahead, toks_.size() - 1);
    return toks_[i];
  }
  Token next() {
    Token t = peek();
    if (pos_ < toks_.size() - 1) ++pos_;
    return t;
  }
  bool is_punct(const char* p, std::size_t ahead = 0) const {
    const Token& t = peek(ahead);
    return t.kind == Token::Punct && t.text == p;
  }
  bool accept(const char* p) {
    if (!is_punct(p)) return false;
    next();
    return true;
  }
  [[noreturn]] static void fail(Loc at, const std::string& message) { throw SyntaxError{at, message}; }
  static std::string describe(const Token& t) {
    switch (t.kind) {
      case Token::End: return "the end of the file";
      case Token::Directive: return "'#" + t.text + "'";
      case Token::String: return "a string";
      default: return "'" + t.text + "'";
    }
  }
  void expect(const char* p, const std::string& what) {
    if (!accept(p)) fail(peek().loc, fmt::format("expected '{}' {}, got {}", p, what, describe(peek())));
  }
  std::string expect_name(const std::string& what) {
    if (peek().kind != Token::Name) fail(peek().loc, fmt::format("expected {}, got {}", what, describe(peek())));
    return next().text;
  }
  struct Deeper {
    Reader& r;
    Deeper(Reader& reader, Loc at) : r(reader) {
      if (++r.depth_ > kMaxNesting) fail(at, fmt::format("nesting too deep (more than {} levels)", kMaxNesting));
    }
    ~Deeper() { --r.depth_; }
  };

  // Whether the next token can begin a value (after a keyword: is what follows its value?).
  bool starts_value() const {
    const Token& t = peek();
    switch (t.kind) {
      case Token::Number:
      case Token::String: return true;
      case Token::Punct: return t.text == "<" || t.text == "(" || t.text == "-" || t.text == "+" || t.text == "!";
      case Token::Name: return name_is_value(t.text);
      default: return false;
    }
  }

  // A name begins a value when declared, built in, or spelled like an identifier (POV-Ray's
  // keywords are lower case); an undeclared lower-case name is a keyword rts may not know.
  bool name_is_value(const std::string& n) const {
    if (is_punct("{", 1)) return false;
    if (declared_.count(n) || is_builtin_value(n)) return true;
    if (is_statement_keyword(n)) return false;
    return !all_lowercase(n) || is_punct("(", 1);
  }

  // ---- items ----
  // Reads items until '}' (in a block), the end of the file, or one of the directives in
  // `stops` (not consumed).
  std::vector<Item> items(const Block* in_block, std::set<std::string> stops) {
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

  Item item(const Block* in_block) {
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
        it.args.push_back(expr());
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

  std::shared_ptr<Block> block() {
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
    b->items = items(b.get(), {});
    if (!accept("}"))
      fail(peek().loc, fmt::format("expected '}}' to close the '{}' block opened at line {}, got {}", b->kind,
                                   open.line, describe(peek())));
    return b;
  }

  // What comes between `function` and its body: the parameters `(a, b, c)` (a Keyword item
  // "params", Name arguments) or a height field's resolution `W, H` (Keyword "resolution").
  // Anything else up to the body is skipped, as before.
  void function_header(Block& f) {
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

  // A function's body `{ expression }` as the block's Value item, when it reads as one
  // expression of the scene language (arithmetic, calls, x, y, z); otherwise (POV-Ray's
  // function-only syntax, a pattern { } inside) skipped, and the block has no body.
  void function_body(Block& f) {
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

  // Skips a balanced { ... } starting at the current '{'.
  void skip_braces() {
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

  // ---- directives ----
  std::vector<Item> body(std::set<std::string> stops) { return items(nullptr, std::move(stops)); }

  void expect_directive(const char* name, Loc opened, const std::string& what) {
    const Token& t = peek();
    if (t.kind != Token::Directive || t.text != name)
      fail(t.loc, fmt::format("expected '#{}' to close the {} at line {}, got {}", name, what, opened.line,
                              describe(t)));
    next();
  }

  ExprPtr paren_expr() {
    expect("(", "after the directive");
    ++paren_;
    ExprPtr e = expr();
    --paren_;
    expect(")", "to close the condition");
    return e;
  }

  Item directive() {
    Token t = next();
    Item it;
    it.loc = t.loc;
    it.comments = t.comments;
    const std::string& d = t.text;
    if (d == "declare" || d == "local") {
      it.kind = Item::Declare;
      it.local = d == "local";
      it.name = expect_name("a name after '#" + d + "'");
      declared_.insert(it.name);
      if (accept("[")) {  // an array element: #declare A[i] = v (A[i][j]: the first index kept)
        ++paren_;
        ExprPtr index = expr();
        --paren_;
        expect("]", "to close the index");
        while (accept("[")) {
          expr();
          expect("]", "to close the index");
        }
        it.args.resize(2);
        it.args[1] = index;
      } else {
        it.args.resize(1);
      }
      expect("=", "after the name in '#" + d + "'");
      if (peek().kind == Token::Name && peek().text == "function") {
        Item f = item(nullptr);
        auto e = std::make_shared<Expr>();
        e->kind = Expr::BlockValue;
        e->loc = f.loc;
        e->block = f.block;
        it.args[0] = e;
      } else if (peek().kind == Token::Name && is_punct("{", 1)) {
        auto e = std::make_shared<Expr>();
        e->kind = Expr::BlockValue;
        e->loc = peek().loc;
        e->block = block();
        it.args[0] = e;
      } else {
        it.args[0] = expr();
      }
      accept(";");
      return it;
    }
    if (d == "macro") {
      it.kind = Item::Macro;
      it.name = expect_name("the macro's name");
      declared_.insert(it.name);
      expect("(", "to open the macro's parameters");
      while (!is_punct(")")) {
        it.params.push_back(expect_name("a parameter name"));
        declared_.insert(it.params.back());
        if (!accept(",")) break;
      }
      expect(")", "to close the macro's parameters");
      it.body = body({"end"});
      expect_directive("end", t.loc, "'#macro'");
      return it;
    }
    if (d == "while") {
      it.kind = Item::While;
      it.args.push_back(paren_expr());
      it.body = body({"end", "break"});
      accept_break();
      expect_directive("end", t.loc, "'#while'");
      return it;
    }
    if (d == "for") {
      it.kind = Item::For;
      expect("(", "after '#for'");
      ++paren_;
      it.name = expect_name("the loop variable");
      declared_.insert(it.name);
      expect(",", "after the loop variable");
      it.args.push_back(expr());
      expect(",", "after the start value");
      it.args.push_back(expr());
      if (accept(",")) it.args.push_back(expr());
      --paren_;
      expect(")", "to close '#for'");
      it.body = body({"end", "break"});
      accept_break();
      expect_directive("end", t.loc, "'#for'");
      return it;
    }
    if (d == "if" || d == "ifdef" || d == "ifndef") {
      it.kind = Item::If;
      if (d == "if") {
        it.args.push_back(paren_expr());
      } else {
        expect("(", "after '#" + d + "'");
        auto e = std::make_shared<Expr>();
        e->kind = Expr::Name;
        e->loc = peek().loc;
        e->text = expect_name("a name");
        if (accept("[")) {  // #ifdef(A[i]): the element; read and drop the index
          expr();
          expect("]", "to close the index");
        }
        expect(")", "to close '#" + d + "'");
        it.args.push_back(e);
        it.ifdef = true;
        it.negate = d == "ifndef";
      }
      it.body = body({"else", "elseif", "end"});
      if (peek().kind == Token::Directive && peek().text == "elseif") {
        // #elseif (c) ... is an #if nested in the #else, closed by the same #end.
        Token e = peek();
        toks_[pos_].text = "if";
        Item inner = directive_elseif(e);
        it.else_body.push_back(std::move(inner));
        return it;
      }
      if (peek().kind == Token::Directive && peek().text == "else") {
        next();
        it.else_body = body({"end"});
      }
      expect_directive("end", t.loc, "'#" + d + "'");
      return it;
    }
    if (d == "switch") {
      it.kind = Item::Switch;
      it.args.push_back(paren_expr());
      while (true) {
        const Token& c = peek();
        if (c.kind != Token::Directive) {
          if (c.kind == Token::End) break;
          fail(c.loc, fmt::format("expected '#case', '#range', '#else' or '#end' in '#switch', got {}", describe(c)));
        }
        if (c.text == "end") break;
        Item cs;
        cs.kind = Item::Case;
        cs.loc = c.loc;
        cs.name = c.text;
        next();
        if (cs.name == "case") {
          cs.args.push_back(paren_expr());
        } else if (cs.name == "range") {
          expect("(", "after '#range'");
          ++paren_;
          cs.args.push_back(expr());
          expect(",", "between the range's ends");
          cs.args.push_back(expr());
          --paren_;
          expect(")", "to close '#range'");
        } else if (cs.name != "else") {
          fail(cs.loc, fmt::format("expected '#case', '#range', '#else' or '#end' in '#switch', got '#{}'", cs.name));
        }
        cs.body = body({"case", "range", "else", "break", "end"});
        accept_break();
        it.body.push_back(std::move(cs));
      }
      expect_directive("end", t.loc, "'#switch'");
      return it;
    }
    if (d == "include") {
      it.kind = Item::Include;
      if (peek().kind != Token::String) {
        // #include Name: a computed file name; the writer warns.
        it.kind = Item::Ignored;
        it.name = "include (a computed name)";
        expr();
        return it;
      }
      it.name = next().text;
      return it;
    }
    if (d == "version") {
      it.kind = Item::Version;
      it.args.push_back(expr());
      accept(";");
      return it;
    }
    if (d == "default") {
      it.kind = Item::Default;
      Loc open = peek().loc;
      expect("{", "after '#default'");
      it.block = std::make_shared<Block>();
      it.block->kind = "default";
      it.block->loc = open;
      it.block->items = items(it.block.get(), {});
      expect("}", "to close '#default'");
      return it;
    }
    if (d == "debug" || d == "warning" || d == "error" || d == "render" || d == "statistics") {
      it.kind = Item::Message;
      it.name = d;
      it.args.push_back(expr());
      return it;
    }
    if (d == "undef") {
      it.kind = Item::Ignored;
      it.name = d;
      expect_name("a name after '#undef'");
      return it;
    }
    if (d == "fopen" || d == "fclose" || d == "read" || d == "write") {
      // File input/output: skipped to the end of the statement (the writer warns).
      it.kind = Item::Ignored;
      it.name = d;
      if (d == "fopen") {
        expect_name("a file identifier");
        if (peek().kind == Token::String) next();
        if (peek().kind == Token::Name) next();
      } else if (d == "fclose") {
        expect_name("a file identifier");
      } else {
        Loc open = peek().loc;
        expect("(", "after '#" + d + "'");
        int depth = 1;
        while (depth > 0) {
          const Token& x = next();
          if (x.kind == Token::End) fail(open, "'(' without ')'");
          if (x.kind == Token::Punct && x.text == "(") ++depth;
          if (x.kind == Token::Punct && x.text == ")") --depth;
        }
      }
      return it;
    }
    if (d == "end" || d == "else" || d == "elseif" || d == "case" || d == "range" || d == "break")
      fail(t.loc, fmt::format("'#{}' without a matching directive before it", d));
    fail(t.loc, fmt::format("unknown directive '#{}'", d));
  }

  Item directive_elseif(const Token&) {
    // The current token was renamed to #if: read it as one; its #end closes the outer #if too.
    return directive();
  }

  void accept_break() {
    if (peek().kind == Token::Directive && peek().text == "break") next();
  }

  // ---- expressions ----
  ExprPtr make(Expr::Kind k, Loc at, std::string text = {}) {
    auto e = std::make_shared<Expr>();
    e->kind = k;
    e->loc = at;
    e->text = std::move(text);
    return e;
  }
  ExprPtr binary(const std::string& op, ExprPtr a, ExprPtr b, Loc at) {
    ExprPtr e = make(Expr::Binary, at, op);
    e->args = {std::move(a), std::move(b)};
    return e;
  }

  ExprPtr expr() {
    Deeper d(*this, peek().loc);
    ExprPtr c = or_expr();
    if (paren_ > 0 && is_punct("?")) {
      Loc at = next().loc;
      ExprPtr a = expr();
      expect(":", "in 'condition ? a : b'");
      ExprPtr b = expr();
      ExprPtr e = make(Expr::Ternary, at);
      e->args = {c, a, b};
      return e;
    }
    return c;
  }
  ExprPtr or_expr() {
    ExprPtr a = and_expr();
    while (paren_ > 0 && is_punct("|")) {
      Loc at = next().loc;
      a = binary("|", a, and_expr(), at);
    }
    return a;
  }
  ExprPtr and_expr() {
    ExprPtr a = cmp_expr();
    while (paren_ > 0 && is_punct("&")) {
      Loc at = next().loc;
      a = binary("&", a, cmp_expr(), at);
    }
    return a;
  }
  ExprPtr cmp_expr() {
    ExprPtr a = add_expr();
    while (paren_ > 0 && (is_punct("<") || is_punct("<=") || is_punct("=") || is_punct("!=") || is_punct(">=") ||
                          is_punct(">"))) {
      Token op = next();
      a = binary(op.text, a, add_expr(), op.loc);
    }
    return a;
  }
  ExprPtr add_expr() {
    ExprPtr a = mul_expr();
    while (is_punct("+") || is_punct("-")) {
      Token op = next();
      a = binary(op.text, a, mul_expr(), op.loc);
    }
    return a;
  }
  ExprPtr mul_expr() {
    ExprPtr a = unary_expr();
    while (is_punct("*") || is_punct("/")) {
      Token op = next();
      a = binary(op.text, a, unary_expr(), op.loc);
    }
    return a;
  }
  ExprPtr unary_expr() {
    Deeper d(*this, peek().loc);
    if (is_punct("-") || is_punct("+") || is_punct("!")) {
      Token op = next();
      ExprPtr e = make(Expr::Unary, op.loc, op.text);
      e->args.push_back(unary_expr());
      return e;
    }
    return postfix_expr();
  }
  ExprPtr postfix_expr() {
    ExprPtr e = primary();
    while (true) {
      if (is_punct(".") && peek(1).kind == Token::Name) {
        Loc at = next().loc;
        ExprPtr m = make(Expr::Member, at, next().text);
        m->args.push_back(e);
        e = m;
      } else if (is_punct("[") && e->kind != Expr::Number) {
        Loc at = next().loc;
        ExprPtr i = make(Expr::Index, at);
        ++paren_;
        i->args = {e, expr()};
        --paren_;
        expect("]", "to close the index");
        e = i;
      } else {
        return e;
      }
    }
  }
  static bool is_color_keyword(const std::string& n) {
    return n == "rgb" || n == "rgbf" || n == "rgbt" || n == "rgbft" || n == "srgb" || n == "srgbf" ||
           n == "srgbt" || n == "srgbft";
  }
  ExprPtr primary() {
    const Token& t = peek();
    Loc at = t.loc;
    switch (t.kind) {
      case Token::Number: {
        ExprPtr e = make(Expr::Number, at, t.text);
        e->number = std::strtod(t.text.c_str(), nullptr);
        next();
        return e;
      }
      case Token::String: {
        ExprPtr e = make(Expr::String, at, t.text);
        next();
        return e;
      }
      case Token::Punct:
        if (t.text == "(") {
          next();
          ++paren_;
          ExprPtr e = expr();
          --paren_;
          expect(")", "to close '('");
          return e;
        }
        if (t.text == "<") {
          next();
          ExprPtr e = make(Expr::Vector, at);
          int saved = paren_;
          paren_ = 0;
          // Components may go without commas (<4 0 0>) and end with one (<1, 2, 3,>).
          e->args.push_back(expr());
          while (!is_punct(">")) {
            bool comma = accept(",");
            if (is_punct(">")) break;
            if (!comma && !starts_value()) break;
            e->args.push_back(expr());
          }
          paren_ = saved;
          if (!accept(">"))
            fail(peek().loc, fmt::format("expected ',' or '>' in the vector opened at line {}:{}, got {}", at.line,
                                         at.col, describe(peek())));
          // POV-Ray's vectors have 2 to 5 components (a one-component <x> was written to rts,
          // which cannot read it: fuzz_pov).
          if (e->args.size() < 2 || e->args.size() > 5)
            fail(at, fmt::format("a vector has 2 to 5 components, this one {}", e->args.size()));
          return e;
        }
        break;
      case Token::Name: {
        std::string n = next().text;
        if (is_color_keyword(n)) {
          ExprPtr e = make(Expr::Color, at, n);
          e->args.push_back(unary_expr());
          return e;
        }
        if (n == "color" || n == "colour") {
          ExprPtr e = make(Expr::Color, at, "color");
          if (peek().kind == Token::Name && (peek().text == "red" || peek().text == "green" ||
                                             peek().text == "blue" || peek().text == "filter" ||
                                             peek().text == "transmit" || peek().text == "alpha")) {
            // The old form: color red R green G blue B (missing channels are 0).
            ExprPtr v = make(Expr::Vector, peek().loc);
            for (int i = 0; i < 5; ++i) {
              ExprPtr zero = make(Expr::Number, at, "0");
              v->args.push_back(zero);
            }
            while (peek().kind == Token::Name) {
              const std::string c = peek().text;
              int slot = c == "red" ? 0 : c == "green" ? 1 : c == "blue" ? 2 : c == "filter" ? 3
                       : (c == "transmit" || c == "alpha") ? 4 : -1;
              if (slot < 0) break;
              next();
              v->args[static_cast<std::size_t>(slot)] = unary_expr();
            }
            e->text = "rgbft";
            e->args.push_back(v);
            return e;
          }
          e->args.push_back(add_expr());
          return e;
        }
        if (n == "array") {
          ExprPtr e = make(Expr::Array, at);
          std::vector<ExprPtr> sizes;
          while (is_punct("[")) {
            next();
            sizes.push_back(expr());
            expect("]", "to close the array's size");
          }
          if (sizes.empty()) fail(at, "'array' needs its size in brackets: array[N] (or array[N] { values })");
          if (sizes.size() != 1) {
            // A multi-dimensional array: read over (the writer warns).
            e->text = "multi";
            if (is_punct("{")) skip_braces();
            e->args.push_back(sizes[0]);
            return e;
          }
          e->args.push_back(sizes[0]);
          if (accept("{")) {
            e->text = "init";
            while (!is_punct("}")) {
              e->args.push_back(expr());
              if (!accept(",")) break;
            }
            expect("}", "to close the array's values");
          }
          return e;
        }
        if (is_punct("(")) {
          next();
          ExprPtr e = make(Expr::Call, at, n);
          ++paren_;
          while (!is_punct(")")) {
            if (peek().kind == Token::Name && is_punct("{", 1)) {
              ExprPtr b = make(Expr::BlockValue, peek().loc);
              b->block = block();
              e->args.push_back(b);
            } else {
              e->args.push_back(expr());
            }
            if (!accept(",")) break;
          }
          --paren_;
          expect(")", "to close the call's arguments");
          return e;
        }
        return make(Expr::Name, at, n);
      }
      default: break;
    }
    fail(at, fmt::format("expected a value, got {}", describe(t)));
  }
};

}  // namespace

Program read_program(const std::string& text, const std::string& file, std::set<std::string>& declared) {
  Reader r(text, declared);
  return r.program(file);
}

}  // namespace rts::import::pov
