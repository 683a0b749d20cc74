// POV-Ray expressions as rts expressions: operators (`=` compares, `&` `|` `!`), the axis
// constants, float-to-vector promotion, colour keywords, built-in functions.
#include <cmath>
#include <numbers>
#include <map>

#include <fmt/format.h>

#include "import/pov/translator.hpp"

namespace rts::import::pov {

namespace {

std::string paren(const Text& t, int prec) { return t.prec < prec ? "(" + t.s + ")" : t.s; }

bool is_vectorish(Type t) { return t == Type::Vector || t == Type::Color; }

// POV-Ray's escapes that rts spells the same; others keep their backslash as a character.
std::string rts_escaped(const std::string& pov) {
  std::string out = "\"";
  for (std::size_t i = 0; i < pov.size(); ++i) {
    char c = pov[i];
    if (c == '\\') {
      const char n = i + 1 < pov.size() ? pov[i + 1] : '\0';
      if (n == 'n' || n == 't' || n == 'r' || n == '\\' || n == '"') {
        out += c;
        out += n;
        ++i;
        continue;
      }
      out += "\\\\";  // a lone backslash (also the last character) is a character
      continue;
    }
    // rts strings cannot hold a raw line break; POV-Ray reads a carriage return (or a newline
    // after a backslash) inside one, so both are written as escapes.
    if (c == '\r') {
      out += "\\r";
      continue;
    }
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    if (c == '"') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string vec_text(const std::vector<double>& v) {
  std::string s = "<";
  for (std::size_t i = 0; i < v.size() && i < 4; ++i) s += (i ? ", " : "") + num(v[i]);
  return s + ">";
}

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

}  // namespace

std::string Translator::rename(const std::string& n) const {
  static const std::set<std::string> reserved = {"let", "if", "else", "for", "in", "while", "macro", "return",
                                                 "break", "continue", "include", "true", "false", "none", "and",
                                                 "or", "not", "with", "translate", "rotate", "scale", "matrix",
                                                 "step"};
  if (auto a = aliases_.find(n); a != aliases_.end()) return a->second;
  return reserved.count(n) ? n + "_" : n;
}

bool Translator::literal_number(const Expr& e, double& out) {
  if (e.kind == Expr::Number) {
    out = e.number;
    return true;
  }
  if (e.kind == Expr::Name && e.text == "pi") {  // a POV-Ray keyword: never redeclared
    out = std::numbers::pi;
    return true;
  }
  if (e.kind == Expr::Unary && (e.text == "-" || e.text == "+") && literal_number(*e.args[0], out)) {
    if (e.text == "-") out = -out;
    return true;
  }
  if (e.kind == Expr::Binary && e.text != "=" && e.text.size() == 1) {
    double a, b;
    if (literal_number(*e.args[0], a) && literal_number(*e.args[1], b)) {
      switch (e.text[0]) {
        case '+': out = a + b; return true;
        case '-': out = a - b; return true;
        case '*': out = a * b; return true;
        case '/': if (b == 0) return false; out = a / b; return true;
        default: return false;
      }
    }
  }
  if (e.kind == Expr::Name && e.text == "pi") {
    out = M_PI;
    return true;
  }
  return false;
}

bool Translator::literal_vector(const Expr& e, std::vector<double>& out) {
  if (e.kind == Expr::Name && (e.text == "x" || e.text == "y" || e.text == "z")) {
    out = {0, 0, 0};
    out[static_cast<std::size_t>(e.text[0] - 'x')] = 1;
    return true;
  }
  if (e.kind == Expr::Vector) {
    out.clear();
    for (const ExprPtr& c : e.args) {
      double v;
      if (!literal_number(*c, v)) return false;
      out.push_back(v);
    }
    return true;
  }
  if (e.kind == Expr::Unary && (e.text == "-" || e.text == "+") && literal_vector(*e.args[0], out)) {
    if (e.text == "-")
      for (double& v : out) v = -v;
    return true;
  }
  if (e.kind == Expr::Binary && (e.text == "*" || e.text == "+" || e.text == "-" || e.text == "/")) {
    std::vector<double> a, b;
    double k;
    bool va = literal_vector(*e.args[0], a), vb = literal_vector(*e.args[1], b);
    if (!va && literal_number(*e.args[0], k)) a.assign(vb ? b.size() : 3, k), va = !vb ? false : true;
    if (!vb && literal_number(*e.args[1], k)) b.assign(va ? a.size() : 3, k), vb = va;
    if (!va || !vb || a.size() != b.size()) return false;
    out.resize(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      switch (e.text[0]) {
        case '*': out[i] = a[i] * b[i]; break;
        case '+': out[i] = a[i] + b[i]; break;
        case '-': out[i] = a[i] - b[i]; break;
        case '/': if (b[i] == 0) return false; out[i] = a[i] / b[i]; break;
      }
    }
    return true;
  }
  return false;
}

Symbol* Translator::lookup(const std::string& name) {
  for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s) {
    auto it = s->find(name);
    if (it != s->end()) return &it->second;
  }
  return nullptr;
}

std::string Translator::array_element(const Expr& e) {
  if (e.kind != Expr::BlockValue) return value(e);
  const Block& b = *e.block;
  if (b.kind == "texture" || b.kind == "material") {
    MaterialProps m;
    Item part;
    part.kind = Item::Nested;
    part.block = e.block;
    texture_part(part, m);
    return material_text(m, true);
  }
  if (b.kind == "pigment") return pigment_value(b);
  unsupported(e.loc, b.kind + " as an array element", "a value declared with let and put in the list by name", false);
  return "none";
}

std::string Translator::vector_value(const Expr& e) {
  std::vector<double> v;
  if (literal_vector(e, v) && v.size() == 3) return vec(glm::dvec3(v[0], v[1], v[2]));
  double k;
  if (literal_number(e, k)) return vec(glm::dvec3(k));
  Text t = expr(e);
  if (t.type == Type::Float) return "<1, 1, 1> * " + paren(t, 8);
  return t.s;
}

// As value() and vector_value(), as an operand of an arithmetic operator of precedence `prec`
// (7: + and -, 8: * and /): parenthesised when weaker. POV-Ray's `!x` translates to the
// condition `not x != 0`, which `5 * not ...` cannot parse (fuzzer, CI of 2026-11-29), and a
// sum after `-` would change its meaning.
std::string Translator::operand(const Expr& e, int prec) { return paren(expr(e), prec); }

std::string Translator::vector_operand(const Expr& e, int prec) {
  std::vector<double> v;
  double k;
  if ((literal_vector(e, v) && v.size() == 3) || literal_number(e, k)) return vector_value(e);
  Text t = expr(e);
  if (t.type == Type::Float) return paren(Text{"<1, 1, 1> * " + paren(t, 8), Type::Vector, 8}, prec);
  return paren(t, prec);
}

// POV-Ray's library colours declared rgbf (colors.inc's Clear, glass.inc's Col_Glass_*): their
// filter, which rts's library colours (rgb) leave out; null for the others.
static const double* library_filter(const std::string& name) {
  static const std::map<std::string, double> filters = {
      {"Clear", 1.0},                 {"Col_Glass_Old", 0.85},        {"Col_Glass_Winebottle", 0.6},
      {"Col_Glass_Beerbottle", 0.6},  {"Col_Glass_Ruby", 0.8},        {"Col_Glass_Green", 0.9},
      {"Col_Glass_Dark_Green", 0.8},  {"Col_Glass_Yellow", 0.8},      {"Col_Glass_Orange", 0.8},
      {"Col_Glass_Vicksbottle", 0.9}, {"Col_Glass_Clear", 1.0},       {"Col_Glass_General", 0.9},
      {"Col_Glass_Bluish", 0.8}};
  auto it = filters.find(name);
  return it == filters.end() ? nullptr : &it->second;
}

std::string Translator::color_value(const Expr& e, double* filter, double* transmit, int* prec) {
  Text t = expr(e);
  if (filter) *filter = t.filter;
  if (transmit) *transmit = t.transmit;
  if (prec) *prec = t.type == Type::Float || t.type == Type::Vector ? 12 : t.prec;  // rgb(...) is whole
  if (t.type == Type::Float) return "rgb(" + t.s + ")";
  if (t.type == Type::Vector) {
    std::vector<double> v;
    if (literal_vector(e, v) && v.size() >= 3) {
      if (v.size() >= 4 && filter) *filter = v[3];
      if (v.size() >= 5 && transmit) *transmit = v[4];
      return rgb(glm::dvec3(v[0], v[1], v[2]));
    }
    return "rgb(" + t.s + ")";
  }
  return t.s;
}

std::string Translator::condition(const Expr& e) {
  Text t = expr(e);
  if (t.type == Type::Bool) return t.s;
  return paren(t, 6) + " != 0";
}

Text Translator::expr(const Expr& e) {
  switch (e.kind) {
    case Expr::Number: return Text{num(e.number), Type::Float};
    case Expr::String: return Text{rts_escaped(e.text), Type::String};
    case Expr::Name: {
      const std::string& n = e.text;
      if (auto v = function_vars_.find(n); v != function_vars_.end()) return Text{v->second, Type::Float};
      if (Symbol* s = lookup(n)) {
        // colors.inc's Clear is white with filter 1: a pigment of it lets light through (the
        // faces of a CSG box that only cuts, as in POV-Ray's quartic demos); glass.inc's
        // Col_Glass_* carry a filter too. rts's library colour is the rgb part; the filter
        // goes with it here.
        if (library_names_.count(n))
          if (const double* f = library_filter(n)) return Text{n == "Clear" ? "rgb(1)" : rename(n), Type::Color, 12, *f, 0.0};
        return Text{rename(n), s->type};
      }
      if (n == "x" || n == "y" || n == "z") {
        std::vector<double> v;
        literal_vector(e, v);
        return Text{vec(glm::dvec3(v[0], v[1], v[2])), Type::Vector};
      }
      if (n == "pi") return Text{"pi", Type::Float};
      if (n == "true" || n == "yes" || n == "on") return Text{"true", Type::Bool};
      if (n == "false" || n == "no" || n == "off") return Text{"false", Type::Bool};
      if (n == "clock") return Text{"clock", Type::Float};
      if (n == "clock_on") return Text{"false", Type::Bool};
      if (n == "t" || n == "u" || n == "v") {
        unsupported(e.loc, n, "vectors have 3 components in rts; write <..> in full", false);
        return Text{"<0, 0, 0>", Type::Vector};
      }
      if (n == "image_width" || n == "image_height") {
        warn(e.loc, fmt::format("'{}' is taken as {} (rts scenes do not read the image size)", n,
                                n == "image_width" ? 640 : 480));
        return Text{n == "image_width" ? "640" : "480", Type::Float};
      }
      if (n == "version") return Text{num(version_ > 0 ? version_ : 3.7), Type::Float};
      if (n == "clock_delta") return Text{"0", Type::Float};
      if (n == "frame_number") return Text{"frame", Type::Float};
      if (n == "initial_clock") return Text{"0", Type::Float};
      if (n == "final_clock") return Text{"1", Type::Float};
      // A name from an include (colors.inc, textures.inc) or one the scene never declares.
      return Text{rename(n), Type::Unknown};
    }
    case Expr::Vector: {
      // POV-Ray's 2-D vectors (uv and spline points) promote to 3-D with z = 0 wherever a vector
      // is used; rts's vectors have three components, so a 2-D one is written with its 0.
      std::vector<double> lit;
      if (literal_vector(e, lit) && lit.size() >= 2) {
        if (lit.size() == 2) lit.push_back(0.0);
        return Text{vec_text(lit), Type::Vector};
      }
      std::string s = "<";
      for (std::size_t i = 0; i < e.args.size() && i < 4; ++i) {
        Text c = expr(*e.args[i]);
        s += (i ? ", " : "") + paren(c, 7);
      }
      if (e.args.size() == 2) s += ", 0";
      if (e.args.size() > 4) warn(e.loc, "vectors of more than 4 components are cut to 4");
      return Text{s + ">", Type::Vector};
    }
    case Expr::Color: {
      const std::string& k = e.text;
      const Expr& a = *e.args[0];
      if (k == "color") {
        Text t;
        double f = 0, tr = 0;
        // An expression color_value passes through keeps its precedence (`colour !0`, from the
        // fuzzer, is `not 0 != 0`: an operand of another `!` needs its parentheses).
        t.s = color_value(a, &f, &tr, &t.prec);
        for (std::size_t i = 1; i < e.args.size(); ++i) {  // `color C transmit 0.6` (the reader's)
          double v = 0;
          const Expr& channel = *e.args[i];
          if (channel.args.empty() || !literal_number(*channel.args[0], v)) {
            warn(channel.loc, "a computed '" + channel.text + "' after a colour is dropped");
            continue;
          }
          (channel.text == "filter" ? f : tr) = v;
        }
        t.type = Type::Color;
        t.filter = f;
        t.transmit = tr;
        return t;
      }
      std::vector<double> v;
      double one;
      Text out;
      out.type = Type::Color;
      bool srgb = k.rfind("srgb", 0) == 0;
      std::string extra = k.substr(srgb ? 4 : 3);  // "", "f", "t", "ft"
      if (literal_number(a, one)) {
        double c = srgb ? srgb_to_linear(one) : one;
        out.s = rgb(glm::dvec3(c));
        if (extra == "f" || extra == "ft") out.filter = one;
        if (extra == "t") out.transmit = one;
        if (extra == "ft") out.transmit = one;
        return out;
      }
      if (literal_vector(a, v) && v.size() >= 3) {
        glm::dvec3 c(v[0], v[1], v[2]);
        if (srgb) c = glm::dvec3(srgb_to_linear(c.x), srgb_to_linear(c.y), srgb_to_linear(c.z));
        out.s = rgb(c);
        if (extra == "f" && v.size() >= 4) out.filter = v[3];
        if (extra == "t" && v.size() >= 4) out.transmit = v[3];
        if (extra == "ft" && v.size() >= 5) out.filter = v[3], out.transmit = v[4];
        return out;
      }
      if (srgb) warn(e.loc, "'" + k + "' of a computed value is taken as linear rgb");
      if (!extra.empty()) warn(e.loc, "'" + k + "' of a computed value: its filter/transmit is dropped");
      Text t = expr(a);
      if (a.kind == Expr::Vector && a.args.size() >= 3) {
        out.s = fmt::format("rgb({}, {}, {})", value(*a.args[0]), value(*a.args[1]), value(*a.args[2]));
        return out;
      }
      out.s = "rgb(" + t.s + ")";
      return out;
    }
    case Expr::Unary: {
      Text a = expr(*e.args[0]);
      if (e.text == "+") return a;
      if (e.text == "!") {
        std::string c = a.type == Type::Bool ? paren(a, 4) : paren(a, 6) + " != 0";
        return Text{"not " + c, Type::Bool, 4};
      }
      std::vector<double> v;
      // In a function body x, y, z are numbers (function_vars_): nothing folds to a vector.
      if (function_vars_.empty() && literal_vector(e, v) && v.size() >= 2) return Text{vec_text(v), Type::Vector};
      return Text{"-" + paren(a, 9), a.type, 9};
    }
    case Expr::Binary: {
      const std::string& op = e.text;
      if (op == "&" || op == "|") {
        std::string a = condition(*e.args[0]), b = condition(*e.args[1]);
        int p = op == "&" ? 3 : 2;
        return Text{fmt::format("{} {} {}", a, op == "&" ? "and" : "or", b), Type::Bool, p};
      }
      // Fold literal vectors (2 * x, <1, 2, 3> / 2): what people write for a direction.
      std::vector<double> v;
      if (function_vars_.empty() && literal_vector(e, v) && v.size() >= 2) return Text{vec_text(v), Type::Vector};
      Text a = expr(*e.args[0]), b = expr(*e.args[1]);
      if (op == "=" || op == "!=" || op == "<" || op == "<=" || op == ">" || op == ">=") {
        std::string o = op == "=" ? "==" : op;
        return Text{paren(a, 7) + " " + o + " " + paren(b, 7), Type::Bool, 5};
      }
      int p = (op == "+" || op == "-") ? 7 : 8;
      // Float-to-vector promotion for + and -: POV-Ray adds the float to every component.
      if ((op == "+" || op == "-") && is_vectorish(a.type) != is_vectorish(b.type) &&
          (a.type == Type::Float || b.type == Type::Float)) {
        Text& f = a.type == Type::Float ? a : b;
        Type vt = a.type == Type::Float ? b.type : a.type;
        f.s = vt == Type::Color ? "rgb(" + f.s + ")" : "<1, 1, 1> * " + paren(f, 8);
        f.prec = vt == Type::Color ? 12 : 8;
        f.type = vt;
      }
      Type t = is_vectorish(a.type) ? a.type : is_vectorish(b.type) ? b.type
               : (a.type == Type::Float && b.type == Type::Float) ? Type::Float : Type::Unknown;
      // Left-associative: the right operand of - and / needs parentheses at the same level.
      std::string rs = (op == "-" || op == "/") ? (b.prec <= p ? "(" + b.s + ")" : b.s) : paren(b, p);
      return Text{paren(a, p) + " " + op + " " + rs, t, p};
    }
    case Expr::Ternary: {
      // rts's select(c, a, b) evaluates only the chosen value, as POV-Ray's ?: does.
      Text a = expr(*e.args[1]);
      return Text{fmt::format("select({}, {}, {})", condition(*e.args[0]), a.s, value(*e.args[2])), a.type, 11};
    }
    case Expr::Member: {
      Text a = expr(*e.args[0]);
      std::string m = e.text;
      static const std::map<std::string, std::string> names = {
          {"x", "x"}, {"y", "y"}, {"z", "z"}, {"u", "x"}, {"v", "y"}, {"red", "x"}, {"green", "y"}, {"blue", "z"}};
      auto it = names.find(m);
      if (it == names.end()) {
        unsupported(e.loc, "." + m, "rts colours and vectors have 3 components (.x .y .z)", false);
        return Text{"0", Type::Float};
      }
      // A float is promoted to a vector of three equal components (POV-Ray): its .x is itself.
      if (a.type == Type::Float) return a;
      return Text{paren(a, 11) + "." + it->second, Type::Float, 11};
    }
    case Expr::Index: {
      Text a = expr(*e.args[0]);
      Text i = expr(*e.args[1]);
      return Text{paren(a, 11) + "[" + i.s + "]", Type::Unknown, 11};
    }
    case Expr::Array: {
      if (e.text == "multi init") return expr(*e.args[0]);  // its rows
      if (e.text == "rows" || e.text == "init") {
        // array[n] { a, b }, and each level of array[n][m] { {a, b}, {c, d} }: a list literal.
        std::string s = "[";
        for (std::size_t i = e.text == "init" ? 1 : 0; i < e.args.size(); ++i)
          s += (s.size() > 1 ? ", " : "") + array_element(*e.args[i]);
        return Text{s + "]", Type::List};
      }
      if (e.text == "multi") {
        // array[n][m]: lists of lists of none (POV-Ray's elements start undefined).
        helpers_.insert("pov_array");
        std::string sizes;
        for (const ExprPtr& a : e.args) sizes += (sizes.empty() ? "" : ", ") + value(*a);
        return Text{"pov_array([" + sizes + "])", Type::List, 11};
      }
      double n;
      if (literal_number(*e.args[0], n) && n >= 0 && n <= 10000) {
        // Elements without a value are none (#ifdef(A[i]) asks; reading one is POV-Ray's error too).
        std::string s = "[";
        for (int i = 0; i < static_cast<int>(n); ++i) s += i ? ", none" : "none";
        return Text{s + "]", Type::List};
      }
      // A computed size: a list of that many nones, made when the scene runs.
      helpers_.insert("pov_array");
      return Text{"pov_array([" + value(*e.args[0]) + "])", Type::List, 11};
    }
    case Expr::Call: return call(e);
    case Expr::BlockValue:
      unsupported(e.loc, e.block->kind, "a value declared with let and passed by name", false);
      return Text{"none", Type::Unknown};
  }
  return Text{"none"};
}

Text Translator::call(const Expr& e) {
  const std::string& f = e.text;
  std::vector<Text> a;
  for (const ExprPtr& x : e.args) a.push_back(expr(*x));
  auto args = [&](std::size_t from = 0) {
    std::string s;
    for (std::size_t i = from; i < a.size(); ++i) s += (i > from ? ", " : "") + a[i].s;
    return s;
  };
  if (Symbol* s = lookup(f); s && s->type == Type::Macro) return Text{rename(f) + "(" + args() + ")", Type::Unknown, 11};
  // Same name, same meaning.
  static const std::map<std::string, std::pair<std::string, Type>> same = {
      {"sin", {"sin", Type::Float}},       {"cos", {"cos", Type::Float}},     {"tan", {"tan", Type::Float}},
      {"asin", {"asin", Type::Float}},     {"acos", {"acos", Type::Float}},   {"atan", {"atan", Type::Float}},
      {"atan2", {"atan2", Type::Float}},   {"sqrt", {"sqrt", Type::Float}},   {"pow", {"pow", Type::Float}},
      {"exp", {"exp", Type::Float}},       {"ln", {"log", Type::Float}},      {"abs", {"abs", Type::Float}},
      {"floor", {"floor", Type::Float}},   {"ceil", {"ceil", Type::Float}},   {"radians", {"radians", Type::Float}},
      {"degrees", {"degrees", Type::Float}}, {"min", {"min", Type::Float}},   {"max", {"max", Type::Float}},
      {"vlength", {"length", Type::Float}}, {"vnormalize", {"normalize", Type::Vector}},
      {"vdot", {"dot", Type::Float}},      {"vcross", {"cross", Type::Vector}}, {"vrotate", {"vrotate", Type::Vector}},
      {"vaxis_rotate", {"vaxis_rotate", Type::Vector}}, {"rand", {"rand", Type::Float}},
      {"seed", {"random", Type::Random}},  {"str", {"str", Type::String}},  {"concat", {"", Type::String}},
      {"strlen", {"len", Type::Float}}};
  if (auto it = same.find(f); it != same.end()) {
    if (f == "concat") {
      std::string s;
      for (std::size_t i = 0; i < a.size(); ++i) s += (i ? " + " : "") + a[i].s;
      return Text{s, Type::String, 7};
    }
    if (f == "seed" && a.size() == 1)  // POV-Ray's own sequence for the seed (runtime/value.cpp)
      return Text{"random(" + a[0].s + ", \"povray\")", Type::Random, 11};
    if (f == "str") {  // POV-Ray's str(x, width, decimals): rts's str takes the same three
      std::string s;
      for (const Text& t : a) s += (s.empty() ? "" : ", ") + t.s;
      return Text{"str(" + s + ")", Type::String, 11};
    }
    return Text{it->second.first + "(" + args() + ")", it->second.second, 11};
  }
  if (f == "log" && a.size() == 1) return Text{"log(" + a[0].s + ") / log(10)", Type::Float, 8};
  if (f == "dimension_size" && a.size() == 2) {
    // The size of dimension k (1 the outermost) of an array, which the import writes as lists
    // of lists: len(A), len(A[0]), ... (k literal).
    double k = 0;
    if (literal_number(*e.args[1], k) && k >= 1 && k <= 5 && std::floor(k) == k) {
      std::string inner = paren(a[0], 11);
      for (int i = 1; i < static_cast<int>(k); ++i) inner += "[0]";
      return Text{"len(" + inner + ")", Type::Float, 11};
    }
  }
  if (f == "sqr" && a.size() == 1) return Text{paren(a[0], 9) + " ^ 2", Type::Float, 10};
  if (f == "mod" && a.size() == 2) return Text{paren(a[0], 9) + " % " + paren(a[1], 9), Type::Float, 8};
  if (f == "int" && a.size() == 1) {
    helpers_.insert("pov_int");
    return Text{"pov_int(" + a[0].s + ")", Type::Float, 11};
  }
  if (f == "div" && a.size() == 2) {
    helpers_.insert("pov_int");
    return Text{"pov_int(" + a[0].s + " / " + paren(a[1], 9) + ")", Type::Float, 11};
  }
  if (f == "select" && (a.size() == 3 || a.size() == 4)) {
    // POV-Ray's select(A, B, C[, D]) tests the sign of A.
    if (a.size() == 3) return Text{fmt::format("select({} < 0, {}, {})", paren(a[0], 7), a[1].s, a[2].s), a[1].type, 11};
    return Text{fmt::format("select({0} < 0, {1}, select({0} == 0, {2}, {3}))", paren(a[0], 7), a[1].s, a[2].s, a[3].s),
                a[1].type, 11};
  }
  if (f == "defined" && !e.args.empty() && e.args[0]->kind == Expr::Name)
    return Text{declared(e.args[0]->text) ? "true" : "false", Type::Bool};
  if (f == "vstr" || f == "chr" || f == "substr" || f == "strlen" || f == "strupr" || f == "strlwr" ||
      f == "asc" || f == "val" || f == "file_exists" || f == "dimension_size" || f == "dimensions" || f == "trace" || f == "inside" ||
      f == "min_extent" || f == "max_extent" || f == "eval_pigment") {
    unsupported(e.loc, f + "()", "no rts built-in of that name yet", false);
    return Text{"0", Type::Float};
  }
  // A user macro defined in an include, or a function value: called as is.
  return Text{rename(f) + "(" + args() + ")", Type::Unknown, 11};
}

}  // namespace rts::import::pov
