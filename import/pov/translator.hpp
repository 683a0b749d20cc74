// The writer: a POV-Ray Program (ast.hpp) as rts text. One Translator reads the main file
// and, recursively, the user's own include files; it keeps what each name holds (a float, a
// colour, an object, a finish ...) because POV-Ray's meaning of a value depends on it
// (`pigment { P }`, `object { O }`, float-to-vector promotion).
//
// translate_expr.cpp: expressions; translate_object.cpp: objects and materials;
// translate_scene.cpp: statements, lights, camera, settings, includes.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "import/pov/ast.hpp"
#include "import/pov/pov_import.hpp"
#include "import/writer.hpp"

namespace rts::import::pov {

// What a value is, as far as the translation can tell.
enum class Type { Unknown, Float, Bool, Vector, Color, String, Object, Material, Pigment, Finish, Interior,
                  Normal, Camera, Light, Transform, List, Random, Macro };

// An expression written as rts text, with its type and how tightly it binds (rts's levels:
// 2 or, 3 and, 4 not, 5 compare, 7 add, 8 multiply, 9 unary, 11 postfix, 12 primary).
struct Text {
  std::string s;
  Type type = Type::Unknown;
  int prec = 12;
  double filter = 0, transmit = 0;  // colours written with rgbf/rgbt/rgbft
};

// Whether `text` is a whole literal number (what the translator writes for literal values),
// and its value.
bool text_number(const std::string& text, double& out);

// Material properties in the order they are written; set() replaces an earlier value.
struct MaterialProps {
  std::string base;  // "" (a new material block) or an expression to derive from (`T with { }`)
  std::vector<std::pair<std::string, std::string>> props;
  void set(const std::string& name, const std::string& value);
  bool has(const std::string& name) const;
  bool empty() const { return base.empty() && props.empty(); }
  // POV-Ray lets a pigment's filtered and transmitted light past the surface instead of lighting
  // it: ambient and diffuse are scaled by 1 - (filter * max(colour) + transmit), which rts's
  // material writes out (material_text).
  double opacity = 1.0;
  // A material chosen by pattern (translate_texture_map.cpp): `pattern` and `materials` only,
  // written without POV-Ray's defaults (each choice carries its own).
  bool chosen = false;
  // A layered texture (POV-Ray's `texture { A } texture { B }`): `layers` only, each layer
  // written with POV-Ray's defaults (material_text).
  bool layered = false;
};

// A declared name. What a use needs from its block is worked out when it is declared, so
// a use never follows names again: `#declare F = finish { F phong 1 }` means the earlier F
// (POV-Ray's meaning), and a chain of declarations each naming the last twice
// (`#declare F2 = finish { F1 F1 }`) costs each declaration once instead of doubling.
struct Symbol {
  Type type = Type::Unknown;
  std::shared_ptr<Block> block;  // declared blocks (a camera's items are taken from it)
  std::string object_kind;       // Object: the block's kind (sphere, union, ...)
  bool textured = false;         // Object: it carries its own texture (has_texture)
  std::vector<std::string> steps;  // Transform: its steps as rts transforms
  MaterialProps props;           // Finish, Interior: what it adds to a material
  // Macro: the parameter its body #declares (POV-Ray passes a variable by reference: the
  // caller's variable changes), or -1. rts's macro returns it; the call assigns it back.
  int out_param = -1;
  Symbol() = default;
  Symbol(Type t, std::shared_ptr<Block> b, std::string kind)
      : type(t), block(std::move(b)), object_kind(std::move(kind)) {}
};

class Translator {
 public:
  Translator(const PovOptions& options, PovResult& result) : opt_(options), result_(result) {}

  // Translates one file's program into `w`.
  void file(const Program& p, const std::string& path, Writer& w);
  void header(Writer& w, const std::string& source_name);
  void footer(Writer& w);  // settings that depend on the whole scene (the output gamma)

  // ---- expressions (translate_expr.cpp) ----
  Text expr(const Expr& e);
  Text call(const Expr& e);
  std::string value(const Expr& e) { return expr(e).s; }
  std::string vector_value(const Expr& e);
  // The same as an operand of an operator of precedence `prec` (7: + and -, 8: * and /).
  std::string operand(const Expr& e, int prec);
  std::string vector_operand(const Expr& e, int prec);
  // An array initialiser's element: a value, or a texture, material or pigment block.
  std::string array_element(const Expr& e);  // promotes a float to <f, f, f>
  std::string color_value(const Expr& e, double* filter = nullptr, double* transmit = nullptr,
                          int* prec = nullptr);
  std::string condition(const Expr& e);     // a bool: floats compare with 0
  std::string float_value(const Expr& e) { return expr(e).s; }
  // Literal values, when the expression is one (after folding x, y, z, unary minus, k * v).
  static bool literal_vector(const Expr& e, std::vector<double>& out);
  // Is `k` a pigment pattern rts translates as a pattern block (checker and image_map have
  // forms of their own)?
  static bool pigment_pattern(const std::string& k);
  static bool literal_number(const Expr& e, double& out);
  std::string rename(const std::string& pov_name) const;  // rts's reserved words get a '_'

