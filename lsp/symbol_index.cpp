#include "lsp/symbol_index.hpp"

#include <cstdint>
#include <algorithm>
#include <set>

namespace rts::lsp {

namespace {

class Indexer {
 public:
  Indexer(std::string_view text, const LineIndex& lines, SymbolIndex& out) : text_(text), lines_(lines), out_(out) {}

  std::size_t at(SourceLoc loc) const { return lines_.offset_of_loc(loc.line(), loc.col()); }
  // The end of the body whose '{' is at `open` (one past its '}').
  std::size_t body_end(SourceLoc open) const {
    std::size_t close = matching_close(text_, at(open));
    return std::min(text_.size(), close + 1);
  }
  // Where a statement starting at `begin` ends: a body's close, else the end of the line.
  std::size_t line_end(std::size_t begin) const {
    std::size_t eol = text_.find('\n', begin);
    return eol == std::string_view::npos ? text_.size() : eol;
  }

  void stmts(const ast::StmtList& list, std::size_t scope_end, bool top) {
    for (const ast::StmtLink& s : list) stmt(*s, scope_end, top);
  }

  void body(const ast::Body& b) { stmts(b.stmts, body_end(b.open_loc), false); }

  void stmt(const ast::Stmt& s, std::size_t scope_end, bool top) {
    const std::size_t begin = at(s.loc);
    switch (s.kind) {
      case ast::StmtKind::Let: {
        const auto& l = static_cast<const ast::LetStmt&>(s);
        Declaration d{Declaration::Let, *l.name};
        d.begin = at(l.name_loc);
        d.end = token_end(text_, d.begin);
        d.scope_begin = begin;
        d.scope_end = scope_end;
        d.stmt_begin = begin;
        d.stmt_end = std::max(d.end, line_end(begin));
        d.top_level = top;
        d.let = &l;
        out_.declarations.push_back(d);
        expr(l.value.get());
        break;
      }
      case ast::StmtKind::Macro: {
        const auto& m = static_cast<const ast::MacroStmt&>(s);
        Declaration d{Declaration::Macro, *m.name};
        // The name follows the keyword.
        std::size_t name = text_.find(*m.name, begin + 5);
        d.begin = name == std::string_view::npos ? begin : name;
        d.end = d.begin + (name == std::string_view::npos ? 0 : m.name->size());
        // Visible in the whole scope (a macro may call itself and later ones).
        d.scope_begin = top ? 0 : begin;
        d.scope_end = scope_end;
        d.stmt_begin = begin;
        d.stmt_end = body_end(m.body.open_loc);
        d.top_level = top;
        d.macro = &m;
        out_.declarations.push_back(d);
        for (const ast::Param& p : m.params) {
          Declaration pd{Declaration::Param, *p.name};
          pd.begin = at(p.loc);
          pd.end = token_end(text_, pd.begin);
          pd.scope_begin = pd.begin;
          pd.scope_end = d.stmt_end;
          pd.stmt_begin = pd.begin;
          pd.stmt_end = pd.end;
          pd.macro = &m;
          out_.declarations.push_back(pd);
          expr(p.default_value.get());
        }
        body(m.body);
        break;
      }
      case ast::StmtKind::For: {
        const auto& f = static_cast<const ast::ForStmt&>(s);
        expr(f.iterable.get());
        Declaration d{Declaration::LoopVar, *f.var};
        d.begin = at(f.var_loc);
        d.end = token_end(text_, d.begin);
        d.scope_begin = d.begin;
        d.scope_end = body_end(f.body.open_loc);
        d.stmt_begin = begin;
        d.stmt_end = d.scope_end;
        out_.declarations.push_back(d);
        body(f.body);
        break;
      }
      case ast::StmtKind::If: {
        const auto& i = static_cast<const ast::IfStmt&>(s);
        expr(i.cond.get());
        body(i.then_body);
        if (i.else_body) body(*i.else_body);
        break;
      }
      case ast::StmtKind::While: {
        const auto& w = static_cast<const ast::WhileStmt&>(s);
        expr(w.cond.get());
        body(w.body);
        break;
      }
      case ast::StmtKind::Include: {
        const auto& inc = static_cast<const ast::IncludeStmt&>(s);
        out_.includes.push_back(IncludeRef{std::string(inc.path), begin, std::max(begin, line_end(begin))});
        break;
      }
      case ast::StmtKind::ExprStmt: {
        const auto& e = static_cast<const ast::ExprStmt&>(s);
        if (top) placed(*e.expr, begin);
        expr(e.expr.get());
        break;
      }
      case ast::StmtKind::Assign:
        expr(static_cast<const ast::AssignStmt&>(s).value.get());
        break;
      case ast::StmtKind::Return:
        expr(static_cast<const ast::ReturnStmt&>(s).value.get());
        break;
      case ast::StmtKind::Break:
      case ast::StmtKind::Continue:
        break;
    }
  }

