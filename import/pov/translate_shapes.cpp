// POV-Ray shapes whose components are blocks of their own: a blob's spheres and cylinders
// become the list properties of rts's blob (docs/shapes.md#blob).
#include <fmt/format.h>

#include "import/pov/translator.hpp"

namespace rts::import::pov {

Block Translator::blob_components(const Block& b, std::vector<std::string>& props) {
  Block rest;
  rest.kind = b.kind;
  rest.loc = b.loc;
  std::string spheres, cylinders;
  for (const Item& it : b.items) {
    if (it.kind == Item::Keyword && it.name == "threshold" && !it.args.empty()) {
      props.push_back("threshold = " + value(*it.args[0]));
      continue;
    }
    if (it.kind == Item::Keyword && (it.name == "sturm" || it.name == "hierarchy")) continue;  // solver hints
    if (it.kind == Item::Keyword && it.name == "component") {
      // The old form: component strength, radius, <centre>.
      if (it.args.size() < 3) error(it.loc, "'component' needs a strength, a radius and a centre");
      spheres += fmt::format("{}[{}, {}, {}]", spheres.empty() ? "" : ", ", vector_value(*it.args[2]),
                             value(*it.args[1]), value(*it.args[0]));
      continue;
    }
    if (it.kind == Item::Nested && (it.block->kind == "sphere" || it.block->kind == "cylinder")) {
      const Block& c = *it.block;
      std::vector<const Expr*> v;
      std::string translate;  // a literal translate moves the component; other modifiers are not carried
      for (const Item& ci : c.items) {
        if (ci.kind == Item::Value) v.push_back(ci.args[0].get());
        else if (ci.kind == Item::Keyword && ci.name == "strength" && !ci.args.empty()) v.push_back(ci.args[0].get());
        else if (ci.kind == Item::Keyword && ci.name == "translate" && !ci.args.empty() && translate.empty())
          translate = vector_value(*ci.args[0]);
        else
          unsupported(ci.loc, ci.kind == Item::Nested ? ci.block->kind + " (on a blob component)"
                                                      : ci.name + " (on a blob component)",
                      "the blob's own texture and transforms", false);
      }
      auto at = [&](std::size_t i) { return translate.empty() ? vector_value(*v[i])
                                                              : vector_value(*v[i]) + " + " + translate; };
      if (c.kind == "sphere") {
        if (v.size() < 3) error(c.loc, "a blob's 'sphere' needs a centre, a radius and a strength");
        spheres += fmt::format("{}[{}, {}, {}]", spheres.empty() ? "" : ", ", at(0), value(*v[1]), value(*v[2]));
      } else {
        if (v.size() < 4) error(c.loc, "a blob's 'cylinder' needs two ends, a radius and a strength");
        cylinders += fmt::format("{}[{}, {}, {}, {}]", cylinders.empty() ? "" : ", ", at(0), at(1), value(*v[2]),
                                 value(*v[3]));
      }
      continue;
    }
    rest.items.push_back(it);
  }
  if (!spheres.empty()) props.push_back("spheres = [" + spheres + "]");
  if (!cylinders.empty()) props.push_back("cylinders = [" + cylinders + "]");
  return rest;
}

}  // namespace rts::import::pov
