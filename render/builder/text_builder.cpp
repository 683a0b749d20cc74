// The `text` block (docs/shapes.md#text): POV-Ray's text object, built as one prism per glyph
// in a group. FreeType reads the font's outlines in font units; each contour's lines and
// quadratic (TrueType) or cubic (CFF) curves become cubic Bézier segments of a prism outline
// (a quadratic raised to a cubic is the same curve), so the glyph is traced exactly by the
// prism's curved walls; the em square is one unit, the baseline y = 0, the glyphs extruded from
// z = 0 to z = thickness, as POV-Ray lays them out (advance widths, the font's kerning, then
// `offset` after each character; the line starts at the first glyph's left edge).
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "render/builder/scene_builder.hpp"
#include "render/builder/scene_builder_detail.hpp"
#include "render/geometry/shapes/prism.hpp"

namespace rts::render {

using builder_detail::add_node;
using builder_detail::names_of;
using builder_detail::resolve_path;

namespace {

// A string longer than this is refused (each character is a prism).
constexpr std::size_t kMaxTextCharacters = 4096;

struct LibraryDeleter {
  void operator()(FT_Library l) const { FT_Done_FreeType(l); }
};
struct FaceDeleter {
  void operator()(FT_Face f) const { FT_Done_Face(f); }
};

// UTF-8 to code points; a byte that does not start a complete sequence stands for itself
// (Latin-1), as POV-Ray reads bytes.
std::vector<uint32_t> code_points(const std::string& s) {
  std::vector<uint32_t> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const auto b = static_cast<unsigned char>(s[i]);
    const std::size_t extra = b >= 0xF0 && b < 0xF8 ? 3 : b >= 0xE0 && b < 0xF0 ? 2 : b >= 0xC0 && b < 0xE0 ? 1 : 0;
    uint32_t cp = extra == 0 ? b : (b & (0x3Fu >> extra));
    bool ok = extra > 0 && i + extra < s.size();
    for (std::size_t k = 1; ok && k <= extra; ++k) {
      const auto c = static_cast<unsigned char>(s[i + k]);
      ok = (c & 0xC0) == 0x80;
      cp = (cp << 6) | (c & 0x3Fu);
    }
    if (ok) {
      out.push_back(cp);
      i += extra + 1;
    } else {
      out.push_back(b);
      ++i;
    }
  }
  return out;
}

// Fonts in the system's font folders and POV-Ray's library folder (where its scenes' timrom.ttf
// and cyrvetic.ttf are) may be read wherever the scene is: FreeType only reads their outlines,
// and no error quotes a font's bytes. Any other file follows the scene's read policy.
bool system_font(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
  if (ec || !std::filesystem::is_regular_file(canonical, ec)) return false;
  std::string ext = canonical.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".ttf" && ext != ".otf" && ext != ".ttc") return false;
  const std::string c = canonical.string();
  for (const char* dir : {"/usr/share/fonts/", "/usr/local/share/fonts/", "/usr/share/povray-3.7/include/",
                          "/usr/local/share/povray-3.7/include/"})
    if (c.rfind(dir, 0) == 0) return true;
  return false;
}

// The font file: `resolved` (the name beside the scene), else the name in the system's font
// folders and POV-Ray's library folder, as POV-Ray looks in its Library_Path; as POV-Ray does,
// a name without an extension is also tried with ".ttf". "" when none exists.
std::string find_font(const std::string& resolved, const std::string& name) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<std::string> names = {resolved};
  const bool bare = !fs::path(name).has_extension();
  if (bare) names.push_back(resolved + ".ttf");
  const std::string base = fs::path(name).filename().string();
  if (!base.empty() && !fs::path(name).has_parent_path())
    for (const char* dir : {"/usr/share/povray-3.7/include", "/usr/local/share/povray-3.7/include",
                            "/usr/share/fonts/truetype/dejavu", "/usr/share/fonts/truetype",
                            "/usr/share/fonts/opentype", "/usr/local/share/fonts"}) {
      names.push_back(std::string(dir) + "/" + base);
      if (bare) names.push_back(std::string(dir) + "/" + base + ".ttf");
    }
  for (const std::string& n : names)
    if (fs::exists(n, ec)) return n;
  return "";
}

// A glyph's contours as cubic Bézier segments, 4 points each, in em units (x, y as x, z).
struct OutlineSink {
  double scale;
  std::vector<Vec3> points;
  glm::dvec2 at{0.0};
  void segment(glm::dvec2 c1, glm::dvec2 c2, glm::dvec2 to) {
    for (const glm::dvec2& p : {at, c1, c2, to}) points.emplace_back(p.x, p.y, 0.0);
    at = to;
  }
};

glm::dvec2 point_of(const FT_Vector* v, double scale) {
  return glm::dvec2(static_cast<double>(v->x) * scale, static_cast<double>(v->y) * scale);
}

int move_to(const FT_Vector* to, void* user) {
  auto* s = static_cast<OutlineSink*>(user);
  s->at = point_of(to, s->scale);
  return 0;
}
int line_to(const FT_Vector* to, void* user) {
  auto* s = static_cast<OutlineSink*>(user);
  const glm::dvec2 b = point_of(to, s->scale);
  s->segment(s->at + (b - s->at) / 3.0, s->at + 2.0 * (b - s->at) / 3.0, b);
  return 0;
}
int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
  auto* s = static_cast<OutlineSink*>(user);
  const glm::dvec2 c = point_of(control, s->scale), b = point_of(to, s->scale);
  s->segment(s->at + 2.0 * (c - s->at) / 3.0, b + 2.0 * (c - b) / 3.0, b);  // degree elevation: exact
  return 0;
}
int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
  auto* s = static_cast<OutlineSink*>(user);
  s->segment(point_of(c1, s->scale), point_of(c2, s->scale), point_of(to, s->scale));
  return 0;
}

}  // namespace

