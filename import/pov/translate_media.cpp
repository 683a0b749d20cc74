// POV-Ray's `media` (in an object's interior, or the scene's atmosphere) as rts's media_*
// properties (docs/rendering.md#media). rts's media are physical: a phase function integrates
// to 1 over the sphere, where POV-Ray's do not (its isotropic phase is 1, not 1 / 4 pi). A
// POV-Ray scattering colour c is written as media_scattering = 4 pi c, which scatters as much
// light towards the eye as POV-Ray's; its extinction is then 4 pi c where POV-Ray's is c (times
// its `extinction`), and the importer says so.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "import/pov/translator.hpp"

namespace rts::import::pov {

Block Translator::density_as_pigment(const Block& density) {
  // A density is a pigment whose map gives numbers or greys: the same pattern block. Its
  // density_map holds colours (a color_map) or, by name, other densities (a pigment_map).
  Block as_pigment = density;
  as_pigment.kind = "pigment";
  for (Item& d : as_pigment.items)
    if (d.kind == Item::Nested && d.block->kind == "density_map") {
      auto copy = std::make_shared<Block>(*d.block);
      bool named = false;
      for (const Item& e : copy->items)
        if (e.kind == Item::MapEntry && e.block->items.size() >= 2 && e.block->items[1].kind == Item::Value &&
            e.block->items[1].args[0]->kind == Expr::Name)
          if (Symbol* s = lookup(e.block->items[1].args[0]->text); s && s->type == Type::Pigment) named = true;
      copy->kind = named ? "pigment_map" : "color_map";
      d.block = copy;
    }
  return as_pigment;
}

namespace {
constexpr double kPi = std::numbers::pi;

// POV-Ray's scattering types 2-4 have fixed shapes; rts's Henyey-Greenstein with the same mean
// cosine stands in for them (computed from POV-Ray's formulas: 1 + 9 ((1 + cos) / 2)^8 for Mie
// hazy, 1 + 50 ((1 + cos) / 2)^32 for Mie murky, 1 + cos^2 for Rayleigh).
const char* mean_cosine(int type) {
  switch (type) {
    case 2: return "0.4";    // Mie hazy
    case 3: return "0.567";  // Mie murky
    default: return "0";     // Rayleigh: symmetric
  }
}
}  // namespace

std::vector<std::pair<std::string, std::string>> Translator::media(const Block& b) {
  std::vector<std::pair<std::string, std::string>> props;
  auto set = [&](const std::string& name, const std::string& v) {
    for (auto& p : props)
      if (p.first == name) {
        p.second = v;
        return;
      }
    props.emplace_back(name, v);
  };
  bool density_seen = false;
  for (const Item& it : b.items) {
    if (it.kind == Item::Keyword) {
      const std::string& k = it.name;
      if ((k == "absorption" || k == "emission") && !it.args.empty()) {
        set("media_" + k, color_value(*it.args[0]));
      } else if (k == "method" || k == "intervals" || k == "samples" || k == "confidence" || k == "variance" ||
                 k == "ratio" || k == "jitter" || k == "aa_level" || k == "aa_threshold") {
        // How POV-Ray samples its media: rts marches settings.media_samples points (Whitted)
        // or samples exactly (path mode).
      } else {
        std::vector<std::string> t = transforms(it);
        if (!t.empty())
          unsupported(it.loc, k, "a transform on the media_density texture (media are not moved as a whole)", false);
        else
          unsupported(it.loc, k, "media_absorption, media_scattering, media_emission, media_density", false);
      }
      continue;
    }
    if (it.kind != Item::Nested) continue;
    const Block& n = *it.block;
    if (n.kind == "scattering") {
      int type = 1;
      std::string color;
      const Expr* extinction = nullptr;  // POV-Ray's extinction factor (default 1)
      for (const Item& s : n.items) {
        if (s.kind == Item::Value && color.empty() && s.args[0]->kind == Expr::Number && type == 1 &&
            &s == &n.items.front()) {
          type = static_cast<int>(s.args[0]->number);
        } else if (s.kind == Item::Value) {
          color = color_value(*s.args[0]);
        } else if (s.kind == Item::Keyword && (s.name == "color" || s.name == "colour") && !s.args.empty()) {
          color = color_value(*s.args[0]);
        } else if (s.kind == Item::Keyword && s.name == "eccentricity" && !s.args.empty()) {
          if (type == 5) set("media_eccentricity", value(*s.args[0]));
        } else if (s.kind == Item::Keyword && s.name == "extinction" && !s.args.empty()) {
          extinction = s.args[0].get();
        }
      }
      if (color.empty()) continue;
      set("media_scattering", "4 * pi * " + (color.find(' ') == std::string::npos ? color : "(" + color + ")"));
      if (type >= 2 && type <= 4) {
        set("media_eccentricity", mean_cosine(type));
        warn(n.loc, fmt::format("POV-Ray's scattering type {} is written as Henyey-Greenstein scattering of the "
                                "same mean cosine ({})", type, mean_cosine(type)));
      }
      // With `extinction 4 * pi` POV-Ray's medium is rts's exactly; otherwise the extinction by
      // scattering differs, and the user is told by how much.
      double x = 1.0;
      const bool literal = !extinction || literal_number(*extinction, x);
      if (!literal || std::abs(x - 4.0 * kPi) > 1e-6 * 4.0 * kPi)
        warn(n.loc, fmt::format("POV-Ray's scattering colour c is written as media_scattering = 4 pi c: the same "
                                "light scattered towards the eye (POV-Ray's phase functions are not normalised), "
                                "but {} POV-Ray's extinction by scattering (exact with `extinction 4 * pi`; "
                                "docs/rendering.md#media)",
                                literal ? fmt::format("{:.3g} times", 4.0 * kPi / x) : std::string("not")));
    } else if (n.kind == "density") {
      if (density_seen) {
        unsupported(n.loc, "density", "one media_density texture (POV-Ray multiplies several)", false);
        continue;
      }
      density_seen = true;
      const std::string tex = pigment_value(density_as_pigment(n));
      if (tex.find('{') == std::string::npos)
        unsupported(n.loc, "density", "a media_density pattern (bozo, granite, ...); a constant density scales "
                                      "the coefficients instead",
                    false);
      else
        set("media_density", tex);
    } else {
      unsupported(n.loc, n.kind, "media_absorption, media_scattering, media_emission, media_density", false);
    }
  }
  return props;
}

}  // namespace rts::import::pov
