// POV-Ray's include files and whole files: the standard includes mapped to rts's library,
// a scene's own includes translated beside it, the header and footer of a translated file,
// content sniffing (looks_like_pov) and the entry point, import_pov.
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "import/pov/reader.hpp"
#include "import/pov/translator.hpp"

namespace rts::import::pov {

namespace fs = std::filesystem;

namespace {

// The standard include files and the rts library file each maps to ("" : rts's built-ins
// cover it, nothing to include).
const std::map<std::string, std::string>& standard_includes() {
  static const std::map<std::string, std::string> m = {
      {"colors.inc", "colors.inc"},   {"colours.inc", "colors.inc"}, {"consts.inc", "consts.inc"},
      {"shapes2.inc", "shapes2.inc"}, {"shapesq.inc", "shapesq.inc"},
      {"ior.inc", "consts.inc"},      {"metals.inc", "metals.inc"},  {"golds.inc", "metals.inc"},
      {"glass.inc", "glass.inc"},     {"textures.inc", "textures.inc"}, {"shapes.inc", "shapes.inc"},
      {"skies.inc", "skies.inc"},     {"math.inc", ""},              {"transforms.inc", ""},
      {"functions.inc", ""},          {"rand.inc", ""},              {"strings.inc", ""},
      {"arrays.inc", ""},             {"debug.inc", ""},             {"finish.inc", "finish.inc"},
      {"woods.inc", "woods.inc"},     {"stones.inc", "stones.inc"},  {"stones1.inc", "stones.inc"},
      {"stones2.inc", "stones.inc"}};
  return m;
}
const std::set<std::string>& unshipped_includes() {
  // POV-Ray's include files that neither map to rts's library nor translate as they are (macros
  // the import cannot read, radiosity settings). The rest of its library folder (stars.inc,
  // chars.inc, stdcam.inc, shapes_old.inc, sunpos.inc, screen.inc, stdinc.inc ...) is found
  // last on the search path and translated as the user's own includes are.
  static const std::set<std::string> s = {"skies.inc.old", "logo.inc",  "rad_def.inc", "glass_old.inc",
                                          "meshmaker.inc", "makegrass.inc", "potions.inc", "fonts.inc"};
  return s;
}

}  // namespace

void Translator::declare_library_file(const std::string& file) {
  if (!library_files_.insert(file).second) return;
  std::ifstream lib(fs::path(opt_.stdlib_dir) / file);
  std::string line, macro;  // `macro`: the macro whose first body line is next
  while (std::getline(lib, line)) {
    // A macro whose body starts `return material {` gives a material (stones.rts' marble_stone).
    if (!macro.empty() && line.find("return material") != std::string::npos) library_material_macros_.insert(macro);
    macro.clear();
    if (line.rfind("include \"", 0) == 0) {
      // rts's include makes the included file's names visible too (textures.rts: metals, glass,
      // finish ...).
      std::size_t e = line.find('"', 9);
      if (e != std::string::npos) declare_library_file(line.substr(9, e - 9));
    } else if (line.rfind("let ", 0) == 0) {
      std::size_t e = line.find_first_of(" =", 4);
      std::string n = line.substr(4, e == std::string::npos ? std::string::npos : e - 4);
      library_names_.insert(n);
      Symbol s{line.find("rgb(") != std::string::npos ? Type::Color : Type::Unknown, nullptr, ""};
      if (line.find("material") != std::string::npos) s.type = Type::Material;
      if (std::size_t v = line.find_first_not_of(' ', line.find('=') + 1); v != std::string::npos) {
        const std::string callee = line.substr(v, line.find('(', v) - v);
        if (line.find('(', v) != std::string::npos && library_material_macros_.count(callee)) s.type = Type::Material;
      }
      // `let Cube = box { ...`, `let Cone_Y = cone { ...`, `let Ellipsoid = Sphere`: an object of
      // that kind (a texture on it then derives the shape, or wraps a CSG block).
      std::size_t eq = line.find('=');
      std::size_t w0 = eq == std::string::npos ? std::string::npos : line.find_first_not_of(' ', eq + 1);
      if (w0 != std::string::npos) {
        std::size_t w1 = line.find_first_of(" {", w0);
        std::string word = line.substr(w0, w1 == std::string::npos ? std::string::npos : w1 - w0);
        if (word == "sky_sphere") {
          s.object_kind = word;   // skies.rts' S_Cloud1 ...: a sky_sphere { S_Cloud1 } names it
        } else if (is_object_kind(word) && line.find('{', w0) != std::string::npos) {
          s = Symbol{Type::Object, nullptr, word};
        } else if (pigment_pattern(word) && line.find('{', w0) != std::string::npos) {
          // `let P_WoodGrain1A = wood { ... } scale ...`: a pattern, a pigment in POV-Ray.
          s = Symbol{Type::Pigment, nullptr, ""};
        } else if (auto known = scopes_.front().find(word); known != scopes_.front().end()) {
          // `let Jade = jade`: another name for a library object, material or colour.
          const std::size_t rest = line.find_first_not_of(' ', w0 + word.size());
          const bool alone = rest == std::string::npos || line.compare(rest, 2, "//") == 0;
          if (known->second.type == Type::Object ||
              (alone && (known->second.type == Type::Material || known->second.type == Type::Color)))
            s = known->second;
        }
      }
      scopes_.front()[n] = s;
      // A one-line material of literal properties: kept for finish { N } and interior { N }.
      std::size_t open = line.find("= material { "), close = line.find(" }");
      if (open != std::string::npos && close != std::string::npos && close > open) {
        std::string body = line.substr(open + 13, close - open - 13);
        MaterialProps props;
        std::size_t at = 0;
        while (at < body.size()) {
          std::size_t next = body.find("  ", at);
          std::string pair = body.substr(at, next == std::string::npos ? std::string::npos : next - at);
          std::size_t eq = pair.find(" = ");
          if (eq != std::string::npos) props.set(pair.substr(0, eq), pair.substr(eq + 3));
          if (next == std::string::npos) break;
          at = next + 2;
        }
        library_parts_[n] = props;
      }
    } else if (line.rfind("macro ", 0) == 0) {
      std::size_t e = line.find('(', 6);
      std::string n = line.substr(6, e == std::string::npos ? std::string::npos : e - 6);
      macro = n;
      library_names_.insert(n);
      scopes_.front()[n] = Symbol{Type::Macro, nullptr, ""};
    }
  }
}

std::vector<std::string> Translator::search_dirs() const {
  std::error_code ec;
  std::vector<std::string> dirs = {dir_.empty() ? std::string(".") : dir_};
  dirs.insert(dirs.end(), opt_.include_dirs.begin(), opt_.include_dirs.end());
  // Last, POV-Ray's own library folder where it is installed (its Library_Path): include files
  // that are not standard includes rts maps, such as the woods' and stones' `.map` files, and
  // the images its samples map (test.png, plasma3.png).
  for (const char* lib : {"/usr/share/povray-3.7/include", "/usr/local/share/povray-3.7/include"})
    if (fs::is_directory(lib, ec)) dirs.emplace_back(lib);
  return dirs;
}

void Translator::include(Writer& w, const Item& it) {
  const std::string& name = it.name;
  fs::path found;
  std::error_code ec;
  for (const std::string& d : search_dirs()) {
    fs::path p = fs::path(d.empty() ? "." : d) / name;
    if (fs::is_regular_file(p, ec)) {
      found = p;
      break;
    }
  }
  std::string base = fs::path(name).filename().string();
  auto std_it = standard_includes().find(base);
  if (found.empty() || std_it != standard_includes().end() || unshipped_includes().count(base)) {
    if (std_it != standard_includes().end()) {
      if (std_it->second.empty()) {
        w.line(fmt::format("// #include \"{}\": rts's built-ins cover it", name));
        return;
      }
      w.line(fmt::format("include \"{}\"", std_it->second));
      // The names the library file defines: declared for the translation.
      if (!opt_.stdlib_dir.empty()) declare_library_file(fs::path(std_it->second).stem().string() + ".rts");
      return;
    }
    if (unshipped_includes().count(base)) {
      unsupported(it.loc, "#include \"" + name + "\"", "rts's standard library has no " + base +
                  " yet (docs/library.md); its names must be written in the scene", true);
      w.line(fmt::format("// #include \"{}\": not in rts's standard library", name));
      return;
    }
    error(it.loc, fmt::format("cannot find include file '{}' (searched {}, the -I folders and POV-Ray's library folder)", name,
                              dir_.empty() ? "." : dir_));
  }
  // The user's own include: translated to its own .rts beside the scene, once.
  std::string canonical = fs::weakly_canonical(found, ec).string();
  // Each include file its own .rts, named after it; never the scene's own name (local.pov
  // including local.inc would overwrite itself) nor another include's (a.inc and a.mcr).
  std::string& out_name = include_names_[canonical];
  if (out_name.empty()) {
    const std::string stem = fs::path(name).stem().string();
    const std::string ext = fs::path(name).extension().string();
    out_name = stem + ".rts";
    if (stem == fs::path(opt_.source_path).stem().string() || include_outputs_.count(out_name))
      out_name = stem + "_" + (ext.size() > 1 ? ext.substr(1) : std::string("inc")) + ".rts";
    for (int n = 2; include_outputs_.count(out_name); ++n) out_name = fmt::format("{}_{}.rts", stem, n);
    include_outputs_.insert(out_name);
  }
  if (!included_.count(canonical)) {
    included_.insert(canonical);
    if (++include_depth_ > 50) error(it.loc, "includes nested more than 50 deep");
    std::ifstream in(found, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    std::string saved_file = file_, saved_dir = dir_, saved_stem = include_stem_;
    const std::map<std::string, std::string> saved_aliases = aliases_;
    include_stem_ = fs::path(name).stem().string();
    include_shadows_.emplace_back();
    Program p;
    try {
      p = read_program(text.str(), name, reader_names_);
    } catch (const SyntaxError& e) {
      throw PovError{Diagnostic{found.string(), e.loc.line, e.loc.col, e.message}};
    }
    Writer iw;
    iw.line(fmt::format("// Imported by `rts import` from {} (a POV-Ray include file).", name));
    iw.blank();
    this->file(p, found.string(), iw);
    file_ = saved_file;
    dir_ = saved_dir;
    // The file's top-level #locals end with it: the includer's symbols come back.
    for (auto& [local, before] : include_shadows_.back()) {
      if (before) scopes_.front()[local] = *before;
      else scopes_.front().erase(local);
    }
    include_shadows_.pop_back();
    aliases_ = saved_aliases;
    include_stem_ = saved_stem;
    --include_depth_;
    result_.includes.push_back(PovOutputFile{out_name, iw.text()});
  }
  w.line(fmt::format("include \"{}\"", out_name));
}

// ---- files ----

void Translator::file(const Program& p, const std::string& path, Writer& w) {
  file_ = path;
  dir_ = fs::path(path).parent_path().string();
  items(w, p.items, true);
  w.comments(p.trailing_comments);
}

void Translator::header(Writer& w, const std::string& source_name) {
  w.line(fmt::format("// Imported by `rts import` from {} (POV-Ray scene language).", source_name));
  w.line("// POV-Ray's conventions are written out: its default finish (ambient 0.1, diffuse 0.6), its black");
  w.line("// default pigment, its camera and its output gamma. See docs/from-povray.md.");
}

void Translator::footer(Writer& w) {
  // POV-Ray 3.7: a scene with assumed_gamma 1.0 (or #version 3.7 without assumed_gamma) is
  // written with the sRGB curve; an older scene (no #version, no assumed_gamma) with none; a
  // scene with assumed_gamma g renders in a space of gamma g, and its values v are written as
  // sRGB of v^g (measured: objects/prism3c, assumed_gamma 2.2, 0.48 codes from POV-Ray's image
  // where no encoding was 7.1; objects/ttf1, 1.9, 0.22 codes where it was 8.9).
  const bool srgb = gamma_seen_ ? std::abs(assumed_gamma_ - 1.0) < 1e-9 : version_ >= 3.7;
  const bool power = gamma_seen_ && !srgb && assumed_gamma_ > 0.0;
  if (opt_.width > 0 || opt_.height > 0 || opt_.antialias_threshold >= 0) {
    // POV-Ray's render options (an .ini file): the image size, and +A as a fixed sample count.
    std::string s;
    if (opt_.width > 0) s += fmt::format("  width = {}", opt_.width);
    if (opt_.height > 0) s += fmt::format("  height = {}", opt_.height);
    w.blank();
    if (opt_.antialias_threshold >= 0) {
      s += "  samples = 9";
      w.line(fmt::format("// POV-Ray's +A{}: it supersamples a pixel that differs from its neighbours by more than {}",
                         num(opt_.antialias_threshold), num(opt_.antialias_threshold)));
      w.line("// with up to 3x3 rays (Antialias_Depth 3); here 9 samples in every pixel (or --target-error).");
    } else {
      w.line("// POV-Ray's render options (its .ini file).");
    }
    w.line("settings {" + s.substr(1) + " }");
  }
  if (!camera_seen_) {
    w.blank();
    w.line("// POV-Ray's default camera: at the origin looking along +z, its 1.33 wide right vector.");
    w.line("camera { position = <0, 0, 0>  direction = <0, 0, 1>  right = <1.33, 0, 0>  up = <0, 1, 0> }");
  }
  w.blank();
  if (power) {
    w.line(fmt::format("// POV-Ray with assumed_gamma {0}: the scene's values are in a space of gamma {0}; each is",
                       num(assumed_gamma_)));
    w.line(fmt::format("// written as sRGB of its {}th power.", num(assumed_gamma_)));
    w.line(fmt::format("settings {{ output_gamma = {} }}", num(assumed_gamma_)));
  } else {
    w.line(srgb ? "// POV-Ray 3.7 with assumed_gamma 1.0: the image is sRGB-encoded."
                : "// POV-Ray without #version 3.7 / assumed_gamma 1.0 writes the image without gamma encoding.");
    w.line(fmt::format("settings {{ output_gamma = \"{}\" }}", srgb ? "srgb" : "linear"));
  }
  w.line("// POV-Ray's lights fall off by their fade_distance/fade_power only: with --integrator path too.");
  w.line("settings { light_falloff = \"attenuation\" }");
  if (radiosity_) {
    w.line("// POV-Ray's radiosity: rts's path tracer (indirect light from every surface, unbiased; the");
    w.line("// radiosity block's settings have no use there). Give it samples: rts render ... --samples 64");
    w.line("settings { integrator = \"path\" }");
  }
}

// The names the user's include files declare, before the main file is read: the reader needs
// them to tell a lower-case name that is a value from a keyword. Each file is read once: a file
// that includes itself twice would otherwise be read 2^20 times.
void collect_declared(const std::string& text, const std::string& dir, const PovOptions& options,
                      std::set<std::string>& names, std::set<std::string>& seen, int depth) {
  if (depth > 20) return;
  std::vector<Token> toks;
  try {
    toks = tokenize(text);
  } catch (const SyntaxError&) {
    return;  // reported when the file itself is read
  }
  for (std::size_t i = 0; i + 1 < toks.size(); ++i) {
    if (toks[i].kind != Token::Directive) continue;
    const std::string& d = toks[i].text;
    if ((d == "declare" || d == "local" || d == "macro") && toks[i + 1].kind == Token::Name)
      names.insert(toks[i + 1].text);
    if (d == "include" && toks[i + 1].kind == Token::String) {
      std::vector<std::string> dirs = {dir};
      dirs.insert(dirs.end(), options.include_dirs.begin(), options.include_dirs.end());
      for (const std::string& folder : dirs) {
        fs::path p = fs::path(folder.empty() ? "." : folder) / toks[i + 1].text;
        std::error_code ec;
        if (!fs::is_regular_file(p, ec) || standard_includes().count(p.filename().string())) continue;
        if (!seen.insert(fs::weakly_canonical(p, ec).string()).second) break;
        std::ifstream in(p, std::ios::binary);
        std::stringstream buffer;
        buffer << in.rdbuf();
        collect_declared(buffer.str(), p.parent_path().string(), options, names, seen, depth + 1);
        break;
      }
    }
  }
}

bool looks_like_pov(const std::string& text) {
  std::string head = text.substr(0, 1 << 16);
  for (const char* marker : {"#include", "#declare", "#version", "#local", "#macro"})
    if (head.find(marker) != std::string::npos) return true;
  for (const char* block : {"camera", "light_source"}) {
    std::size_t at = 0;
    while ((at = head.find(block, at)) != std::string::npos) {
      std::size_t i = at + std::string(block).size();
      while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
      if (i < head.size() && head[i] == '{') return true;
      at = i;
    }
  }
  return false;
}

PovResult import_pov(const std::string& text, const PovOptions& options) {
  PovResult result;
  Translator t(options, result);
  t.library_known_ = !options.stdlib_dir.empty() && fs::is_directory(options.stdlib_dir);
  Program p;
  try {
    std::set<std::string> seen;
    collect_declared(text, fs::path(options.source_path).parent_path().string(), options, t.reader_names_, seen, 0);
    p = read_program(text, options.source_path, t.reader_names_);
  } catch (const SyntaxError& e) {
    throw PovError{Diagnostic{options.source_path, e.loc.line, e.loc.col, e.message}};
  }
  Writer body;
  t.file(p, options.source_path, body);
  Writer out;
  t.header(out, fs::path(options.source_path).filename().string());
  if (t.helpers_.count("pov_int")) {
    out.blank();
    out.line("// POV-Ray's int(): rounds towards zero.");
    out.line("macro pov_int(x) { if x < 0 { return ceil(x) }  return floor(x) }");
  }
  if (t.helpers_.count("pov_look_at")) {
    out.blank();
    out.line("// POV-Ray's camera vectors when the scene computes them: `angle` (0: none) sets direction's");
    out.line("// length from right's; towards a look_at point they turn keeping their lengths and right's");
    out.line("// handedness, `sky` the reference for up (looking along it keeps right's direction).");
    out.line("macro pov_look_at(position, target, sky, direction, right, up, angle) {");
    out.line("    let d = direction");
    out.line("    if angle > 0 { d = normalize(d) * (0.5 * length(right) / tan(angle * pi / 360)) }");
    out.line("    if target == none { return [d, right, up] }");
    out.line("    if length(target - position) < 1e-9 { return [d, right, up] }");
    out.line("    let dl = length(d)");
    out.line("    let hand = select(dot(cross(up, d), right) > 0, 1, -1)");
    out.line("    d = normalize(target - position)");
    out.line("    let r = cross(sky, d)");
    out.line("    if length(r) < 1e-9 { r = right }");
    out.line("    r = normalize(r)");
    out.line("    return [d * dl, r * (length(right) * hand), cross(d, r) * length(up)]");
    out.line("}");
  }
  if (t.helpers_.count("pov_array")) {
    out.blank();
    out.line("// POV-Ray's array[n][m]...: lists (of lists) of none, an element without a value (as in POV-Ray,");
    out.line("// where reading one is an error); an element changes with with_item.");
    out.line("macro pov_array(sizes, k = 0) {");
    out.line("    let a = []");
    out.line("    for i in 0 .. floor(sizes[k]) { a += [select(k + 1 < len(sizes), pov_array(sizes, k + 1), none)] }");
    out.line("    return a");
    out.line("}");
  }
  out.blank();
  std::string s = out.text() + body.text();
  Writer tail;
  t.footer(tail);
  result.rts = s + tail.text();
  return result;
}

}  // namespace rts::import::pov