NodeId SceneBuilder::text(ParamSet& ps, const ShapeDesc& base) {
  ps.set_valid_names(names_of("text"));
  if (!ps.has("font")) ps.fail_block("text needs property 'font' (a TrueType or OpenType font file)");
  if (!ps.has("string")) ps.fail_block("text needs property 'string' (the characters to write)");
  const SourceRef font_loc = loc_of(ps, "font");
  const std::string font = ps.string("font", "");
  const std::string path = find_font(resolve_path(font, font_loc), font);
  if (path.empty())
    throw SceneError(font_loc, fmt::format("cannot find font file '{}' (looked beside the scene file, then in "
                                           "/usr/share/fonts and POV-Ray's library folder)",
                                           font));
  if (!system_font(path)) check_readable(path, font, "font file", font_loc);
  const std::string text = ps.string("string", "");
  const double thickness = ps.number("thickness", 1.0);
  if (!(thickness > 0.0) || !std::isfinite(thickness))
    throw SceneError(loc_of(ps, "thickness"), fmt::format("text thickness must be above 0, got {}", thickness));
  const Vec3 offset = ps.vec3("offset", Vec3(0.0));
  if (!std::isfinite(offset.x) || !std::isfinite(offset.y) || !std::isfinite(offset.z))
    throw SceneError(loc_of(ps, "offset"), "text offset is not finite");
  const std::vector<uint32_t> chars = code_points(text);
  if (chars.size() > kMaxTextCharacters)
    throw SceneError(loc_of(ps, "string"), fmt::format("text has {} characters, more than the {} one text block may hold",
                                                       chars.size(), kMaxTextCharacters));
  ps.check_unused(*names_of("text"));

  FT_Library raw_library = nullptr;
  if (FT_Init_FreeType(&raw_library) != 0) throw SceneError(font_loc, "cannot start FreeType to read the font");
  std::unique_ptr<FT_LibraryRec_, LibraryDeleter> library(raw_library);
  FT_Face raw_face = nullptr;
  if (FT_New_Face(library.get(), path.c_str(), 0, &raw_face) != 0)
    throw SceneError(font_loc, fmt::format("cannot read font '{}': not a font file FreeType reads", font));
  std::unique_ptr<FT_FaceRec_, FaceDeleter> face(raw_face);
  if (!FT_IS_SCALABLE(face.get()) || face->units_per_EM == 0)
    throw SceneError(font_loc, fmt::format("font '{}' has no outlines (a bitmap font)", font));
  FT_Select_Charmap(face.get(), FT_ENCODING_UNICODE);
  const double scale = 1.0 / static_cast<double>(face->units_per_EM);

  GroupDesc group;
  group.casts_shadow = base.casts_shadow;
  Vec3 pen(0.0);
  FT_UInt previous = 0;
  bool first = true;
  const FT_Outline_Funcs funcs{move_to, line_to, conic_to, cubic_to, 0, 0};
  for (uint32_t cp : chars) {
    const FT_UInt glyph = FT_Get_Char_Index(face.get(), cp);
    if (previous != 0 && glyph != 0 && FT_HAS_KERNING(face.get())) {
      FT_Vector kern;
      if (FT_Get_Kerning(face.get(), previous, glyph, FT_KERNING_UNSCALED, &kern) == 0)
        pen.x += static_cast<double>(kern.x) * scale;
    }
    previous = glyph;
    if (FT_Load_Glyph(face.get(), glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0)
      throw SceneError(font_loc, fmt::format("font '{}': cannot load the glyph of character U+{:04X}", font, cp));
    const FT_GlyphSlot slot = face->glyph;
    // POV-Ray starts the string at its first glyph's left edge: the first character's left side
    // bearing is taken off the whole line (measured against POV-Ray 3.7: "oH" and "Ho" shift
    // by o's and H's bearing, the spacing after unchanged).
    if (first) pen.x -= static_cast<double>(slot->metrics.horiBearingX) * scale;
    first = false;
    if (slot->format == FT_GLYPH_FORMAT_OUTLINE && slot->outline.n_contours > 0) {
      OutlineSink sink{scale, {}, glm::dvec2(0.0)};
      FT_Outline_Decompose(&slot->outline, &funcs, &sink);
      if (sink.points.size() >= 4 && sink.points.size() <= static_cast<std::size_t>(kMaxPrismPoints)) {
        ShapeDesc s = base;
        PrismData g;
        g.points = std::move(sink.points);
        g.spline = SplineKind::Bezier;
        // Swept along y from -thickness to 0; turned by -90 degrees about x below, the outline's
        // second coordinate is the text's y and the sweep runs from z = 0 to z = thickness.
        g.height1 = -thickness;
        g.height2 = 0.0;
        PrismData probe = g;
        if (detail::prism_spline_curves(probe).empty()) {  // a contour that does not close is left out
          prism_setup(g);
          s.geometry = Prism(std::move(g));
          scene_.shapes.push_back(std::move(s));
          const NodeId node = add_node(scene_, NodeKind::Shape, scene_.shapes.size() - 1, ps.loc());
          const Mat4 place = glm::translate(Mat4(1.0), pen) *
                             glm::rotate(Mat4(1.0), glm::radians(-90.0), Vec3(1, 0, 0));
          group.children.push_back(Child{node, place, ps.loc()});
        }
      }
    }
    pen.x += static_cast<double>(slot->metrics.horiAdvance) * scale;
    pen += offset;
  }
  scene_.groups.push_back(std::move(group));
  return add_node(scene_, NodeKind::Group, scene_.groups.size() - 1, ps.loc());
}

}  // namespace rts::render
