// The shape kinds' descriptors (render/geometry/shapes/<kind>.hpp, listed by ShapeGeometry) and
// everything derived from them or checked against them: the builder's kinds and property
// names, the feature names, docs/shapes.md's property tables, docs/runtime.md's list of shape
// kinds, and (for every block kind: shapes, lights, materials, textures, settings, camera,
// CSG) the docs and the fuzz dictionary. A new kind or property that is not documented, or not in the
// dictionary, fails here with the line to add.
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "render/geometry/shapes/shape_kinds.hpp"
#include "render/shade/features.hpp"
#include "render/builder/scene_builder.hpp"

using namespace rts::render;

namespace {

std::string read_text(const std::string& relative) {
  std::ifstream in(std::string(RTS_SOURCE_DIR) + "/" + relative, std::ios::binary);
  REQUIRE(in);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The text of `## name` up to the next `## ` heading.
std::string section(const std::string& doc, const std::string& name) {
  std::size_t a = doc.find("\n## " + name + "\n");
  if (a == std::string::npos) return "";
  std::size_t b = doc.find("\n## ", a + 1);
  return doc.substr(a, b == std::string::npos ? std::string::npos : b - a);
}

std::string table_of(const ShapeInfo& shape) {
  std::string t = "| Property | Type | Default | Meaning |\n|---|---|---|---|\n";
  for (const PropertyInfo& p : shape.properties)
    t += fmt::format("| `{}` | {} | {} | {} |\n", p.name, p.type, p.default_value, p.meaning);
  return t;
}

}  // namespace

TEST_CASE("shape descriptors: unique names and properties, one per ShapeGeometry alternative", "[kinds]") {
  std::set<std::string_view> names;
  for (std::size_t k = 0; k < kShapeKindCount; ++k) {
    const ShapeInfo& s = kShapeInfos[k];
    CAPTURE(s.name);
    CHECK(names.insert(s.name).second);
    CHECK(shape_name(k) == s.name);
    CHECK(find_shape(s.name) == &kShapeInfos[k]);
    CHECK(SceneBuilder::category(s.name) == BlockCategory::Shape);
    CHECK(feature_name(shape_feature(k)) == s.name);
    std::set<std::string_view> props;
    for (const PropertyInfo& p : s.properties) {
      CHECK(props.insert(p.name).second);
      CHECK(p.name != "material");  // every shape takes it; not listed per kind
      CHECK(!p.type.empty());
      CHECK(!p.default_value.empty());
      CHECK(!p.meaning.empty());
    }
  }
  CHECK(find_shape("teapot") == nullptr);
  CHECK(SceneBuilder::category("teapot") == BlockCategory::Unknown);
  // The builder's list of kinds holds every shape exactly once.
  std::size_t shapes_listed = 0;
  for (std::string_view k : SceneBuilder::block_kinds()) shapes_listed += find_shape(k) != nullptr;
  CHECK(shapes_listed == kShapeKindCount);
}

TEST_CASE("docs/shapes.md has each shape's property table exactly as its descriptor", "[kinds]") {
  const std::string doc = read_text("docs/shapes.md");
  for (const ShapeInfo& s : kShapeInfos) {
    const std::string name(s.name);
    CAPTURE(name);
    const std::string sec = section(doc, name);
    INFO("docs/shapes.md needs a section '## " << name << "' with this table:\n" << table_of(s));
    REQUIRE(!sec.empty());
    CHECK(sec.find(table_of(s)) != std::string::npos);
    CHECK(doc.find(fmt::format("| [{0}](#{0}) |", name)) != std::string::npos);  // the overview table
    CHECK(std::filesystem::exists(std::string(RTS_SOURCE_DIR) + "/docs/images/shape_" + name + ".rts"));
  }
  // docs/runtime.md's list of block kinds by category names every shape.
  const std::string runtime = read_text("docs/runtime.md");
  std::string list = "| shape | `";
  for (std::size_t k = 0; k < kShapeKindCount; ++k) {
    if (k > 0) list += ' ';
    list += kShapeInfos[k].name;
  }
  list += "` |";
  CHECK(runtime.find(list) != std::string::npos);
}

TEST_CASE("every block kind and property is documented and in the fuzz dictionary", "[kinds]") {
  const std::string dict = read_text("tests/fuzz/rts.dict");
  std::string docs;
  for (const auto& f : std::filesystem::directory_iterator(std::string(RTS_SOURCE_DIR) + "/docs"))
    if (f.path().extension() == ".md") docs += read_text("docs/" + f.path().filename().string());
  auto in_dict = [&](std::string_view word) { return dict.find(fmt::format("=\"{}\"\n", word)) != std::string::npos; };
  std::size_t properties = 0;
  for (std::string_view kind : SceneBuilder::block_kinds()) {
    CAPTURE(kind);
    INFO("add to tests/fuzz/rts.dict: prop_" << kind << "=\"" << kind << "\"");
    CHECK(in_dict(kind));
    CHECK(docs.find(fmt::format("`{}", kind)) != std::string::npos);
    // Lights, materials, textures, settings, camera, CSG blocks and shapes alike: every name
    // the builder accepts, from the same tables its unknown-property check uses.
    for (std::string_view name : SceneBuilder::property_names(kind)) {
      CAPTURE(name);
      ++properties;
      INFO("add to tests/fuzz/rts.dict: prop_" << name << "=\"" << name << "\", and document `" << name << "` of "
                                               << kind << " in docs/");
      CHECK(in_dict(name));
      CHECK(docs.find(fmt::format("`{}`", name)) != std::string::npos);
    }
  }
  // The tables are not empty: settings, camera, materials, lights and textures all have names.
  for (std::string_view kind : {"settings", "camera", "material", "point_light", "area_light", "checker", "marble",
                                "image_texture", "union"})
    CHECK(!SceneBuilder::property_names(kind).empty());
  CHECK(properties > 200);
  for (const ShapeInfo& s : kShapeInfos)
    for (const PropertyInfo& p : s.properties) {
      CAPTURE(s.name, p.name);
      INFO("add to tests/fuzz/rts.dict: prop_" << p.name << "=\"" << p.name << "\"");
      CHECK(in_dict(p.name));
    }
}
