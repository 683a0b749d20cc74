// Blocks (`sphere { ... }`, `material { ... }`, `group { ... }`), `with` derivation,
// transform postfixes, conversion of values to builder parameters, and object placement.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "render/geometry/csg/csg_tree.hpp"
#include "runtime/interpreter.hpp"
#include "runtime/povray_hints.hpp"

namespace rts::runtime {

namespace {

// Restores the interpreter state that a block body changes, however the body ends.
template <typename T>
struct Restore {
  T& ref;
  T saved;
  explicit Restore(T& r) : ref(r), saved(r) {}
  ~Restore() { ref = saved; }
};

using ObjectCount = Placement::ObjectCount;
constexpr uint64_t kSaturatedCount = Placement::kSaturatedCount;

void set_or_add(std::vector<Property>& props, Property p) {
  for (Property& q : props)
    if (q.name == p.name) {
      q = std::move(p);
      return;
    }
  props.push_back(std::move(p));
}

}  // namespace

void Interpreter::collect_properties(const ast::BlockBody& body, std::vector<Property>& props, bool allow_placement) {
  Restore<unsigned> loops(loop_depth_);
  Restore<bool> in_macro(in_macro_);
  Placement::Allow placement(placement_, allow_placement);
  loop_depth_ = 0;    // `break` cannot leave a block
  in_macro_ = false;  // nor can `return`
  check_stack(body.items.empty() ? current_loc_ : body.items.front().loc);
  push_scope();
  for (const ast::BlockItem& item : body.items) {
    if (item.property) {
      set_or_add(props, Property{item.property, eval(*item.value()), item.loc});
    } else {
      exec(*item.stmt());
    }
  }
  pop_scope();
}

Value Interpreter::eval_block(const ast::BlockExpr& e, bool keep_block) {
  const std::string& kind = *e.kind_name;
  render::BlockCategory cat = render::SceneBuilder::category(kind);
  switch (cat) {
    case render::BlockCategory::Unknown: {
      std::string msg = fmt::format("unknown block kind '{}'", kind);
      std::string hint = render::closest_name(kind, render::SceneBuilder::block_kinds());
      if (std::string pov = povray_hint(kind); !pov.empty())
        msg += pov;
      else if (!hint.empty())
        msg += fmt::format("; did you mean '{}'?", hint);
      fail(e.loc, msg);
    }
    case render::BlockCategory::Group: {
      std::vector<render::Child> children;
      std::vector<Property> props;
      {
        Placement::Into target(placement_, children);
        collect_properties(e.body, props, true);
      }
      // What the group expands to, checked now: groups of groups double at every level, and
      // 40 levels are 2^40 objects, which flattening would try to build.
      ObjectCount count = placement_.count(children);
      if (count.total() > options_.limits.max_objects)
        fail(e.loc, fmt::format("this group expands to {} objects, more than the limit of {} (groups inside groups "
                                "multiply; raise the limit with --max-objects)",
                                count.total() >= kSaturatedCount ? std::string("billions of")
                                                                  : std::to_string(count.total()),
                                options_.limits.max_objects));
      Value v;
      v.type = Type::Object;
      if (props.empty()) {
        v.id = builder_.group(std::move(children), ref(e.loc));
      } else {
        render::ParamSet ps = to_params(kind, e.loc, props);  // `material`: the members' default
        v.id = builder_.group(std::move(children), ps);
      }
      placement_.record(v.id, count);
      return v;
    }
    case render::BlockCategory::Csg: {
      // Like a group: the shapes placed in the body are its children; its properties are
      // the children's default material and `inverse`.
      std::vector<render::Child> children;
      std::vector<Property> props;
      {
        Placement::Into target(placement_, children);
        collect_properties(e.body, props, true);
      }
      ObjectCount count = placement_.count(children);
      if (count.total() > render::kMaxCsgLeaves)
        fail(e.loc, fmt::format("this {} holds {} shapes, more than the {} one CSG block can combine", kind,
                                count.total() >= kSaturatedCount ? std::string("billions of")
                                                                  : std::to_string(count.total()),
                                render::kMaxCsgLeaves));
      render::ParamSet ps = to_params(kind, e.loc, props);
      Value v;
      v.type = Type::Object;
      v.id = builder_.csg(kind, std::move(children), ps);
      placement_.record(v.id, ObjectCount{1, 0});
      return v;
    }
    case render::BlockCategory::Material:
    case render::BlockCategory::Texture: {
      auto rec = std::make_shared<RecordValue>();
      rec->kind = e.kind_name;
      rec->loc = e.loc;
      collect_properties(e.body, rec->props, false);
      rec->update_depth();
      Value v;
      v.type = cat == render::BlockCategory::Material ? Type::Material : Type::Texture;
      v.ref = std::move(rec);
      check_nesting(v, e.loc);
      return v;
    }
    default:
      break;
  }
  std::vector<Property> props;
  props.reserve(e.body.items.size());
  collect_properties(e.body, props, false);
  switch (cat) {
    case render::BlockCategory::Settings: {
      render::ParamSet ps = to_params(kind, e.loc, props);
      builder_.settings(ps);
      return Value::none();
    }
    case render::BlockCategory::Camera: {
      render::ParamSet ps = to_params(kind, e.loc, props);
      builder_.camera(ps);
      return Value::none();
    }
    case render::BlockCategory::Shape:
    case render::BlockCategory::Light: {
      if (!keep_block) return define_object(kind, e.loc, props);
      auto obj = std::make_shared<ObjectValue>();
      obj->kind = e.kind_name;
      obj->loc = e.loc;
      obj->props = std::move(props);
      return define_object(std::move(obj));
    }
    default:
      break;
  }
  fail(e.loc, "internal error: unhandled block category");
}

Value Interpreter::define_object(const std::string& kind, SourceLoc loc, const std::vector<Property>& props) {
  render::ParamSet ps = to_params(kind, loc, props);
  Value v;
  v.type = Type::Object;
  const bool shape = render::SceneBuilder::category(kind) == render::BlockCategory::Shape;
  v.id = shape ? builder_.shape(kind, ps) : builder_.light(kind, ps);
  placement_.record(v.id, shape ? ObjectCount{1, 0} : ObjectCount{0, 1});
  for (const render::SceneWarning& w : builder_.take_warnings()) {
    const SourceFile* file = includes_.file_named(w.where.file);
    warnings_.warning(file ? SourceLoc::at(file, w.where.line, w.where.col) : loc, w.message);
  }
  return v;
}

Value Interpreter::define_object(std::shared_ptr<ObjectValue> obj) {
  // A mesh is built when first placed (see realize_object): one never placed costs nothing and
  // its file is never opened. Other shapes and lights are cheap and built (so checked) now.
  if (*obj->kind != "mesh") obj->built_id = define_object(*obj->kind, obj->loc, obj->props).id;
  Value v;
  v.type = Type::Object;
  v.id = render::kNoId;  // the node is the definition's built_id
  v.ref = std::move(obj);
  return v;
}

uint32_t Interpreter::realize_object(const Value& object) {
  if (object.id != render::kNoId || !object.ref) return object.id;
  const ObjectValue& def = static_cast<const ObjectValue&>(*object.ref).definition();
  if (def.built_id == render::kNoId) def.built_id = define_object(*def.kind, def.loc, def.props).id;
  return def.built_id;
}

Value Interpreter::eval_with(const ast::WithExpr& e) {
  Value base = eval(*e.base);
  if (base.type == Type::Object) {
    const ObjectValue* def = object_definition(base);
    if (!def) fail(e.base->loc, "cannot derive a group with 'with'");
    // A new definition: the base block's properties, overridden, under the base's transform.
    auto obj = std::make_shared<ObjectValue>();
    obj->transform = object_transform(base);
    obj->kind = def->kind;
    obj->props = def->props;
    obj->loc = e.loc;
    collect_properties(e.body, obj->props, false);
    return define_object(std::move(obj));
  }
  if (base.type != Type::Material && base.type != Type::Texture)
    fail(e.base->loc, fmt::format("'with' derives from a material, a texture, a shape or a light, got {}", with_article(base.type)));
  auto rec = std::make_shared<RecordValue>(as_record(base));
  rec->built_id = render::kNoId;
  rec->loc = e.loc;
  collect_properties(e.body, rec->props, false);
  rec->update_depth();
  Value v;
  v.type = base.type;
  v.ref = std::move(rec);
  check_nesting(v, e.loc);
  return v;
}

Value Interpreter::make_texture(ast::Symbol kind, std::vector<Property> props, SourceLoc loc) {
  auto rec = std::make_shared<RecordValue>();
  rec->kind = kind;
  rec->props = std::move(props);
  rec->loc = loc;
  rec->update_depth();
  Value v;
  v.type = Type::Texture;
  v.ref = std::move(rec);
  check_nesting(v, loc);
  return v;
}

// A texture moved by `t`; a material with each texture it holds moved (its colour pattern, its
// channel textures, bump and normal maps, the pattern that chooses and each choice or layer:
// POV-Ray's texture { T scale 2 }), except its medium's density, which lies in world space.
Value Interpreter::transform_textures(const Value& v, const render::Mat4& t) {
  if (v.type == Type::Texture) {
    auto rec = std::make_shared<RecordValue>(as_record(v));
    rec->built_id = render::kNoId;
    rec->transform = t * rec->transform;
    Value r = v;
    r.ref = std::move(rec);
    return r;
  }
  if (v.type == Type::Material) {
    auto rec = std::make_shared<RecordValue>(as_record(v));
    rec->built_id = render::kNoId;
    for (Property& p : rec->props) {
      if (p.name && *p.name == "media_density") continue;
      p.value = transform_textures(p.value, t);
    }
    Value r = v;
    r.ref = std::move(rec);
    return r;
  }
  if (v.type == Type::List) {
    const auto& items = as_list(v);
    if (std::none_of(items.begin(), items.end(),
                     [](const Value& x) { return x.type == Type::Material || x.type == Type::Texture; }))
      return v;  // numbers, colours, a colour map: nothing to move
    std::vector<Value> moved;
    moved.reserve(items.size());
    for (const Value& x : items) moved.push_back(transform_textures(x, t));
    return Value::list(std::move(moved));
  }
  return v;
}

Value Interpreter::eval_transform(const ast::TransformExpr& e) {
  Value obj = eval(*e.object);
  Value arg = eval(*e.arg);
  const char* op = ast::to_string(e.op());
  auto need = [&](bool ok, const char* what) {
    if (!ok) fail(e.arg->loc, fmt::format("'{}' needs {}, got {}", op, what, with_article(arg.type)));
  };
  render::Mat4 t(1.0);
  switch (e.op()) {
    case ast::TransformOp::Translate:
      need(arg.type == Type::Vector, "a vector");
      t = glm::translate(render::Mat4(1.0), arg.v);
      break;
    case ast::TransformOp::Rotate:
      need(arg.type == Type::Vector, "a vector of angles in degrees");
      // About x first, then y, then z (matrices apply right to left).
      t = glm::rotate(render::Mat4(1.0), glm::radians(arg.v.z), render::Vec3(0, 0, 1)) *
          glm::rotate(render::Mat4(1.0), glm::radians(arg.v.y), render::Vec3(0, 1, 0)) *
          glm::rotate(render::Mat4(1.0), glm::radians(arg.v.x), render::Vec3(1, 0, 0));
      break;
    case ast::TransformOp::Scale: {
      need(arg.type == Type::Vector || arg.type == Type::Number, "a number or a vector");
      render::Vec3 s = arg.type == Type::Number ? render::Vec3(arg.v.x) : arg.v;
      if (s.x == 0 || s.y == 0 || s.z == 0) fail(e.arg->loc, "cannot scale by zero (the result would be flat)");
      t = glm::scale(render::Mat4(1.0), s);
      break;
    }
    case ast::TransformOp::Matrix:
      if (arg.type == Type::Transform) {
        t = as_transform(arg);
        break;
      }
      need(arg.type == Type::List && as_list(arg).size() == 12, "a list of 12 numbers or a transform");
      // POV-Ray order: the 3x3 part row by row, then the translation; row i of POV-Ray's
      // row-vector matrix is column i of ours.
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) {
          const Value& x = as_list(arg)[static_cast<std::size_t>(i * 3 + j)];
          if (x.type != Type::Number) fail(e.arg->loc, "'matrix' needs a list of 12 numbers");
          t[i][j] = x.v.x;
        }
      if (std::fabs(glm::determinant(t)) == 0.0) fail(e.arg->loc, "this matrix is singular (not invertible)");
      break;
  }
  switch (obj.type) {
    case Type::Object: {
      Value r = obj;
      auto moved = std::make_shared<ObjectValue>();
      moved->transform = t * object_transform(obj);
      if (obj.ref) {
        const auto& from = static_cast<const ObjectValue&>(*obj.ref);
        // Share the defining block, never copy it: chains stay one link long.
        if (from.defined_by)
          moved->defined_by = from.defined_by;
        else if (from.kind)
          moved->defined_by = std::static_pointer_cast<const ObjectValue>(obj.ref);
      }
      r.ref = std::move(moved);
      return r;
    }
    case Type::Transform: {
      Value r = obj;
      r.ref = std::make_shared<TransformValue>(t * as_transform(obj));
      return r;
    }
    case Type::Texture:
    case Type::Material:
      return transform_textures(obj, t);
    default:
      fail(e.op_loc(), fmt::format("cannot {} {}; transforms apply to objects, materials, textures and transforms", op,
                                 with_article(obj.type)));
  }
}

