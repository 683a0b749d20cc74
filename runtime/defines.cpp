#include "runtime/defines.hpp"

#include <fmt/format.h>

namespace rts::runtime {

void Defines::parse(const std::vector<Define>& defines, Includes& files) {
  for (const Define& d : defines) {
    const SourceFile* f = nullptr;
    const ast::Program& p =
        files.parse_text(fmt::format("<define {}>", d.name), fmt::format("let {} = {}", d.name, d.value), f);
    if (p.stmts().size() != 1 || p.stmts()[0]->kind != ast::StmtKind::Let)
      throw LanguageError(SourceLoc::at(f, 1, 1), fmt::format("define '{}={}' is not a single value", d.name, d.value));
    entries_.push_back(Entry{ast::intern(d.name), static_cast<const ast::LetStmt&>(*p.stmts()[0]).value.get(),
                             d.name + "=" + d.value});
  }
}

const ast::Expr* Defines::take(ast::Symbol name) {
  Entry* def = nullptr;
  for (Entry& d : entries_)
    if (d.name == name && !d.used) def = &d;
  if (!def) return nullptr;
  for (Entry& d : entries_)
    if (d.name == name) d.used = true;
  return def->expr;
}

void Defines::warn_unmatched(const SourceFile& main, DiagnosticSink& warnings) const {
  for (const Entry& d : entries_)
    if (!d.used)
      warnings.warning(SourceLoc::whole(&main),
                       fmt::format("define '{}' matches no top-level 'let {}' in this file", d.text, *d.name));
}

}  // namespace rts::runtime