  // A top-level statement that places an object: a block, a macro call, either transformed.
  void placed(const ast::Expr& e, std::size_t begin) {
    const ast::Expr* x = &e;
    while (x->kind == ast::ExprKind::Transform) x = static_cast<const ast::TransformExpr*>(x)->object.get();
    std::string kind;
    std::size_t end = line_end(begin);
    if (x->kind == ast::ExprKind::Block) {
      const auto& b = static_cast<const ast::BlockExpr&>(*x);
      kind = *b.kind_name;
      end = body_end(b.body.open_loc);
    } else if (x->kind == ast::ExprKind::Call) {
      const auto& c = static_cast<const ast::CallExpr&>(*x);
      if (c.callee->kind == ast::ExprKind::Name) kind = *static_cast<const ast::NameExpr&>(*c.callee).name + "()";
    } else if (x->kind == ast::ExprKind::Name) {
      kind = *static_cast<const ast::NameExpr&>(*x).name;
    } else if (x->kind == ast::ExprKind::With) {
      kind = "with";
      end = body_end(static_cast<const ast::WithExpr&>(*x).body.open_loc);
    }
    if (!kind.empty()) out_.objects.push_back(PlacedObject{kind, begin, std::max(end, begin)});
  }

  void block_body(const ast::BlockBody& b) {
    const std::size_t end = body_end(b.open_loc);
    for (const ast::BlockItem& item : b.items) {
      if (item.stmt()) stmt(*item.stmt(), end, false);
      expr(item.value().get());
    }
  }

  // Blocks inside expressions have bodies with statements (lets in a group...).
  void expr(const ast::Expr* e) {
    if (!e || ++depth_ > kMaxDepth) {
      if (e) --depth_;
      return;
    }
    switch (e->kind) {
      case ast::ExprKind::Vector:
        for (const auto& c : static_cast<const ast::VectorExpr*>(e)->components) expr(c.get());
        break;
      case ast::ExprKind::List:
        for (const auto& c : static_cast<const ast::ListExpr*>(e)->elements) expr(c.get());
        break;
      case ast::ExprKind::Unary:
        expr(static_cast<const ast::UnaryExpr*>(e)->operand.get());
        break;
      case ast::ExprKind::Binary:
        expr(static_cast<const ast::BinaryExpr*>(e)->lhs.get());
        expr(static_cast<const ast::BinaryExpr*>(e)->rhs.get());
        break;
      case ast::ExprKind::Range: {
        const auto* r = static_cast<const ast::RangeExpr*>(e);
        expr(r->from.get());
        expr(r->to.get());
        expr(r->step.get());
        break;
      }
      case ast::ExprKind::Call:
        for (const auto& a : static_cast<const ast::CallExpr*>(e)->args) expr(a.value.get());
        break;
      case ast::ExprKind::Index:
        expr(static_cast<const ast::IndexExpr*>(e)->object.get());
        expr(static_cast<const ast::IndexExpr*>(e)->index.get());
        break;
      case ast::ExprKind::Member:
        expr(static_cast<const ast::MemberExpr*>(e)->object.get());
        break;
      case ast::ExprKind::Block:
        block_body(static_cast<const ast::BlockExpr*>(e)->body);
        break;
      case ast::ExprKind::With:
        expr(static_cast<const ast::WithExpr*>(e)->base.get());
        block_body(static_cast<const ast::WithExpr*>(e)->body);
        break;
      case ast::ExprKind::Transform:
        expr(static_cast<const ast::TransformExpr*>(e)->object.get());
        expr(static_cast<const ast::TransformExpr*>(e)->arg.get());
        break;
      default:
        break;
    }
    --depth_;
  }