render::ParamValue Interpreter::to_param(const Property& p, const std::string& kind) {
  const Value& v = p.value;
  switch (v.type) {
    case Type::Number:
      return v.v.x;
    case Type::Bool:
      return v.truth();
    case Type::String:
      return as_string(v);
    case Type::Vector:
      return render::Vec3(v.v);
    case Type::Color:
      return render::Color(v.v.x, v.v.y, v.v.z);
    case Type::Texture:
      return render::TextureRef{realize_texture(v)};
    case Type::Material:
      return render::MaterialRef{realize_material(v)};
    case Type::Macro:
      return render::FunctionRef{compile_function(v, p.loc)};
    case Type::Object: {
      // An isosurface's container: an untransformed box or sphere, read from its own block.
      const ObjectValue* def = object_definition(v);
      const std::string shape = def ? std::string(*def->kind) : std::string();
      if (shape != "box" && shape != "sphere")
        fail(p.loc, fmt::format("property '{}' of {} cannot hold {}; only an isosurface's 'contained_by' takes an "
                                "object, a box or a sphere",
                                *p.name, kind, shape.empty() ? std::string("a group") : "a " + shape));
      if (object_transform(v) != render::Mat4(1.0))
        fail(p.loc, fmt::format("property '{}' of {} takes an untransformed {}: give its size in its own "
                                "properties (transform the {} instead)",
                                *p.name, kind, shape, kind));
      render::ParamSet inner = to_params(shape, def->loc, def->props);
      render::ContainerParam c;
      c.sphere = shape == "sphere";
      if (c.sphere) {
        c.center = inner.vec3("center", c.center);
        c.radius = inner.require_number("radius");
      } else {
        c.min = inner.require_vec3("min");
        c.max = inner.require_vec3("max");
      }
      inner.check_unused(c.sphere ? std::vector<std::string_view>{"center", "radius"}
                                  : std::vector<std::string_view>{"min", "max"});
      return c;
    }
    case Type::List: {
      const auto& items = as_list(v);
      if (items.empty()) return std::vector<double>{};
      if (items.front().type == Type::Material) {
        // A material chosen by pattern: `materials = [dark, light]`.
        render::MaterialListParam list;
        for (const Value& x : items) {
          if (x.type != Type::Material)
            fail(p.loc, fmt::format("property '{}' of {} cannot hold this list: a list of materials holds only "
                                    "materials, not {}",
                                    *p.name, kind, with_article(x.type)));
          list.materials.push_back(realize_material(x));
        }
        return list;
      }
      if (std::any_of(items.begin(), items.end(), [](const Value& x) { return x.type == Type::Texture; })) {
        // A sky_sphere's layers: textures, and solid colors among them.
        render::LayersParam layers;
        for (const Value& x : items) {
          if (x.type == Type::Texture) {
            layers.textures.push_back(realize_texture(x));
            layers.colors.emplace_back(0.0);
          } else if (x.type == Type::Color || x.type == Type::Vector) {
            layers.textures.push_back(render::kNoId);
            layers.colors.emplace_back(x.v.x, x.v.y, x.v.z);
          } else {
            fail(p.loc, fmt::format("property '{}' of {} cannot hold this list: a list of layers holds textures "
                                    "and colors, not {}",
                                    *p.name, kind, with_article(x.type)));
          }
        }
        return layers;
      }
      if (items.front().type == Type::Vector || items.front().type == Type::Color) {
        // Colors travel as vectors (r, g, b): `vertex_colors = [rgb(1, 0, 0), ...]`.
        std::vector<render::Vec3> out;
        out.reserve(items.size());
        for (const Value& x : items) {
          if (x.type != items.front().type) break;
          out.push_back(x.v);
        }
        if (out.size() == items.size()) return out;
      } else if (items.front().type == Type::Number) {
        std::vector<double> out;
        out.reserve(items.size());
        for (const Value& x : items) {
          if (x.type != Type::Number) break;
          out.push_back(x.v.x);
        }
        if (out.size() == items.size()) return out;
      } else if (items.front().type == Type::List && !as_list(items.front()).empty() &&
                 as_list(items.front()).front().type == Type::Vector) {
        // Rows of vectors then numbers: a blob's `spheres = [[<0, 0, 0>, 1, 1], ...]`.
        render::RowsParam rows;
        for (const Value& x : items) {
          const auto* row = x.type == Type::List ? &as_list(x) : nullptr;
          render::RowsParam::Row r;
          bool ok = row != nullptr;
          for (std::size_t i = 0; ok && i < row->size(); ++i) {
            const Value& e = (*row)[i];
            if (e.type == Type::Vector && r.numbers.empty())
              r.vectors.push_back(e.v);
            else if (e.type == Type::Number)
              r.numbers.push_back(e.v.x);
            else
              ok = false;
          }
          if (!ok)
            fail(p.loc, fmt::format("property '{}' of {} cannot hold this list: each entry is a list of vectors "
                                    "then numbers, e.g. [<0, 0, 0>, 1, 1]",
                                    *p.name, kind));
          rows.rows.push_back(std::move(r));
        }
        return rows;
      } else if (*p.name == "points" && items.front().type == Type::List && !as_list(items.front()).empty() &&
                 std::all_of(as_list(items.front()).begin(), as_list(items.front()).end(),
                             [](const Value& x) { return x.type == Type::Number; })) {
        // Rows of numbers: a sor's `points = [[0.5, 0], [0.8, 1], ...]` (only a `points`
        // property: elsewhere [[0.5, 1]] is a color map missing its color, and says so).
        render::RowsParam rows;
        for (const Value& x : items) {
          const auto* row = x.type == Type::List ? &as_list(x) : nullptr;
          if (!row || !std::all_of(row->begin(), row->end(), [](const Value& e) { return e.type == Type::Number; }))
            fail(p.loc, fmt::format("property '{}' of {} cannot hold this list: each entry is a list of numbers, "
                                    "e.g. [0.5, 1]",
                                    *p.name, kind));
          render::RowsParam::Row r;
          for (const Value& e : *row) r.numbers.push_back(e.v.x);
          rows.rows.push_back(std::move(r));
        }
        return rows;
      } else if (items.front().type == Type::List) {
        // A color map: [[value, color], ...].
        render::ColorMapParam map;
        for (const Value& x : items) {
          const auto* pair = x.type == Type::List ? &as_list(x) : nullptr;
          // [value, color] or [value, color, transmit] (POV-Ray's rgbt: a sky_sphere layer's see-through),
          // or [value, texture] (POV-Ray's pigment_map: the texture's color at the point).
          const bool textured = pair && pair->size() == 2 && (*pair)[1].type == Type::Texture;
          if (!pair || pair->size() < 2 || pair->size() > 3 || (*pair)[0].type != Type::Number ||
              ((*pair)[1].type != Type::Color && (*pair)[1].type != Type::Vector && !textured) ||
              (pair->size() == 3 && (*pair)[2].type != Type::Number))
            fail(p.loc, fmt::format("property '{}' of {} cannot hold this list: a color map is a list of [number, "
                                    "color] pairs (or [number, color, transmit], or [number, texture]), e.g. "
                                    "[[0, rgb(1)], [1, rgb(0)]]",
                                    *p.name, kind));
          render::ColorMapEntry entry{(*pair)[0].v.x, textured ? render::Vec3(0.0) : (*pair)[1].v,
                                      pair->size() == 3 ? (*pair)[2].v.x : 0.0};
          if (textured) entry.texture = realize_texture((*pair)[1]);
          map.entries.push_back(entry);
        }
        return map;
      }
      fail(p.loc,
           fmt::format("property '{}' of {} cannot hold this list: properties take lists of numbers, of vectors or of colors",
                       *p.name, kind));
    }
    default:
      fail(p.loc, fmt::format("property '{}' of {} cannot hold {}", *p.name, kind, with_article(v.type)));
  }
}

