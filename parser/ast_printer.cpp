// print_ast: the S-expression dump (format documented in docs/language.md, "AST print
// format"). Every node is described as a Form (a head, the location, and its parts: atoms
// or child nodes); a form prints on one line when it is flat (no statement or block-item
// children anywhere inside). Otherwise its head, and the atoms and flat children before its
// first multi-line child, stay on the first line, and every later part goes on its own
// line, indented two spaces deeper.
#include <ostream>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "parser/parser.hpp"

namespace rts {
namespace {

using namespace rts::ast;

struct NamedBody {
  const char* head;
  const Body* body;
};
struct ParamList {
  const NodeList<Param>* params;
};
using NodeRef = std::variant<const Expr*, const Stmt*, const BlockItem*, const Argument*,
                             const Param*, NamedBody, ParamList>;

struct Part {
  std::string atom;  // used when is_atom
  NodeRef node;
  bool is_atom = false;
};

struct Form {
  bool is_leaf = false;  // printed as a bare atom (numbers, names, ...)
  std::string head;      // the atom text for a leaf
  SourceLoc loc;
  std::vector<Part> parts;
};

std::string quote(std::string_view s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      case '\0': out += "\\0"; break;
      default:
        if (c < 0x20 || c == 0x7F) out += fmt::format("\\u{{{:X}}}", c);
        else out += static_cast<char>(c);
    }
  }
  out += '"';
  return out;
}

Part atom(std::string text) { return Part{std::move(text), NodeRef{}, true}; }
Part child(NodeRef n) { return Part{{}, n, false}; }

void add_body(Form& f, const Body& body) {
  for (const StmtLink& s : body.stmts) f.parts.push_back(child(s.get()));
}
void add_items(Form& f, const BlockBody& body) {
  for (const BlockItem& item : body.items) f.parts.push_back(child(&item));
}

Form leaf(std::string text, SourceLoc loc) {
  Form f;
  f.is_leaf = true;
  f.head = std::move(text);
  f.loc = loc;
  return f;
}

Form form(const char* head, SourceLoc loc) {
  Form f;
  f.head = head;
  f.loc = loc;
  return f;
}

const char* unary_head(UnaryOp op) {
  switch (op) {
    case UnaryOp::Neg: return "neg";
    case UnaryOp::Plus: return "pos";
    case UnaryOp::Not: return "not";
  }
  return "?";
}