 private:
  // The parser bounds nesting (ParseLimits::max_nesting); this only guards the walk itself.
  static constexpr unsigned kMaxDepth = 4096;
  std::string_view text_;
  const LineIndex& lines_;
  SymbolIndex& out_;
  unsigned depth_ = 0;
};

}  // namespace

const Declaration* SymbolIndex::resolve(std::string_view name, std::size_t offset) const {
  const Declaration* best = nullptr;
  for (const Declaration& d : declarations) {
    if (d.name != name || offset < d.scope_begin || offset > d.scope_end) continue;
    if (!best || d.scope_begin >= best->scope_begin) best = &d;
  }
  return best;
}

std::vector<const Declaration*> SymbolIndex::visible_at(std::size_t offset) const {
  std::vector<const Declaration*> out;
  std::set<std::string_view> seen;
  std::vector<const Declaration*> all;
  for (const Declaration& d : declarations)
    if (offset >= d.scope_begin && offset <= d.scope_end) all.push_back(&d);
  std::sort(all.begin(), all.end(), [](auto* a, auto* b) { return a->scope_begin > b->scope_begin; });
  for (const Declaration* d : all)
    if (seen.insert(d->name).second) out.push_back(d);
  return out;
}

SymbolIndex index_program(const ast::Program& program, std::string_view text, const LineIndex& lines) {
  SymbolIndex out;
  Indexer ix(text, lines, out);
  // Top-level names reach past the end: kept for a later text that does not parse (typing at
  // the end of the file), they are still visible there.
  ix.stmts(program.stmts(), SIZE_MAX, true);
  return out;
}

std::string macro_signature(const Declaration& macro, std::string_view text, std::vector<std::string>* params) {
  std::size_t open = text.find('(', macro.end);
  if (open == std::string_view::npos || open > macro.stmt_end) return macro.name + "()";
  std::size_t close = std::min(matching_close(text, open), text.size() - 1);
  std::string sig = macro.name + std::string(text.substr(open, close - open + 1));
  if (params && macro.macro) {
    // Each parameter's own text (its default included), cut at the top-level commas.
    std::string_view inside = text.substr(open + 1, close > open ? close - open - 1 : 0);
    std::size_t start = 0;
    int depth = 0;
    for (std::size_t i = 0; i <= inside.size(); ++i) {
      char c = i < inside.size() ? inside[i] : ',';
      if (c == '(' || c == '[' || c == '{' || c == '<') ++depth;
      if (c == ')' || c == ']' || c == '}' || c == '>') --depth;
      if (c == ',' && depth <= 0) {
        std::string_view p = inside.substr(start, i - start);
        while (!p.empty() && (p.front() == ' ' || p.front() == '\n' || p.front() == '\t')) p.remove_prefix(1);
        while (!p.empty() && (p.back() == ' ' || p.back() == '\n' || p.back() == '\t' || p.back() == '\r'))
          p.remove_suffix(1);
        if (!p.empty()) params->emplace_back(p);
        start = i + 1;
      }
    }
  }
  return sig;
}

}  // namespace rts::lsp