render::ParamSet Interpreter::to_params(const std::string& kind, SourceLoc loc, const std::vector<Property>& props) {
  render::ParamSet ps(kind, ref(loc));
  ps.reserve(props.size());
  for (const Property& p : props) {
    if (p.value.type == Type::None) continue;  // `name = none` leaves the property unset
    ps.add(*p.name, to_param(p, kind), ref(p.loc));
  }
  return ps;
}

uint32_t Interpreter::realize_material(const Value& material) {
  RecordValue& rec = as_record(material);
  if (rec.built_id == render::kNoId) {
    render::ParamSet ps = to_params(*rec.kind, rec.loc, rec.props);
    rec.built_id = builder_.material(ps);
  }
  return rec.built_id;
}

uint32_t Interpreter::realize_texture(const Value& texture) {
  RecordValue& rec = as_record(texture);
  if (rec.built_id == render::kNoId) {
    render::ParamSet ps = to_params(*rec.kind, rec.loc, rec.props);
    rec.built_id = builder_.texture(*rec.kind, ps, rec.transform);
  }
  return rec.built_id;
}

void Interpreter::place(const Value& object, SourceLoc loc) {
  placement_.admit(loc);
  render::Child c{realize_object(object), object_transform(object), ref(loc)};
  if (placement_.to_world(c, loc)) builder_.place(c);
}

}  // namespace rts::runtime
