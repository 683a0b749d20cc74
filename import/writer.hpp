// Writing readable .rts text: numbers in their shortest exact form, vectors, colors, indented
// lines and carried-over comments.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace rts::import {

std::string num(double x);
std::string vec(const glm::dvec3& v);      // <x, y, z>
std::string rgb(const glm::dvec3& c);      // rgb(r, g, b), or rgb(g) when gray
std::string rts_string(const std::string& s);  // "s" with \ and " escaped
// A 4x4 column-vector matrix (m[row][col]) as rts's `matrix [...]` list (the 3x3 part column
// by column, then the translation: the order POV-Ray and rts use).
std::string matrix_list(const double m[4][4]);
// A course's specular color as rts's `specular` value: a number when gray, else rgb(r, g, b).
std::string specular_value(const glm::dvec3& c);
// Per-vertex specular colors as rts's `vertex_specular` list: numbers when every one is gray,
// else colors (one list holds one kind).
std::string specular_list(const std::vector<glm::dvec3>& colors);

class Writer {
 public:
  explicit Writer(int depth = 0) : depth_(depth) {}
  void line(const std::string& text);      // at the current indentation
  void comments(const std::vector<std::string>& lines);
  void blank();
  void open(const std::string& text);      // "text {" and indent
  void close(const std::string& suffix = "");  // "}" + suffix and dedent
  void middle(const std::string& text);          // "} text {" at the outer level: `} else {`
  const std::string& text() const { return out_; }

 private:
  std::string out_;
  int depth_ = 0;
};

// What every translation produces: the course scenes are right-handed (camera looking down
// -z, +x to its right); the camera says so (`handedness = "right"`), so objects, lights and
// camera keep the course's own numbers and the picture is not mirrored.
struct SceneText {
  std::vector<std::string> header;   // comment lines
  Writer top;                        // settings, camera, materials
  Writer world;                      // objects and lights, course coordinates
  std::string finish() const;
};

// Which image extent a perspective camera's angle spans.
enum class FovAxis { Horizontal, Vertical };

// A right-handed perspective camera block in the course's coordinates.
void write_camera(Writer& w, const glm::dvec3& position, const glm::dvec3& look_at, const glm::dvec3& up,
                  double fov, FovAxis axis, const std::string& note);

}  // namespace rts::import
