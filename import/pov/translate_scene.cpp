// POV-Ray statements as rts statements: diagnostics, directives, declarations and placements.
// Lights, the camera and global settings are in translate_view.cpp; includes, files and the
// entry point, import_pov, in translate_files.cpp.
#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "import/pov/reader.hpp"
#include "import/pov/translator.hpp"

namespace rts::import::pov {

// ---- diagnostics ----

void Translator::unsupported(Loc at, const std::string& keyword, const std::string& alternative, bool planned) {
  warn(at, fmt::format("POV-Ray's '{}' is not translated; closest in rts: {} ({})", keyword, alternative,
                       planned ? "planned" : "not planned"));
}

void Translator::warn(Loc at, const std::string& message) {
  Diagnostic d{file_, at.line, at.col, message};
  if (opt_.strict) throw PovError{d};
  for (const Diagnostic& w : result_.warnings)
    if (w.file == d.file && w.line == d.line && w.col == d.col && w.message == d.message) return;
  result_.warnings.push_back(d);
}

void Translator::error(Loc at, const std::string& message) const { throw PovError{Diagnostic{file_, at.line, at.col, message}}; }

bool Translator::missing_name(Loc at, const std::string& name, const std::string& what) {
  if (!library_known_ || lookup(name) || reader_names_.count(name)) return false;
  unsupported(at, name, fmt::format("rts's standard library has no {} of that name (docs/library.md); {}", what,
                                    what == "object" ? "it is left out" : "a default is used"),
              false);
  return true;
}

// ---- statements ----

void Translator::items(Writer& w, const std::vector<Item>& list, bool top) {
  for (const Item& it : list) item(w, it, top);
}

// Names a loop or if body declares before the code after it uses them: POV-Ray's #declare is
// global, rts's `let` lives in its body, so they are declared (as none) before the statement.
void Translator::hoist(Writer& w, const std::vector<Item>& body) {
  std::vector<const std::vector<Item>*> todo = {&body};
  while (!todo.empty()) {
    const std::vector<Item>* list = todo.back();
    todo.pop_back();
    for (const Item& it : *list) {
      if (it.kind == Item::Declare && !it.local && it.args.size() == 1 && !declared(it.name)) {
        w.line(fmt::format("let {} = none  // declared inside the {} below", rename(it.name),
                           "block"));
        define(it.name, Symbol{Type::Unknown, nullptr, ""});
      }
      if (it.kind == Item::If || it.kind == Item::While || it.kind == Item::For || it.kind == Item::Switch ||
          it.kind == Item::Case) {
        todo.push_back(&it.body);
        todo.push_back(&it.else_body);
      }
    }
  }
}

void Translator::item(Writer& w, const Item& it, bool top) {
  w.comments(it.comments);
  // A macro's, loop's or condition's body is rts statements: `name = value` assigns there.
  const bool opens_body = it.kind == Item::Macro || it.kind == Item::While || it.kind == Item::For ||
                          it.kind == Item::Switch || (it.kind == Item::If && !it.ifdef);
  BodyFlag body(in_block_body_, opens_body ? false : in_block_body_);
  switch (it.kind) {
    case Item::Value: {
      // A macro call is a statement in rts too (it places what the macro makes); any other
      // value standing alone (`#declare A = A y+ x;` reads as A, then `y + x`) is not one.
      if (it.args[0]->kind != Expr::Call) {
        warn(it.loc, "a value where POV-Ray expects an object, a directive or a declaration; it is dropped");
        return;
      }
      Text t = expr(*it.args[0]);
      // A macro that #declares one of its parameters changes the caller's variable in
      // POV-Ray (Turn_Me(Thing, ...)): the translated macro returns it, assigned here.
      if (Symbol* s = lookup(it.args[0]->text); s && s->type == Type::Macro && s->out_param >= 0) {
        const auto k = static_cast<std::size_t>(s->out_param);
        if (k < it.args[0]->args.size() && it.args[0]->args[k]->kind == Expr::Name &&
            declared(it.args[0]->args[k]->text)) {
          w.line(rename(it.args[0]->args[k]->text) + " = " + t.s);
          return;
        }
      }
      w.line(t.s);
      return;
    }
    case Item::Keyword:
      unsupported(it.loc, it.name, "a statement such as an object, a light or settings { }", false);
      return;
    case Item::MapEntry: return;
    case Item::Nested: place_block(w, *it.block); return;
    case Item::Declare: declare(w, it); return;
    case Item::Macro: {
      // What the macro gives, when its body is one block (a pigment, a texture, an object):
      // a texture { M(...) } of a pigment macro is then a pattern, not a material to derive.
      std::string gives;
      for (const Item& b : it.body)
        if (b.kind == Item::Nested) gives = gives.empty() ? b.block->kind : "several";
      if (gives == "pigment") {
        // A pattern rts translates (its transforms then move it), or a colour or a pattern it
        // does not (written as the material's colour, whatever the macro gives).
        bool pattern = false;
        for (const Item& b : it.body)
          if (b.kind == Item::Nested)
            for (const Item& p : b.block->items)
              pattern = pattern || (p.kind == Item::Keyword && (pigment_pattern(p.name) || p.name == "checker")) ||
                        (p.kind == Item::Nested && p.block->kind == "image_map");
        if (!pattern) gives = "pigment colour";
      }
      Symbol macro{Type::Macro, nullptr, gives};
      // A parameter the body #declares (not #local): POV-Ray's by-reference argument.
      {
        std::vector<int> assigned;
        std::vector<const std::vector<Item>*> todo = {&it.body};
        while (!todo.empty()) {
          const std::vector<Item>* list = todo.back();
          todo.pop_back();
          for (const Item& b : *list) {
            if (b.kind == Item::Declare && !b.local && b.args.size() == 1)
              for (std::size_t i = 0; i < it.params.size(); ++i)
                if (it.params[i] == b.name &&
                    std::find(assigned.begin(), assigned.end(), static_cast<int>(i)) == assigned.end())
                  assigned.push_back(static_cast<int>(i));
            if (b.kind == Item::If || b.kind == Item::While || b.kind == Item::For || b.kind == Item::Switch ||
                b.kind == Item::Case) {
              todo.push_back(&b.body);
              todo.push_back(&b.else_body);
            }
          }
        }
        if (assigned.size() == 1) macro.out_param = assigned[0];
      }
      define(it.name, macro);
      std::string params;
      for (const std::string& p : it.params) params += (params.empty() ? "" : ", ") + rename(p);
      w.open(fmt::format("macro {}({})", rename(it.name), params));
      scopes_.emplace_back();
      scopes_.back()[kMacroScope] = Symbol{};   // #local's reach ends here
      ++macro_depth_;
      for (const std::string& p : it.params) define(p, Symbol{Type::Unknown, nullptr, ""});
      // A body that is one value (an object, a texture, an expression) gives it back.
      std::vector<const Item*> real;
      for (const Item& b : it.body)
        if (b.kind != Item::Declare) real.push_back(&b);
      bool one_value = real.size() == 1 && (real[0]->kind == Item::Value ||
                                            (real[0]->kind == Item::Nested && is_object_kind(real[0]->block->kind)));
      if (one_value) {
        for (const Item& b : it.body)
          if (&b != real[0]) item(w, b, false);
        w.comments(real[0]->comments);
        if (real[0]->kind == Item::Value) w.line("return " + value(*real[0]->args[0]));
        else object(w, *real[0]->block, "return ", false);
      } else if (real.size() == 1 && real[0]->kind == Item::Nested &&
                 (real[0]->block->kind == "texture" || real[0]->block->kind == "pigment" ||
                  real[0]->block->kind == "finish")) {
        for (const Item& b : it.body)
          if (&b != real[0]) item(w, b, false);
        MaterialProps m;
        texture_part(*real[0], m);
        w.line("return " + (real[0]->block->kind == "pigment" ? pigment_value(*real[0]->block) : material_text(m, true)));
      } else {
        items(w, it.body, false);
        // POV-Ray's by-reference parameter: given back, and assigned by the call (Item::Value).
        if (macro.out_param >= 0) w.line("return " + rename(it.params[static_cast<std::size_t>(macro.out_param)]));
      }
      --macro_depth_;
      scopes_.pop_back();
      w.close();
      return;
    }
    case Item::While: {
      hoist(w, it.body);
      w.open("while " + condition(*it.args[0]));
      scopes_.emplace_back();
      items(w, it.body, false);
      scopes_.pop_back();
      w.close();
      return;
    }
    case Item::For: {
      hoist(w, it.body);
      // A range's ends and step are additive-level expressions in rts: a lower one (`#for (R, 0,
      // !1)`: `not 1 != 0`, which the fuzzer found) goes in parentheses.
      auto bound = [&](const Expr& e) {
        const Text t = expr(e);
        return t.prec < 7 ? "(" + t.s + ")" : t.s;
      };
      std::string step = it.args.size() > 2 ? " step " + bound(*it.args[2]) : "";
      w.open(fmt::format("for {} in {} ..= {}{}", rename(it.name), bound(*it.args[0]), bound(*it.args[1]), step));
      scopes_.emplace_back();
      define(it.name, Symbol{Type::Float, nullptr, ""});
      items(w, it.body, false);
      scopes_.pop_back();
      w.close();
      return;
    }
    case Item::If: {
      // #ifdef(A[i]): whether the element has a value (pov_array's elements start as none),
      // asked when the scene runs; any other #ifdef is answered here.
      const bool element = it.ifdef && it.args.size() > 1 && declared(it.args[0]->text);
      if (it.ifdef && !element) {
        // #ifdef: whether the name is declared at this point of the translation.
        bool d = declared(it.args[0]->text) != it.negate;
        w.line(fmt::format("// #{}({}): {} when translated", it.negate ? "ifndef" : "ifdef", it.args[0]->text,
                           d ? "true" : "false"));
        items(w, d ? it.body : it.else_body, top);
        return;
      }
      hoist(w, it.body);
      hoist(w, it.else_body);
      w.open("if " + (element ? fmt::format("{}[{}] {} none", rename(it.args[0]->text), value(*it.args[1]),
                                            it.negate ? "==" : "!=")
                              : condition(*it.args[0])));
      scopes_.emplace_back();
      items(w, it.body, false);
      scopes_.pop_back();
      if (!it.else_body.empty()) {
        w.middle("else");
        scopes_.emplace_back();
        items(w, it.else_body, false);
        scopes_.pop_back();
      }
      w.close();
      return;
    }
    case Item::Switch: {
      hoist(w, it.body);
      Text v = expr(*it.args[0]);
      std::string sel = "pov_switch";
      w.line(fmt::format("let {} = {}  // #switch", sel, v.s));
      bool first = true, had_else = false;
      for (const Item& c : it.body) {
        if (had_else) {
          // After the #else nothing is reached (fuzz_pov: a second #else wrote a second else).
          warn(c.loc, "a #switch clause after its #else is never reached: left out");
          continue;
        }
        had_else = c.name == "else";
        std::string cond;
        // A case value with operators goes in parentheses (fuzz_pov: `#case (a & b)` wrote
        // `pov_switch == a != 0 and b != 0`, a chained comparison).
        auto operand = [&](const Expr& e) {
          const std::string v = value(e);
          return v.find(' ') == std::string::npos ? v : "(" + v + ")";
        };
        if (c.name == "case") cond = fmt::format("{} == {}", sel, operand(*c.args[0]));
        else if (c.name == "range")
          cond = fmt::format("{0} >= {1} and {0} <= {2}", sel, operand(*c.args[0]), operand(*c.args[1]));
        if (c.name == "else") {
          if (first) w.open("if true");
          else w.middle("else");
        } else if (first) {
          w.open("if " + cond);
        } else {
          w.middle("else if " + cond);
        }
        first = false;
        scopes_.emplace_back();
        items(w, c.body, false);
        scopes_.pop_back();
      }
      if (!first) w.close();
      return;
    }
    case Item::Include: include(w, it); return;
    case Item::Version: {
      double v;
      if (literal_number(*it.args[0], v)) version_ = v;
      w.line("// #version " + value(*it.args[0]));
      return;
    }
    case Item::Default: {
      for (const Item& d : it.block->items) {
        if (d.kind == Item::Nested && (d.block->kind == "finish" || d.block->kind == "pigment" ||
                                       d.block->kind == "texture" || d.block->kind == "normal")) {
          texture_part(d, default_texture_);
        } else {
          unsupported(d.loc, "#default", "the value written where it is used", false);
        }
      }
      w.line("// #default: POV-Ray's defaults changed; written into each material below");
      return;
    }
    case Item::Message: {
      if (it.name == "error") w.line("error(" + value(*it.args[0]) + ")");
      else if (it.name == "debug" || it.name == "warning") w.line("print(" + value(*it.args[0]) + ")");
      return;
    }
    case Item::Ignored:
      if (it.name != "undef") unsupported(it.loc, "#" + it.name, "values written into the scene", false);
      return;
    case Item::Case: return;
  }
}

void Translator::declare(Writer& w, const Item& it) {
  if (it.local && !include_stem_.empty() && scopes_.size() == 1 && it.args.size() == 1 &&
      !std::any_of(include_shadows_.back().begin(), include_shadows_.back().end(),
                   [&](const auto& s) { return s.first == it.name; })) {
    // A #local at an include file's top level: the file's own name (see aliases_), an alias
    // that no symbol has, under which the file's later uses write it.
    std::string alias = it.name + "_" + include_stem_;
    for (auto c = alias.begin(); c != alias.end(); ++c)
      if (!std::isalnum(static_cast<unsigned char>(*c))) *c = '_';
    for (int k = 2; lookup(alias) || std::any_of(aliases_.begin(), aliases_.end(), [&](const auto& a) {
                      return a.second == alias;
                    });
         ++k)
      alias = fmt::format("{}_{}_{}", it.name, include_stem_, k);
    auto& global = scopes_.front();
    auto before = global.find(it.name);
    include_shadows_.back().emplace_back(it.name, before == global.end() ? std::nullopt
                                                                          : std::optional<Symbol>(before->second));
    if (before != global.end()) global.erase(before);
    aliases_[it.name] = alias;
  }
  const std::string n = rename(it.name);
  if (it.args.size() >= 2) {  // #declare A[i] = v, A[i][j] = v
    // rts's lists are values: the element changes in a copy, A = with_item(A, i, v), nested
    // for each further index (A = with_item(A, i, with_item(A[i], j, v))).
    std::string v = value(*it.args[0]);
    for (std::size_t k = it.args.size() - 1; k >= 1; --k) {
      std::string list = n;
      for (std::size_t j = 1; j < k; ++j) list += fmt::format("[{}]", value(*it.args[j]));
      v = fmt::format("with_item({}, {}, {})", list, value(*it.args[k]), v);
    }
    if (in_block_body_) w.open("if true");  // directly in a block, `name = value` is a property
    w.line(fmt::format("{} = {}", n, v));
    if (in_block_body_) w.close();
    return;
  }
  const Expr& e = *it.args[0];
  // POV-Ray's #local names belong to the macro or file: its #while, #for and #if open no
  // scope, so a #local of a name the macro (or file) already has, even outside the loop it is
  // in, assigns it (rts's loop bodies are scopes: a `let` there would start a new name each
  // pass, and `#local Col = Col + 1` in a #while would never end).
  bool in_pov_scope = false;
  for (auto sc = scopes_.rbegin(); sc != scopes_.rend(); ++sc) {
    if (sc->count(it.name)) {
      in_pov_scope = true;
      break;
    }
    if (sc->count(kMacroScope)) break;
  }
  bool exists = lookup(it.name) != nullptr && (!it.local || in_pov_scope);
  if (exists && in_block_body_) {
    // Directly in a block, rts reads `name = value` as the block's property.
    w.open("if true");
    {
      BodyFlag statements(in_block_body_, false);
      declare(w, it);
    }
    w.close();
    return;
  }
  std::string head = exists ? n + " = " : "let " + n + " = ";
  if (e.kind == Expr::BlockValue) {
    const Block& b = *e.block;
    Symbol s;
    s.block = e.block;
    if (is_object_kind(b.kind)) {
      s.type = Type::Object;
      s.object_kind = b.kind == "object" ? "object" : b.kind;
      if (b.kind == "object")
        for (const Item& r : b.items)
          if (r.kind == Item::Value && r.args[0]->kind == Expr::Name) {
            if (Symbol* inner = lookup(r.args[0]->text)) s.object_kind = inner->object_kind;
            break;
          }
      s.textured = has_texture(b);  // before N is redefined: `object { N texture { } }` names the old N
      object(w, b, head, false);
      if (b.kind != "object") s.object_kind = last_kind_;
    } else if (b.kind == "texture" || b.kind == "material" || b.kind == "layered_texture") {
      s.type = Type::Material;
      MaterialProps m;
      Item part;
      part.kind = Item::Nested;
      part.block = e.block;
      texture_part(part, m);
      w.line(head + material_text(m, true));
    } else if (b.kind == "pigment") {
      s.type = Type::Pigment;
      w.line(head + pigment_value(b));
    } else if (b.kind == "density") {
      // A declared density (a pattern of numbers): a texture, as a pigment is.
      s.type = Type::Pigment;
      w.line(head + pigment_value(density_as_pigment(b)));
    } else if (b.kind == "sky_sphere") {
      s.object_kind = "sky_sphere";   // used by name in a scene's sky_sphere { }
      const std::string sky = sky_sphere_value(b);
      w.line(head + (sky.empty() ? "none  // a sky_sphere without a pigment" : sky));
    } else if (b.kind == "finish") {
      s.type = Type::Finish;
      finish(b, s.props);
      w.line(fmt::format("// finish {}: written into each material that uses it", it.name));
      define(it.name, s);
      return;
    } else if (b.kind == "interior" || b.kind == "transform" || b.kind == "normal") {
      s.type = b.kind == "interior" ? Type::Interior : b.kind == "normal" ? Type::Normal : Type::Transform;
      if (s.type == Type::Interior) interior(b, s.props);
      if (s.type == Type::Transform) {
        Item whole;
        whole.kind = Item::Nested;
        whole.block = e.block;
        s.steps = transforms(whole);
      }
      w.line(fmt::format("// {} {}: written where it is used", b.kind, it.name));
    } else if (b.kind == "light_source") {
      s.type = Type::Light;
      light(w, b, head);
    } else if (b.kind == "color_map" || b.kind == "colour_map" || b.kind == "pigment_map") {
      s.type = Type::List;
      Block p;
      p.kind = "pigment";
      Item gi;
      gi.kind = Item::Keyword;
      gi.name = "gradient";
      p.items.push_back(gi);
      Item mi;
      mi.kind = Item::Nested;
      mi.block = e.block;
      p.items.push_back(mi);
      std::string g = pigment_value(p);
      auto at = g.find("color_map = ");
      w.line(head + (at == std::string::npos ? "[]" : g.substr(at + 12, g.size() - at - 12 - 2)));
    } else if (b.kind == "function") {
      // A function of x, y, z (or of its named parameters): a macro, called as POV-Ray calls it.
      std::string why;
      if (!declare_function(w, it.name, b, why)) {
        unsupported(b.loc, "function with " + why,
                    "a function written as one expression of its parameters, with the math builtins and declared functions",
                    false);
        w.line(head + "none  // POV-Ray's function is not translated");
        define(it.name, Symbol{Type::Unknown, nullptr, ""});  // not a macro: a function calling it is refused too
        return;
      }
      define(it.name, Symbol{Type::Macro, nullptr, ""});
      return;
    } else if (b.kind == "camera") {
      s.type = Type::Camera;
      w.line(fmt::format("// camera {}: written where it is placed", it.name));
    } else {
      unsupported(b.loc, b.kind, "a value rts has (docs/from-povray.md)", false);
      w.line(head + "none  // POV-Ray's " + b.kind + " is not translated");
    }
    define(it.name, s);
    return;
  }
  Text t = expr(e);
  w.line(head + t.s);
  if (!exists || lookup(it.name)->type == Type::Unknown) {
    Symbol s;
    s.type = t.type;
    if (e.kind == Expr::Name)
      if (Symbol* src = lookup(e.text)) s = *src;
    if (it.local || !exists) define(it.name, s);
    else *lookup(it.name) = s;
  }
}

void Translator::place_block(Writer& w, const Block& b) {
  const std::string& k = b.kind;
  if (is_object_kind(k)) return object(w, b, "", true);
  if (k == "light_source") return light(w, b, "");
  if (k == "camera") return camera(w, b);
  if (k == "global_settings") return global_settings(w, b);
  if (k == "background") {
    for (const Item& it : b.items) {
      const Expr* c = it.kind == Item::Value ? it.args[0].get()
                      : (it.kind == Item::Keyword && !it.args.empty()) ? it.args[0].get() : nullptr;
      if (c) {
        w.line("settings { background = " + color_value(*c) + " }");
        return;
      }
    }
    return;
  }
  if (k == "fog") {
    std::string props;
    double filter = 0, transmit = 0;  // the colour's: POV-Ray's fog tint and least transmittance
    auto colour = [&](const Expr& e) {
      std::string c = color_value(e, &filter, &transmit);
      return "  fog_color = " + c;
    };
    for (const Item& it : b.items) {
      if (it.kind == Item::Keyword && !it.args.empty()) {
        if (it.name == "distance") props += "  fog_distance = " + value(*it.args[0]);
        else if (it.name == "color" || it.name == "colour") props += colour(*it.args[0]);
        else if (it.name == "fog_offset") props += "  fog_offset = " + value(*it.args[0]);
        else if (it.name == "fog_alt") props += "  fog_altitude = " + value(*it.args[0]);
        else if (it.name == "turbulence") props += "  fog_turbulence = " + vector_value(*it.args[0]);
        else if (it.name == "turb_depth" || it.name == "octaves" || it.name == "omega" || it.name == "lambda")
          props += "  fog_" + it.name + " = " + value(*it.args[0]);
        else if (it.name != "fog_type")
          unsupported(it.loc, it.name, "fog_distance, fog_color, fog_offset, fog_altitude, fog_turbulence", false);
      } else if (it.kind == Item::Value) {
        props += colour(*it.args[0]);
      } else if (it.kind == Item::Nested) {
        unsupported(it.loc, it.block->kind, "constant or ground fog", false);
      }
    }
    if (filter > 0) props += "  fog_filter = " + num(filter);
    if (transmit > 0) props += "  fog_transmit = " + num(transmit);
    if (props.empty()) return;  // nothing rts reads (fuzz_pov: a fog of unknown words only)
    w.line("settings {" + props.substr(1) + " }");
    return;
  }
  if (k == "sky_sphere") return sky_sphere(w, b);
  if (k == "radiosity") {
    unsupported(b.loc, "radiosity", "settings { integrator = \"path\" }", true);
    return;
  }
  if (k == "media") {
    // The atmosphere: rts's settings medium fills the space around the objects.
    std::string props;
    for (const auto& p : media(b)) props += "  " + p.first + " = " + p.second;
    if (!props.empty()) w.line("settings {" + props.substr(1) + " }");
    return;
  }
  if (k == "photons" || k == "rainbow") {
    unsupported(b.loc, k, "none", false);
    return;
  }
  unsupported(b.loc, k, "see docs/from-povray.md", false);
}

}  // namespace rts::import::pov