Form describe_expr(const Expr& e) {
  switch (e.kind) {
    case ExprKind::Number: return leaf(fmt::format("{}", static_cast<const NumberExpr&>(e).value()), e.loc);
    case ExprKind::String: return leaf(quote(static_cast<const StringExpr&>(e).value), e.loc);
    case ExprKind::Bool: return leaf(static_cast<const BoolExpr&>(e).value ? "true" : "false", e.loc);
    case ExprKind::None: return leaf("none", e.loc);
    case ExprKind::Name: return leaf(*static_cast<const NameExpr&>(e).name, e.loc);
    case ExprKind::Vector: {
      Form f = form("vec", e.loc);
      for (const ExprPtr& c : static_cast<const VectorExpr&>(e).components) f.parts.push_back(child(c.get()));
      return f;
    }
    case ExprKind::List: {
      Form f = form("list", e.loc);
      for (const ExprLink& c : static_cast<const ListExpr&>(e).elements) f.parts.push_back(child(c.get()));
      return f;
    }
    case ExprKind::Unary: {
      const auto& u = static_cast<const UnaryExpr&>(e);
      Form f = form(unary_head(u.op()), e.loc);
      f.parts.push_back(child(u.operand.get()));
      return f;
    }
    case ExprKind::Binary: {
      const auto& b = static_cast<const BinaryExpr&>(e);
      Form f = form(to_string(b.op()), e.loc);
      f.parts.push_back(child(b.lhs.get()));
      f.parts.push_back(child(b.rhs.get()));
      return f;
    }
    case ExprKind::Range: {
      const auto& r = static_cast<const RangeExpr&>(e);
      Form f = form("range", e.loc);
      f.parts.push_back(atom(r.inclusive ? "..=" : ".."));
      f.parts.push_back(child(r.from.get()));
      f.parts.push_back(child(r.to.get()));
      if (r.step) {
        f.parts.push_back(atom("step"));
        f.parts.push_back(child(r.step.get()));
      }
      return f;
    }
    case ExprKind::Call: {
      const auto& c = static_cast<const CallExpr&>(e);
      Form f = form("call", e.loc);
      f.parts.push_back(child(c.callee.get()));
      for (const Argument& a : c.args) f.parts.push_back(child(&a));
      return f;
    }
    case ExprKind::Index: {
      const auto& i = static_cast<const IndexExpr&>(e);
      Form f = form("index", e.loc);
      f.parts.push_back(child(i.object.get()));
      f.parts.push_back(child(i.index.get()));
      return f;
    }
    case ExprKind::Member: {
      const auto& m = static_cast<const MemberExpr&>(e);
      Form f = form("member", e.loc);
      f.parts.push_back(child(m.object.get()));
      f.parts.push_back(atom(*m.member));
      return f;
    }
    case ExprKind::Block: {
      const auto& b = static_cast<const BlockExpr&>(e);
      Form f = form("block", e.loc);
      f.parts.push_back(atom(*b.kind_name));
      add_items(f, b.body);
      return f;
    }
    case ExprKind::With: {
      const auto& w = static_cast<const WithExpr&>(e);
      Form f = form("with", e.loc);
      f.parts.push_back(child(w.base.get()));
      add_items(f, w.body);
      return f;
    }
    case ExprKind::Transform: {
      const auto& t = static_cast<const TransformExpr&>(e);
      Form f = form(to_string(t.op()), e.loc);
      f.parts.push_back(child(t.object.get()));
      f.parts.push_back(child(t.arg.get()));
      return f;
    }
  }
  return leaf("?", e.loc);
}

Form describe_stmt(const Stmt& s) {
  switch (s.kind) {
    case StmtKind::Let: {
      const auto& l = static_cast<const LetStmt&>(s);
      Form f = form("let", s.loc);
      f.parts.push_back(atom(*l.name));
      f.parts.push_back(child(l.value.get()));
      return f;
    }
    case StmtKind::Assign: {
      const auto& a = static_cast<const AssignStmt&>(s);
      Form f = form("assign", s.loc);
      f.parts.push_back(atom(*a.name));
      f.parts.push_back(atom(to_string(a.op)));
      f.parts.push_back(child(a.value.get()));
      return f;
    }
    case StmtKind::If: {
      const auto& i = static_cast<const IfStmt&>(s);
      Form f = form("if", s.loc);
      f.parts.push_back(child(i.cond.get()));
      f.parts.push_back(child(NamedBody{"then", &i.then_body}));
      if (i.else_body) f.parts.push_back(child(NamedBody{"else", i.else_body.get()}));
      return f;
    }
    case StmtKind::For: {
      const auto& l = static_cast<const ForStmt&>(s);
      Form f = form("for", s.loc);
      f.parts.push_back(atom(*l.var));
      f.parts.push_back(child(l.iterable.get()));
      add_body(f, l.body);
      return f;
    }
    case StmtKind::While: {
      const auto& w = static_cast<const WhileStmt&>(s);
      Form f = form("while", s.loc);
      f.parts.push_back(child(w.cond.get()));
      add_body(f, w.body);
      return f;
    }
    case StmtKind::Macro: {
      const auto& m = static_cast<const MacroStmt&>(s);
      Form f = form("macro", s.loc);
      f.parts.push_back(atom(*m.name));
      f.parts.push_back(child(ParamList{&m.params}));
      add_body(f, m.body);
      return f;
    }
    case StmtKind::Return: {
      const auto& r = static_cast<const ReturnStmt&>(s);
      Form f = form("return", s.loc);
      if (r.value) f.parts.push_back(child(r.value.get()));
      return f;
    }
    case StmtKind::Break: return form("break", s.loc);
    case StmtKind::Continue: return form("continue", s.loc);
    case StmtKind::Include: {
      Form f = form("include", s.loc);
      f.parts.push_back(atom(quote(static_cast<const IncludeStmt&>(s).path)));
      return f;
    }
    case StmtKind::ExprStmt: {
      Form f = form("expr", s.loc);
      f.parts.push_back(child(static_cast<const ExprStmt&>(s).expr.get()));
      return f;
    }
  }
  return leaf("?", s.loc);
}

