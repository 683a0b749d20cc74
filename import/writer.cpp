#include "import/writer.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace rts::import {

std::string num(double x) {
  // Ten significant digits: exact for what people type, and no 0.16000000000000003 from the
  // arithmetic of the translation (folded ambient terms, means, converted angles).
  std::string s = fmt::format("{:.10g}", x);
  return s == "-0" ? "0" : s;
}

std::string vec(const glm::dvec3& v) { return fmt::format("<{}, {}, {}>", num(v.x), num(v.y), num(v.z)); }

std::string rgb(const glm::dvec3& c) {
  if (c.x == c.y && c.y == c.z) return fmt::format("rgb({})", num(c.x));
  return fmt::format("rgb({}, {}, {})", num(c.x), num(c.y), num(c.z));
}

std::string rts_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string matrix_list(const double m[4][4]) {
  return fmt::format("[{}, {}, {},  {}, {}, {},  {}, {}, {},  {}, {}, {}]", num(m[0][0]), num(m[1][0]), num(m[2][0]),
                     num(m[0][1]), num(m[1][1]), num(m[2][1]), num(m[0][2]), num(m[1][2]), num(m[2][2]), num(m[0][3]),
                     num(m[1][3]), num(m[2][3]));
}

std::string specular_value(const glm::dvec3& c) { return c.x == c.y && c.y == c.z ? num(c.x) : rgb(c); }

std::string specular_list(const std::vector<glm::dvec3>& colors) {
  const bool gray = std::all_of(colors.begin(), colors.end(), [](const glm::dvec3& c) { return c == glm::dvec3(c.x); });
  std::string out;
  for (const glm::dvec3& c : colors) {
    out += out.empty() ? "[" : ", ";
    out += gray ? num(c.x) : fmt::format("rgb({}, {}, {})", num(c.x), num(c.y), num(c.z));
  }
  return out + "]";
}

void Writer::line(const std::string& text) {
  out_.append(static_cast<std::size_t>(depth_) * 4, ' ');
  out_ += text;
  out_ += '\n';
}

void Writer::comments(const std::vector<std::string>& lines) {
  for (const std::string& c : lines) line(c.empty() ? "//" : "// " + c);
}

void Writer::blank() {
  if (!out_.empty() && out_.size() >= 2 && out_.substr(out_.size() - 2) != "\n\n") out_ += '\n';
}

void Writer::open(const std::string& text) {
  line(text + " {");
  ++depth_;
}

void Writer::close(const std::string& suffix) {
  if (depth_ > 0) --depth_;
  line("}" + suffix);
}

void Writer::middle(const std::string& text) {
  if (depth_ > 0) --depth_;
  line("} " + text + " {");
  ++depth_;
}

std::string SceneText::finish() const {
  std::string out;
  for (const std::string& h : header) out += h.empty() ? "//\n" : "// " + h + "\n";
  out += "\n" + top.text();
  out += "\n// Objects and lights in the course's right-handed coordinates (the camera is right-handed).\n";
  out += world.text();
  return out;
}

void write_camera(Writer& w, const glm::dvec3& position, const glm::dvec3& look_at, const glm::dvec3& up,
                  double fov, FovAxis axis, const std::string& note) {
  if (!note.empty()) w.line("// " + note);
  w.line(fmt::format("camera {{ position = {}  look_at = {}  up = {}  fov = {}{}  handedness = \"right\" }}",
                     vec(position), vec(look_at), vec(up), num(fov),
                     axis == FovAxis::Vertical ? "  fov_axis = \"vertical\"" : ""));
}

}  // namespace rts::import
