// POV-Ray's textures chosen by a pattern as rts's material chosen by pattern
// (docs/textures.md#materials-chosen-by-pattern):
//
//   texture { checker texture { A } texture { B } }
//     → material { pattern = checker(rgb(0), rgb(1), 1)  materials = [A, B] }
//   texture { gradient y texture_map { [0 A] [0.5 A] [0.5 B] [1 B] } }
//     → material { pattern = gradient { axis = "y"  color_map = [[0, rgb(0.125)], ...] }
//                  materials = [A, A, B, B] }
//
// rts picks a material by the pattern's luminance in equal ranges, so entry i of n becomes the
// grey (i + 0.5) / n: between two entries the colour map's ramp crosses the boundary of their
// ranges half-way, where POV-Ray's blend is half and half. rts does not blend: the texture
// switches there (an entry repeated at the same value, the usual sharp map, is exact).
#include <fmt/format.h>

#include "import/pov/translator.hpp"

namespace rts::import::pov {

bool Translator::texture_pattern(const Block& b, MaterialProps& m) {
  const Item* map = nullptr;
  std::vector<const Item*> textures;
  bool checker = false;
  for (const Item& it : b.items) {
    if (it.kind == Item::Keyword && it.name == "checker" && it.args.empty()) checker = true;
    if (it.kind == Item::Nested && it.block->kind == "texture") textures.push_back(&it);
    if (it.kind == Item::Nested && it.block->kind == "texture_map") map = &it;
  }
  if (!(checker && textures.size() == 2 && !map) && !(map && !checker && textures.empty())) return false;

  // One choice's material, written out with POV-Ray's defaults.
  auto choice = [&](const Item& texture_item) {
    MaterialProps t;
    texture_part(texture_item, t);
    return material_text(t, true);
  };
  std::vector<std::string> materials;
  std::string pattern;
  if (checker) {
    std::string suffix;
    for (const Item& it : b.items)
      for (const std::string& t : transforms(it)) suffix += " " + t;
    // rts's checker gives color1 where POV-Ray's gives its first texture: black, the first choice.
    pattern = suffix.empty() ? "checker(rgb(0), rgb(1), 1)"
                             : "checker { color1 = rgb(0)  color2 = rgb(1) }" + suffix;
    for (const Item* t : textures) materials.push_back(choice(*t));
  } else {
    std::vector<std::string> values;
    for (const Item& e : map->block->items) {
      if (e.kind != Item::MapEntry || e.block->items.empty() || e.block->items[0].kind != Item::Value) continue;
      Item body;  // the entry's texture: what follows its value
      body.kind = Item::Nested;
      body.loc = e.loc;
      body.block = std::make_shared<Block>();
      body.block->kind = "texture";
      body.block->loc = e.loc;
      body.block->items.assign(e.block->items.begin() + 1, e.block->items.end());
      values.push_back(value(*e.block->items[0].args[0]));
      materials.push_back(choice(body));
    }
    if (materials.size() < 2 || materials.size() > 256) {
      unsupported(map->loc, "texture_map", "a texture_map of 2 to 256 literal entries", false);
      return false;
    }
    std::string colors;
    const double n = static_cast<double>(materials.size());
    for (std::size_t i = 0; i < materials.size(); ++i)
      colors += fmt::format("{}[{}, rgb({})]", i ? ", " : "[", values[i], num((static_cast<double>(i) + 0.5) / n));
    colors += "]";
    Block pigment_block;  // the pattern with its modifiers and transforms, and the map above
    pigment_block.kind = "pigment";
    pigment_block.loc = b.loc;
    for (const Item& it : b.items)
      if (&it != map) pigment_block.items.push_back(it);
    MaterialProps p;
    pattern_map_override_ = colors;
    pigment(pigment_block, p);
    pattern_map_override_.clear();
    for (const auto& [name, text] : p.props)
      if (name == "texture") pattern = text;
    if (pattern.empty()) return false;  // not a pattern rts has: pigment() warned
  }
  std::string list;
  for (const std::string& s : materials) list += (list.empty() ? "[" : ", ") + s;
  m = MaterialProps{};
  m.chosen = true;
  m.set("pattern", pattern);
  m.set("materials", list + "]");
  return true;
}

}  // namespace rts::import::pov
