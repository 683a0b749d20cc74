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
double mean(const glm::dvec3& c);

class Writer {
 public:
  explicit Writer(int depth = 0) : depth_(depth) {}
  void line(const std::string& text);      // at the current indentation
  void comments(const std::vector<std::string>& lines);
  void blank();
  void open(const std::string& text);      // "text {" and indent
  void close(const std::string& suffix = "");  // "}" + suffix and dedent
  const std::string& text() const { return out_; }

 private:
  std::string out_;
  int depth_ = 0;
};

// What every translation produces: the course scenes are right-handed (camera looking down
// -z, +x to its right), rts's view is left-handed; the objects and lights go into one group
// mirrored by `scale <-1, 1, 1>`, and the camera is written in the mirrored coordinates, so the
// course's numbers appear unchanged and the picture is not mirrored.
struct SceneText {
  std::vector<std::string> header;   // comment lines
  Writer top;                        // settings, camera, materials
  Writer world{1};                   // objects and lights, course coordinates
  std::string finish() const;
};

// The camera block, mirrored into rts's view (x negated).
void write_camera(Writer& w, const glm::dvec3& position, const glm::dvec3& look_at, const glm::dvec3& up,
                  double horizontal_fov, const std::string& note);

}  // namespace rts::import
