// POV-Ray's `clipped_by` as rts's clip block: `sphere { ... clipped_by { box { ... } } }`
// becomes `clip { sphere { ... }  box { ... } }`. Transforms written before `clipped_by` move
// the object alone (POV-Ray attaches the clipping objects when it reads them); those after it
// move both, so they go after the block.
#include <fmt/format.h>

#include "import/pov/translator.hpp"

namespace rts::import::pov {

namespace {

bool is_transform(const Item& it) {
  if (it.kind == Item::Nested) return it.block->kind == "transform";
  return it.kind == Item::Keyword &&
         (it.name == "translate" || it.name == "rotate" || it.name == "scale" || it.name == "matrix" ||
          it.name == "transform");
}

}  // namespace

// Whether rts's CSG takes what `b` writes as a solid: a closed shape, a block of them, or a
// declared one (a macro's result or an open shape is not known to be).
bool Translator::solid_block(const Block& b) {
  const std::string& k = b.kind;
  if (k == "object") {
    for (const Item& it : b.items) {
      if (it.kind == Item::Value) {
        if (it.args[0]->kind != Expr::Name) return false;
        const Symbol* s = lookup(it.args[0]->text);
        return s && is_solid_kind(s->object_kind);
      }
      if (it.kind == Item::Nested && is_object_kind(it.block->kind)) return solid_block(*it.block);
    }
    return false;
  }
  if (!is_solid_kind(k)) return false;
  for (const Item& it : b.items) {
    if (it.kind == Item::Keyword && it.name == "open") return false;
    const bool csg = k == "union" || k == "merge" || k == "intersection" || k == "difference";
    if (!csg) continue;
    if (it.kind == Item::Nested && is_object_kind(it.block->kind) && !solid_block(*it.block)) return false;
    if (it.kind == Item::Value) return false;  // a macro call's members are not known here
  }
  return true;
}

bool Translator::clipped_object(Writer& w, const Block& b, const std::string& prefix, bool place) {
  const Item* clip = nullptr;
  for (const Item& it : b.items)
    if (it.kind == Item::Nested && it.block->kind == "clipped_by") {
      if (clip) return false;  // two clipped_by: object() warns
      clip = &it;
    }
  if (!clip) return false;
  std::vector<const Block*> clippers;
  for (const Item& it : clip->block->items) {
    // `clipped_by { bounded_by }` and anything but objects: object() warns.
    if (it.kind != Item::Nested || !is_object_kind(it.block->kind) || !solid_block(*it.block)) return false;
    clippers.push_back(it.block.get());
  }
  Block inner;  // the object without clipped_by and the transforms after it
  inner.kind = b.kind;
  inner.loc = b.loc;
  std::vector<const Item*> after;
  bool past = false;
  for (const Item& it : b.items) {
    if (&it == clip) {
      past = true;
    } else if (past && is_transform(it)) {
      after.push_back(&it);
    } else {
      inner.items.push_back(it);
    }
  }
  if (clippers.empty() || !solid_block(inner)) return false;
  std::string suffix;
  for (const Item* it : after)
    for (const std::string& t : transforms(*it)) suffix += " " + t;
  w.open(prefix + "clip");
  ++csg_depth_;  // a union inside stays a CSG block
  object(w, inner, "", place);
  for (const Block* c : clippers) object(w, *c, "", false);
  --csg_depth_;
  w.close(suffix);
  last_kind_ = "clip";
  return true;
}

}  // namespace rts::import::pov