  // ---- objects and materials (translate_object.cpp) ----
  static bool is_object_kind(const std::string& kind);
  static bool is_unsupported_shape(const std::string& kind);
  // A kind rts's CSG takes as a solid (when not `open`): what a clip block may hold.
  static bool is_solid_kind(const std::string& kind);
  // Writes an object block; `prefix` goes before it on the first line ("let S = "), `place`:
  // a placement in the world (objects without a texture get POV-Ray's default one).
  void object(Writer& w, const Block& b, const std::string& prefix, bool place);
  bool has_texture(const Block& b) const;
  // An object with `clipped_by` (translate_clip.cpp) as rts's clip block; false (nothing
  // written) when it has none, or when the object or a clipper is not a solid rts can clip.
  bool clipped_object(Writer& w, const Block& b, const std::string& prefix, bool place);
  bool solid_block(const Block& b);
  std::vector<Item> text_values_;  // object(): a text's values read with its ttf keyword
  // A blob's components (translate_shapes.cpp) as rts's blob properties, added to `props`;
  // returns the block without them (its texture and transforms).
  Block blob_components(const Block& b, std::vector<std::string>& props);
  // One blob component (`sphere { c, r, s }`, `cylinder { a, b, r, s }`) as a list entry of
  // rts's blob; `sphere` says which list it belongs to.
  std::string blob_component(const Block& c, bool& sphere);
  // A blob whose components a loop places (`#while ... sphere { ... } #end`): the loops are
  // written before the blob, each component appended to these lists (object()).
  struct BlobLists {
    std::string spheres, cylinders;
  };
  std::vector<BlobLists> blob_lists_;
  int blob_list_count_ = 0;
  // An isosurface's or height field's own items (translate_shapes.cpp) as rts properties, added
  // to `props`; its function, if any, written first as a macro of the point. Returns the block
  // without them (its texture and transforms).
  Block solid_components(Writer& w, const Block& b, std::vector<std::string>& props);
  // A mesh of literal triangles (all flat or all smooth) or a mesh2 as one rts mesh: its
  // vertices, faces and normals added to `props`, `rest` the block without them (texture,
  // transforms). False for a mesh whose triangles are not all literal (it stays a group).
  bool mesh_components(const Block& b, std::vector<std::string>& props, Block& rest);
  // A function block's body as rts text, with the names in `vars` (x, y, z) replaced; "" when
  // the reader kept no body (POV-Ray syntax rts does not read) or the body calls a function
  // rts cannot compile (functions.inc's f_sphere ...): then `why` says which.
  std::string function_text(const Block& f, const std::map<std::string, std::string>& vars, std::string& why);
  // `#declare F = function(a, b) { ... }` as `macro F(a, b) { return ... }` (x, y, z when none
  // are named, as POV-Ray's); false when the body was not read.
  bool declare_function(Writer& w, const std::string& name, const Block& f, std::string& why);
  // The material a POV-Ray texture-like block (texture, pigment, finish, normal, interior,
  // material) adds to `m`.
  void texture_part(const Item& it, MaterialProps& m);
  // An image_map block as rts's image texture (translate_pigment.cpp).
  std::string image_map(const Block& n);
  // Where POV-Ray looks for a file the scene names: the scene's folder, the -I folders, then its
  // own library folder where it is installed (translate_files.cpp).
  std::vector<std::string> search_dirs() const;
  // A pigment_map block as rts's colour map list, its entries' pigments as textures or colours.
  std::string pigment_map(const Block& n);
  // A media density block as the pigment it reads like (translate_media.cpp).
  Block density_as_pigment(const Block& density);
  // `layers` (texture blocks, the first at the bottom) as one layered material; `base_parts`
  // (an object's interior) go to the bottom layer.
  void layered_texture(const std::vector<const Item*>& layers, const std::vector<const Item*>& base_parts,
                       MaterialProps& m);
  // texture { checker texture { A } texture { B } } and texture { PATTERN texture_map { ... } }
  // as rts's material chosen by pattern (translate_texture_map.cpp); false when `b` is neither.
  bool texture_pattern(const Block& b, MaterialProps& m);
  std::string pattern_map_override_;  // pigment(): the color_map to write instead of the block's
  void pigment(const Block& b, MaterialProps& m);
  void finish(const Block& b, MaterialProps& m);
  void interior(const Block& b, MaterialProps& m);
  // A media block's rts properties (media_absorption = ..., ...), warning about what differs.
  std::vector<std::pair<std::string, std::string>> media(const Block& b);  // translate_media.cpp
  void normal(const Block& b, MaterialProps& m);
  std::string pigment_value(const Block& b);  // a colour or a texture expression
  std::string material_text(const MaterialProps& m, bool with_defaults);
  void default_finish(MaterialProps& m) const;
  std::vector<std::string> transforms(const Item& it);  // "translate <..>" etc. (empty when not one)

