#include "import/import.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "import/tokens.hpp"
#include "import/writer.hpp"

namespace rts::import {

void import_mit(const std::string& text, const ImportOptions& opt, SceneText& out);       // mit.cpp
void import_csci420(const std::string& text, const ImportOptions& opt, SceneText& out);   // csci420.cpp
std::vector<MeshFile> import_uw(const std::string& text, const ImportOptions& opt, SceneText& out);   // uw_ray.cpp

const char* format_name(Format f) {
  switch (f) {
    case Format::Mit: return "MIT 6.837 scene";
    case Format::Csci420: return "USC CSCI 420 .scene";
    case Format::UwRay: return "UW CSE 457 SBT-raytracer 1.0 .ray";
  }
  return "?";
}

namespace {

// What a file is when it is not a course scene: a mesh, an rts scene, another renderer's
// format; "" when nothing is recognised.
std::string not_a_scene(const std::string& first, const std::string& ext, const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  if (ext == ".obj" || first == "v" || first == "vn" || first == "vt" || first == "f" || first == "mtllib" ||
      first == "o" || first == "usemtl")
    return fmt::format("'{}' is a Wavefront OBJ mesh, not a scene: place it in an rts scene with "
                       "mesh {{ file = \"{}\" }} (docs/shapes.md)", name, name);
  if (ext == ".rts") return fmt::format("'{}' is already an rts scene: render it with rts render", name);
  if (first == "ply" || ext == ".ply") return fmt::format("'{}' is a PLY mesh, which rts does not read: convert it to OBJ", name);
  if (ext == ".pbrt" || ext == ".gltf" || ext == ".glb" || ext == ".blend" || ext == ".xml" || ext == ".x3d")
    return fmt::format("'{}' is a {} file, which rts import does not translate (it reads the MIT 6.837, CSCI 420 "
                       "and UW CSE 457 course formats and POV-Ray scenes)", name, ext.substr(1));
  return "";
}

}  // namespace

Format detect_format(const std::string& text, const std::string& path) {
  Tokens tk(text);
  if (!tk.done()) {
    const std::string& first = tk.peek().text;
    if (first == "SBT-raytracer") return Format::UwRay;
    if (first == "PerspectiveCamera" || first == "OrthographicCamera" || first == "Lights" || first == "Background" ||
        first == "Materials" || first == "Group")
      return Format::Mit;
    if (first == "amb:" || (!first.empty() && std::isdigit(static_cast<unsigned char>(first[0])))) return Format::Csci420;
  }
  std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".ray") return Format::UwRay;
  if (ext == ".scene") return Format::Csci420;
  if (ext == ".txt") return Format::Mit;
  const Token& at = tk.peek();
  // Files people hand to `rts import` that are not scenes it translates: say what was read.
  if (const std::string what = not_a_scene(tk.done() ? std::string() : tk.peek().text, ext, path); !what.empty())
    throw ImportError(at.line, at.col, what);
  throw ImportError(at.line, at.col,
                    "cannot tell the format: expected 'SBT-raytracer 1.0' (UW .ray), an object count (CSCI 420 "
                    ".scene), an MIT block such as PerspectiveCamera, or a POV-Ray scene (.pov, --format pov)");
}

ImportResult import_scene(const std::string& text, Format format, const ImportOptions& options) {
  SceneText out;
  out.header.push_back(fmt::format("Imported by `rts import` from {} ({}).", options.source_name, format_name(format)));
  out.header.push_back("Course conventions kept: right-handed coordinates and the vertical field of view (the");
  out.header.push_back("camera's handedness and fov_axis), the course's shading terms as rts materials. See");
  out.header.push_back("docs/from-courses.md.");
  ImportResult result;
  result.format = format;
  switch (format) {
    case Format::Mit: import_mit(text, options, out); break;
    case Format::Csci420: import_csci420(text, options, out); break;
    case Format::UwRay: result.meshes = import_uw(text, options, out); break;
  }
  result.rts = out.finish();
  return result;
}

}  // namespace rts::import
