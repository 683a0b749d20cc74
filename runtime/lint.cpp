#include "runtime/lint.hpp"

#include <filesystem>

#include <fmt/format.h>

namespace rts::runtime {

namespace fs = std::filesystem;

namespace {
// The file an unused declaration names ("file" of a mesh or image_texture), or "".
std::string declared_file(const std::vector<Property>& props) {
  for (const Property& p : props)
    if (*p.name == "file" && p.value.type == Type::String) return as_string(p.value);
  return {};
}
}  // namespace

void warn_unused(std::span<const Binding> globals, const SourceFile& main, DiagnosticSink& warnings) {
  for (const Binding& b : globals) {
    if (b.used || b.loc.file() != &main) continue;
    std::string what, file;
    bool built = false;  // shapes and lights other than meshes are built (and checked) when declared
    switch (b.value.type) {
      case Type::Material: what = "material"; break;
      case Type::Texture:
        what = "texture";
        file = declared_file(as_record(b.value).props);
        break;
      case Type::Macro: what = "macro"; break;
      case Type::Object: {
        what = "object";
        if (!b.value.ref) break;
        const ObjectValue& def = static_cast<const ObjectValue&>(*b.value.ref).definition();
        if (def.kind) what = *def.kind;
        built = def.built_id != render::kNoId;
        file = declared_file(def.props);
        break;
      }
      default: break;
    }
    if (what.empty()) continue;
    const char* why = built ? "" : b.value.type == Type::Macro ? " (so it never runs)" : " (so it is not built)";
    std::string msg = fmt::format("{} '{}' is declared but never used{}", what, *b.name, why);
    if (!file.empty()) {
      std::error_code ec;
      fs::path path(file);  // relative to the declaring file, as the builder resolves it
      if (path.is_relative()) path = fs::path(main.path()).parent_path() / path;
      if (!fs::exists(path, ec)) msg += fmt::format("; its file '{}' does not exist", file);
    }
    warnings.warning(b.loc, msg);
  }
}

}  // namespace rts::runtime