  // ---- statements (translate_scene.cpp) ----
  void items(Writer& w, const std::vector<Item>& items, bool top);
  void item(Writer& w, const Item& it, bool top);
  void declare(Writer& w, const Item& it);
  void place_block(Writer& w, const Block& b);
  void light(Writer& w, const Block& b, const std::string& prefix);
  void camera(Writer& w, const Block& b);
  void sky_sphere(Writer& w, const Block& b);  // translate_sky.cpp
  // The sky as an rts value (`sky_sphere { layers = [...] }`, a declared sky's name), or "" when
  // it has no layer.
  std::string sky_sphere_value(const Block& b);
  void global_settings(Writer& w, const Block& b);
  void include(Writer& w, const Item& it);
  void declare_library_file(const std::string& file);  // its names, and the files it includes
  bool library_part(const std::string& name, MaterialProps& m);  // a finish/interior name merged
  void hoist(Writer& w, const std::vector<Item>& body);

  // ---- diagnostics ----
  // "POV-Ray's 'kw' is not supported: <alternative>" at `at`, once per keyword and place.
  void unsupported(Loc at, const std::string& keyword, const std::string& alternative, bool planned);
  void warn(Loc at, const std::string& message);
  [[noreturn]] void error(Loc at, const std::string& message) const;

  // ---- state ----
  const PovOptions& opt_;
  PovResult& result_;
  std::string file_;               // the file being translated, as named
  std::string dir_;                // its folder
  std::vector<std::map<std::string, Symbol>> scopes_{1};
  // A key no POV-Ray name can be: marks the scope a macro's body opens (#local's reach).
  static constexpr const char* kMacroScope = "\x01macro";
  std::set<std::string> helpers_;  // helper macros the output needs (pov_if, pov_int)
  int computed_cameras_ = 0;       // cameras whose vectors the scene computes (pov_camera_N)
  std::set<std::string> included_;
  std::map<std::string, std::string> include_names_;  // an include file (canonical) → its .rts
  std::set<std::string> include_outputs_;             // the .rts names given out
  std::set<std::string> reader_names_;  // declared names, for the reader (reader.hpp)
  std::set<std::string> library_names_;  // names the included standard library files define
  std::set<std::string> library_material_macros_;  // their macros that return a material
  std::set<std::string> library_files_;  // the library files whose names are declared
  // One-line `let N = material { k = v  k = v }` of the library (its finishes and interiors:
  // Shiny, I_Glass ...): the properties, merged into the material a POV-Ray finish/interior
  // naming N is translated to.
  std::map<std::string, MaterialProps> library_parts_;
  bool library_known_ = false;           // options.stdlib_dir was read: an unknown name is missing
  std::vector<std::string> group_material_;
  int macro_depth_ = 0;   // inside a #macro's body (its objects' texture comes from the call)
  int csg_depth_ = 0;
  // Whether statements are being written directly in an object block's body, where rts reads
  // `name = value` as a property: an assignment there is wrapped in `if true { ... }`.
  bool in_block_body_ = false;
  struct BodyFlag {  // sets in_block_body_ for a scope, restoring it after
    bool& flag;
    bool saved;
    BodyFlag(bool& f, bool v) : flag(f), saved(f) { f = v; }
    ~BodyFlag() { flag = saved; }
  };
  std::string last_kind_;  // the rts kind object() wrote last (a union may become a group)
  // A name neither declared nor in the included library: warns (once per name) and returns true.
  bool missing_name(Loc at, const std::string& name, const std::string& what);
  double version_ = 0;             // #version, 0 when none
  double assumed_gamma_ = 0;       // 0 when none
  bool gamma_seen_ = false;
  bool camera_seen_ = false;       // a camera block was translated (else POV-Ray's default is written)
  bool radiosity_ = false;         // global_settings { radiosity { } }: the path tracer renders it
  MaterialProps default_texture_;  // #default { ... }
  Writer* pending_comment_ = nullptr;
  int include_depth_ = 0;
  // POV-Ray's #local at an include file's top level belongs to that file; rts's include shares
  // the includer's names, so such a local is written under an alias (Thing_local for
  // local.inc's Thing) while the file is translated, and the includer's symbol comes back
  // after it (translate_files.cpp, declare()).
  std::string include_stem_;                          // the include file being translated, or ""
  std::map<std::string, std::string> aliases_;        // POV-Ray name -> rts name, in effect now
  std::vector<std::vector<std::pair<std::string, std::optional<Symbol>>>> include_shadows_;
  // Inside a function body: POV-Ray's x, y, z are the point's coordinates, not axis vectors.
  std::map<std::string, std::string> function_vars_;
  int functions_written_ = 0;  // macros made from isosurface and height field functions

  Symbol* lookup(const std::string& name);
  void define(const std::string& name, Symbol s) { scopes_.back()[name] = std::move(s); }
  bool declared(const std::string& name) { return lookup(name) != nullptr; }
};

}  // namespace rts::import::pov
