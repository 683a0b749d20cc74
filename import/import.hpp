// `rts import`: converts a course scene file into a readable .rts scene.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace rts::import {

enum class Format { Mit, Csci420, UwRay };
const char* format_name(Format f);

// A located problem in the input ("file:line:col: error: message" once printed).
struct ImportError : std::runtime_error {
  ImportError(int line_, int col_, const std::string& message)
      : std::runtime_error(message), line(line_), col(col_) {}
  int line, col;
};

struct MeshFile {
  std::string name;   // file name, written beside the .rts
  std::string text;   // OBJ text
};

struct ImportResult {
  Format format = Format::Mit;
  std::string rts;                 // the scene
  std::vector<MeshFile> meshes;    // OBJ files the scene names
};

struct ImportOptions {
  std::string source_name;   // the input as named on the command line (for the header comment)
  std::string source_dir;    // the input's directory: paths in the input are relative to it
  std::string output_dir;    // where the .rts (and meshes) will live: paths are made relative to it
  std::string mesh_prefix;   // meshes are written as <prefix>_mesh<N>.obj

  // The course programs' own command-line flags and switches, written into the scene as
  // settings so that a plain `rts render` makes the course's image (docs/from-courses.md).
  // MIT 6.837 a2: -size W H, -bounces N, -shadows.
  int width = 0, height = 0;   // 0: the format's default
  int bounces = 0;             // mirror reflection (ks · I_reflected) up to N bounces; 0: none
  bool shadows = false;        // shadow rays only when asked
  // CSCI 420 extra credit: recursive reflection, supersampling, soft shadows by sub-lights.
  int reflection = 0;          // (1 - ks) · local + ks · reflected up to depth N; 0: none
  int antialias = 1;           // N x N samples per pixel
  int soft_shadows = 0;        // each point light split into N jittered sub-lights; 0: none
  double soft_shadow_radius = 0.1;  // the sub-lights lie within this distance of the light
  // Any format: the extra images (-normals, -depth dmin dmax) and their mappings.
  std::string aovs;            // "normal,depth" or empty
  bool has_depth_range = false;
  double depth_near = 0.0, depth_far = 1.0;
};

// The format from the content: "SBT-raytracer" → UW; a leading count or "amb:" → CSCI 420;
// MIT's block names (PerspectiveCamera, OrthographicCamera, ...) → MIT. Falls back on the
// extension (.ray, .scene, .txt). Throws ImportError when it cannot tell.
Format detect_format(const std::string& text, const std::string& path);

ImportResult import_scene(const std::string& text, Format format, const ImportOptions& options);

}  // namespace rts::import