struct Describe {
  Form operator()(const Expr* e) const { return describe_expr(*e); }
  Form operator()(const Stmt* s) const { return describe_stmt(*s); }
  Form operator()(const BlockItem* item) const {
    if (item->stmt()) return describe_stmt(*item->stmt());
    Form f = form("prop", item->loc);
    f.parts.push_back(atom(*item->property));
    f.parts.push_back(child(item->value().get()));
    return f;
  }
  Form operator()(const Argument* a) const {
    if (!a->name) return describe_expr(*a->value);
    Form f = form("named", a->loc);
    f.parts.push_back(atom(*a->name));
    f.parts.push_back(child(a->value.get()));
    return f;
  }
  Form operator()(const Param* p) const {
    if (!p->default_value) return leaf(*p->name, p->loc);
    Form f = form("default", p->loc);
    f.parts.push_back(atom(*p->name));
    f.parts.push_back(child(p->default_value.get()));
    return f;
  }
  Form operator()(NamedBody b) const {
    Form f = form(b.head, b.body->open_loc);
    add_body(f, *b.body);
    return f;
  }
  Form operator()(ParamList p) const {
    Form f = form("params", SourceLoc{});
    for (const Param& param : *p.params) f.parts.push_back(child(&param));
    return f;
  }
};

Form describe(const NodeRef& n) { return std::visit(Describe{}, n); }

// Statements and block items (directly, or inside a then/else body) force a form onto
// several lines: they are the "lines" of the program.
bool is_line(const NodeRef& n) {
  if (std::holds_alternative<const Stmt*>(n) || std::holds_alternative<const BlockItem*>(n)) return true;
  if (auto* b = std::get_if<NamedBody>(&n)) return !b->body->stmts.empty();
  return false;
}

class Printer {
 public:
  Printer(std::ostream& out, bool with_locations) : out_(out), locations_(with_locations) {}
  ~Printer() { flush(); }

  void program(const Program& p) {
    Form f = form("program", SourceLoc{});
    for (const StmtLink& s : p.stmts()) f.parts.push_back(child(s.get()));
    print(f, 0);
    buf_ += '\n';
  }

 private:
  static constexpr std::size_t kFlushBytes = 1 << 16;

  void flush() {
    out_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

  void location(SourceLoc loc, bool is_leaf) {
    if (!locations_ || !loc.valid()) return;
    if (!is_leaf) buf_ += ' ';
    buf_ += fmt::format("@{}:{}", loc.line(), loc.col());
  }

  bool flat(const Form& f) {
    for (const Part& p : f.parts) {
      if (p.is_atom) continue;
      if (is_line(p.node)) return false;
      if (!flat(describe(p.node))) return false;
    }
    return true;
  }

  void print(const Form& f, int level) {
    if (f.is_leaf) {
      buf_ += f.head;
      location(f.loc, true);
      return;
    }
    bool one_line = flat(f);
    buf_ += '(';
    buf_ += f.head;
    location(f.loc, false);
    // Atoms and flat children before the first multi-line child stay on the head line.
    bool leading = true;
    for (const Part& p : f.parts) {
      if (leading && !one_line && !p.is_atom) leading = !is_line(p.node) && flat(describe(p.node));
      if (one_line || leading) {
        buf_ += ' ';
      } else {
        buf_ += '\n';
        buf_.append(static_cast<std::size_t>(2 * (level + 1)), ' ');
      }
      if (p.is_atom) buf_ += p.atom;
      else print(describe(p.node), level + 1);
    }
    buf_ += ')';
    if (buf_.size() >= kFlushBytes) flush();
  }

  std::ostream& out_;
  bool locations_;
  std::string buf_;
};

}  // namespace

void print_ast(std::ostream& out, const ast::Program& program, bool with_locations) {
  Printer(out, with_locations).program(program);
}

}  // namespace rts
