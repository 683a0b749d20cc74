// The non-shape blocks' property tables (render/scene/block_properties.*): the builder accepts
// exactly the names they list (an unknown name is refused with the table's names in its
// suggestion), and the docs document each one.
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "render/builder/block_properties.hpp"
#include "render/builder/scene_builder.hpp"

using namespace rts::render;

namespace {

std::string all_docs() {
  std::string docs;
  for (const auto& f : std::filesystem::directory_iterator(std::string(RTS_SOURCE_DIR) + "/docs"))
    if (f.path().extension() == ".md") {
      std::ifstream in(f.path(), std::ios::binary);
      std::ostringstream ss;
      ss << in.rdbuf();
      docs += ss.str();
    }
  return docs;
}

}  // namespace

TEST_CASE("block property tables: complete entries, known kinds, documented names", "[kinds]") {
  const std::string docs = all_docs();
  REQUIRE(!block_infos().empty());
  for (const BlockInfo& b : block_infos()) {
    CAPTURE(b.kind);
    CHECK(SceneBuilder::category(b.kind) != BlockCategory::Unknown);
    CHECK(find_block_info(b.kind) == &b);
    CHECK(!b.meaning.empty());
    std::set<std::string_view> names;
    for (const PropertyInfo& p : b.properties) {
      CAPTURE(p.name);
      CHECK(names.insert(p.name).second);
      CHECK(!p.type.empty());
      CHECK(!p.default_value.empty());
      CHECK(!p.meaning.empty());
      INFO("document `" << p.name << "` of " << b.kind << " in docs/rendering.md");
      CHECK(docs.find(fmt::format("`{}`", p.name)) != std::string::npos);
    }
  }
  // Shapes come from their ShapeTraits, with `material` first and `casts_shadow` last.
  const BlockInfo* sphere = find_block_info("sphere");
  REQUIRE(sphere);
  CHECK(sphere->properties.size() == 4);
  CHECK(sphere->properties[0].name == "material");
  CHECK(sphere->properties[3].name == "casts_shadow");
  CHECK(find_block_info("teapot") == nullptr);
}

TEST_CASE("block property tables: the builder refuses a name not in the table, suggesting from it", "[kinds]") {
  SceneBuilder builder;
  ParamSet ps("camera", SourceRef{"t.rts", 1, 1});
  ps.add("focus_distanse", 2.0, SourceRef{"t.rts", 1, 10});
  try {
    builder.camera(ps);
    FAIL("an unknown camera property was accepted");
  } catch (const SceneError& e) {
    CHECK(std::string(e.what()).find("did you mean 'focus_distance'") != std::string::npos);
  }
}
