// POV-Ray's sky_sphere as rts's sky_sphere environment (docs/library.md#sky_sphere): each
// pigment a layer in the same order (the first at the bottom), a colour map entry's filter and
// transmit as its transmit, the sky's own transforms after the block.
#include "import/pov/translator.hpp"

namespace rts::import::pov {

std::string Translator::sky_sphere_value(const Block& b) {
  std::string layers, suffix, named;
  for (const Item& it : b.items) {
    if (it.kind == Item::Nested && it.block->kind == "pigment") {
      layers += (layers.empty() ? "" : ", ") + pigment_value(*it.block);
      continue;
    }
    if (it.kind == Item::Keyword && it.name == "emission") {
      // POV-Ray 3.7.1's sky brightness factor; rts's sky is as bright as its colours.
      unsupported(it.loc, "sky_sphere emission", "brighter layer colours", false);
      continue;
    }
    std::vector<std::string> t = transforms(it);
    if (!t.empty()) {
      for (const std::string& step : t) suffix += " " + step;
      continue;
    }
    if (it.kind == Item::Value && it.args[0]->kind == Expr::Name) {
      Symbol* s = lookup(it.args[0]->text);
      if (s && s->type == Type::Pigment) {
        layers += (layers.empty() ? "" : ", ") + rename(it.args[0]->text);
        continue;
      }
      if (s && s->object_kind == "sky_sphere" && named.empty() && layers.empty()) {
        // A declared sky (the scene's, or skies.inc's S_Cloud1 ... in rts's skies.rts).
        named = rename(it.args[0]->text);
        continue;
      }
      unsupported(it.loc, "sky_sphere " + it.args[0]->text,
                  s ? "one declared sky_sphere, alone" : "a sky from skies.rts (settings { environment = S_Cloud1 })", false);
      continue;
    }
    if (!named.empty()) {
      unsupported(it.loc, "a layer added to a declared sky_sphere", "the declared sky, or every layer written out", false);
      continue;
    }
    unsupported(it.loc, it.kind == Item::Nested ? it.block->kind : it.name, "pigment layers and transforms", false);
  }
  if (!named.empty()) return suffix.empty() ? named : "(" + named + ")" + suffix;
  if (layers.empty()) return "";
  return "sky_sphere { layers = [" + layers + "] }" + suffix;
}

void Translator::sky_sphere(Writer& w, const Block& b) {
  // POV-Ray's sky_sphere without a pigment shows nothing (the background); so does rts's scene
  // without one.
  const std::string sky = sky_sphere_value(b);
  if (!sky.empty()) w.line("settings { environment = " + sky + " }");
}

}  // namespace rts::import::pov
