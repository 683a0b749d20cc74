// format_source(): tokens re-joined with canonical whitespace. The rules, in the order they
// are applied, are documented in docs/language.md ("Formatting"); the comments below say
// why each one is safe.
#include "parser/format.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "grammar/lexical.hpp"
#include "parser/parser.hpp"

namespace rts {
namespace {

using namespace rts::ast;

constexpr int kIndentWidth = 4;        // spaces per nesting level
constexpr int kItemGap = 2;            // spaces between two properties/statements on one line
constexpr int kCommentGap = 2;         // at least this many spaces before a trailing // comment

// ---------------------------------------------------------------------------------------
// What the tree knows and the tokens do not: byte offsets of item starts (statements and
// block properties), of unary + and -, and of the '<' that opens a vector.
// ---------------------------------------------------------------------------------------
struct Marks {
  std::unordered_set<std::size_t> item_starts, unary_ops, vector_opens;
};

class MarkCollector {
 public:
  MarkCollector(const SourceFile& file, Marks& marks) : file_(file), marks_(marks) {}

  void stmts(const StmtList& list) {
    for (const StmtLink& s : list) stmt(*s);
  }

 private:
  std::size_t offset(SourceLoc loc) const { return loc.offset(); }

  void stmt(const Stmt& s) {
    marks_.item_starts.insert(offset(s.loc));
    switch (s.kind) {
      case StmtKind::Let: expr(static_cast<const LetStmt&>(s).value.get()); break;
      case StmtKind::Assign: expr(static_cast<const AssignStmt&>(s).value.get()); break;
      case StmtKind::If: {
        const auto& i = static_cast<const IfStmt&>(s);
        expr(i.cond.get());
        stmts(i.then_body.stmts);
        if (i.else_body) stmts(i.else_body->stmts);
        break;
      }
      case StmtKind::For: {
        const auto& f = static_cast<const ForStmt&>(s);
        expr(f.iterable.get());
        stmts(f.body.stmts);
        break;
      }
      case StmtKind::While: {
        const auto& w = static_cast<const WhileStmt&>(s);
        expr(w.cond.get());
        stmts(w.body.stmts);
        break;
      }
      case StmtKind::Macro: {
        const auto& m = static_cast<const MacroStmt&>(s);
        for (const Param& p : m.params) expr(p.default_value.get());
        stmts(m.body.stmts);
        break;
      }
      case StmtKind::Return: expr(static_cast<const ReturnStmt&>(s).value.get()); break;
      case StmtKind::ExprStmt: expr(static_cast<const ExprStmt&>(s).expr.get()); break;
      case StmtKind::Break:
      case StmtKind::Continue:
      case StmtKind::Include: break;
    }
  }

  void block(const BlockBody& body) {
    for (const BlockItem& item : body.items) {
      marks_.item_starts.insert(offset(item.loc));
      if (item.stmt()) stmt(*item.stmt());
      else expr(item.value().get());
    }
  }

  void expr(const Expr* e) {
    if (e == nullptr) return;
    switch (e->kind) {
      case ExprKind::Number:
        // A negative literal is written as a minus before a number (parser/node_builders.cpp).
        if (const std::size_t at = offset(e->loc); at < file_.text().size() && file_.text()[at] == '-')
          marks_.unary_ops.insert(at);
        break;
      case ExprKind::String:
      case ExprKind::Bool:
      case ExprKind::None:
      case ExprKind::Name: break;
      case ExprKind::Vector:
        marks_.vector_opens.insert(offset(e->loc));
        for (const ExprPtr& c : static_cast<const VectorExpr*>(e)->components) expr(c.get());
        break;
      case ExprKind::List:
        for (const ExprLink& c : static_cast<const ListExpr*>(e)->elements) expr(c.get());
        break;
      case ExprKind::Unary: {
        const auto* u = static_cast<const UnaryExpr*>(e);
        if (u->op() != UnaryOp::Not) marks_.unary_ops.insert(offset(u->loc));
        expr(u->operand.get());
        break;
      }
      case ExprKind::Binary: {
        const auto* b = static_cast<const BinaryExpr*>(e);
        expr(b->lhs.get());
        expr(b->rhs.get());
        break;
      }
      case ExprKind::Range: {
        const auto* r = static_cast<const RangeExpr*>(e);
        expr(r->from.get());
        expr(r->to.get());
        expr(r->step.get());
        break;
      }
      case ExprKind::Call: {
        const auto* c = static_cast<const CallExpr*>(e);
        expr(c->callee.get());
        for (const Argument& a : c->args) expr(a.value.get());
        break;
      }
      case ExprKind::Index: {
        const auto* i = static_cast<const IndexExpr*>(e);
        expr(i->object.get());
        expr(i->index.get());
        break;
      }
      case ExprKind::Member: expr(static_cast<const MemberExpr*>(e)->object.get()); break;
      case ExprKind::Block: block(static_cast<const BlockExpr*>(e)->body); break;
      case ExprKind::With: {
        const auto* w = static_cast<const WithExpr*>(e);
        expr(w->base.get());
        block(w->body);
        break;
      }
      case ExprKind::Transform: {
        const auto* t = static_cast<const TransformExpr*>(e);
        expr(t->object.get());
        expr(t->arg.get());
        break;
      }
    }
  }

  const SourceFile& file_;
  Marks& marks_;
};

// ---------------------------------------------------------------------------------------
// Tokens. The lexer mirrors grammar/lexical.hpp closely enough for text that parses (the
// only text the formatter sees): the reparse check below catches any disagreement.
// ---------------------------------------------------------------------------------------
enum class Kind : uint8_t { Word, Number, String, Punct, LineComment, BlockComment };

struct Token {
  Kind kind;
  std::size_t begin, end;  // byte range in the source
  unsigned newlines;       // line breaks between the previous token and this one
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::vector<Token> tokenize(std::string_view text) {
  std::vector<Token> out;
  std::size_t i = 0, n = text.size();
  while (true) {
    unsigned newlines = 0;
    while (i < n && grammar::is_blank(text[i])) newlines += text[i++] == '\n';
    if (i >= n) break;
    std::size_t b = i;
    char c = text[i];
    Kind kind = Kind::Punct;
    if (c == '/' && i + 1 < n && text[i + 1] == '/') {
      kind = Kind::LineComment;
      while (i < n && text[i] != '\n') ++i;
      std::size_t e = i;  // trailing blanks (a CR among them) are not part of the comment
      while (e > b && grammar::is_blank(text[e - 1])) --e;
      out.push_back({kind, b, e, newlines});
      continue;
    }
    if (c == '/' && i + 1 < n && text[i + 1] == '*') {
      kind = Kind::BlockComment;
      std::size_t close = text.find("*/", i + 2);
      i = close == std::string_view::npos ? n : close + 2;
    } else if (c == '"') {
      kind = Kind::String;
      ++i;
      while (i < n && text[i] != '"' && text[i] != '\n') i += text[i] == '\\' ? 2 : 1;
      i = std::min(n, i + 1);
    } else if (is_digit(c) || (c == '.' && i + 1 < n && is_digit(text[i + 1]))) {
      kind = Kind::Number;
      while (i < n && is_digit(text[i])) ++i;
      if (i + 1 < n && text[i] == '.' && is_digit(text[i + 1])) {
        ++i;
        while (i < n && is_digit(text[i])) ++i;
      }
      if (i < n && (text[i] == 'e' || text[i] == 'E')) {
        std::size_t e = i + 1;
        if (e < n && (text[e] == '+' || text[e] == '-')) ++e;
        if (e < n && is_digit(text[e])) {
          i = e;
          while (i < n && is_digit(text[i])) ++i;
        }
      }
    } else if (grammar::is_ident_first(c)) {
      kind = Kind::Word;
      while (i < n && grammar::is_ident_char(text[i])) ++i;
    } else {
      static constexpr std::string_view kLong[] = {"..=", "..", "==", "!=", "<=", ">=",
                                                   "+=",  "-=", "*=", "/="};
      std::size_t len = 1;
      for (std::string_view op : kLong)
        if (text.substr(i, op.size()) == op) {
          len = op.size();
          break;
        }
      i += len;
    }
    out.push_back({kind, b, i, newlines});
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// Layout
// ---------------------------------------------------------------------------------------
enum class Cls : uint8_t { Open, Close, Comma, Semi, Dot, Unary, Op, Operand, Keyword, Comment };

bool is_keyword(std::string_view w) {
  return w != "true" && w != "false" && w != "none" && grammar::is_reserved_word(w);
}

struct Line {
  std::string text;
  std::size_t comment_at = std::string::npos;  // where a trailing // comment starts
};

class Formatter {
 public:
  Formatter(std::string_view text, const Marks& marks) : text_(text), marks_(marks) {}

  std::string run() {
    std::vector<Token> toks = tokenize(text_);
    Cls prev = Cls::Op;
    std::string_view prev_s;
    for (std::size_t k = 0; k < toks.size(); ++k) {
      const Token& t = toks[k];
      std::string_view s = text_.substr(t.begin, t.end - t.begin);
      bool item = marks_.item_starts.count(t.begin) != 0;
      Cls cls = classify(toks, k, s, prev);
      if (lines_.empty() || t.newlines > 0) {
        bool blank = !lines_.empty() && t.newlines >= 2 && prev != Cls::Open && cls != Cls::Close;
        if (blank) lines_.emplace_back();
        int indent = line_indent(cls, s, item);
        lines_.emplace_back();
        line_indent_ = indent;
        lines_.back().text.assign(static_cast<std::size_t>(indent * kIndentWidth), ' ');
      } else {
        int gap = spaces(prev, prev_s, cls, s, item);
        if (cls == Cls::Comment && t.kind == Kind::LineComment) {
          gap = kCommentGap;
          lines_.back().comment_at = lines_.back().text.size() + static_cast<std::size_t>(gap);
        }
        lines_.back().text.append(static_cast<std::size_t>(gap), ' ');
      }
      lines_.back().text += s;
      track_brackets(cls, s);
      prev = cls;
      prev_s = s;
    }
    align_trailing_comments();
    std::string out;
    for (Line& l : lines_) {
      // No trailing blanks, also inside a block comment's lines (they mean nothing there).
      std::istringstream parts(l.text);
      std::string part;
      bool first = true;
      while (std::getline(parts, part)) {
        if (!first) out += '\n';
        first = false;
        while (!part.empty() && grammar::is_blank(part.back())) part.pop_back();
        out += part;
      }
      out += '\n';
    }
    return out;
  }

 private:
  Cls classify(const std::vector<Token>& toks, std::size_t k, std::string_view s, Cls prev) const {
    const Token& t = toks[k];
    switch (t.kind) {
      case Kind::LineComment:
      case Kind::BlockComment: return Cls::Comment;
      case Kind::Number:
      case Kind::String: return Cls::Operand;
      case Kind::Word: {
        // A reserved word after '.' is a member name; before '=' a property or argument name.
        bool named = prev == Cls::Dot ||
                     (k + 1 < toks.size() && text_.substr(toks[k + 1].begin, toks[k + 1].end - toks[k + 1].begin) == "=");
        return is_keyword(s) && !named ? Cls::Keyword : Cls::Operand;
      }
      case Kind::Punct: break;
    }
    if (s == "(" || s == "[" || s == "{") return Cls::Open;
    if (s == ")" || s == "]" || s == "}") return Cls::Close;
    if (s == "<" && marks_.vector_opens.count(t.begin)) return Cls::Open;
    // A '>' closes a vector exactly when a vector is the innermost open bracket: inside a
    // vector component a comparison must be parenthesised.
    if (s == ">" && !stack_.empty() && stack_.back().kind == 'v') return Cls::Close;
    if (s == ",") return Cls::Comma;
    if (s == ";") return Cls::Semi;
    if (s == ".") return Cls::Dot;
    if ((s == "-" || s == "+") && marks_.unary_ops.count(t.begin)) return Cls::Unary;
    return Cls::Op;
  }

  static int spaces(Cls prev, std::string_view prev_s, Cls cls, std::string_view s, bool item) {
    if (cls == Cls::Comma || cls == Cls::Semi) return 0;
    if (cls == Cls::Close) return s == "}" && prev != Cls::Open ? 1 : 0;  // '{ x }', '{}', '(x)'
    if (prev == Cls::Open) return prev_s == "{" ? 1 : 0;
    bool prev_is_else = prev_s == "else";
    if (cls == Cls::Dot || prev == Cls::Dot || prev == Cls::Unary) return 0;
    // f(x) and xs[i]: a bracket right after an operand is a call or an index.
    if (cls == Cls::Open && (s == "(" || s == "[") && (prev == Cls::Operand || prev == Cls::Close)) return 0;
    if (item && prev != Cls::Semi && prev != Cls::Comment && !prev_is_else) return kItemGap;
    return 1;
  }

  int line_indent(Cls cls, std::string_view s, bool item) const {
    if (cls == Cls::Close) return stack_.empty() ? 0 : stack_.back().indent;
    int base = stack_.empty() ? 0 : stack_.back().indent + 1;
    // Among statements and properties, a line that starts none of them continues the
    // previous one's expression: one level deeper.
    bool among_items = stack_.empty() || stack_.back().kind == '{';
    // `else` and a brace on a line of its own (Allman style) line up with their statement.
    bool continues = among_items && !item && cls != Cls::Comment && s != "else" && s != "{";
    return base + (continues ? 1 : 0);
  }

  void track_brackets(Cls cls, std::string_view s) {
    if (cls == Cls::Open) stack_.push_back({s == "<" ? 'v' : s[0], line_indent_});
    else if (cls == Cls::Close && !stack_.empty()) stack_.pop_back();
  }

  // Trailing // comments on consecutive lines start in one column.
  void align_trailing_comments() {
    std::size_t i = 0;
    while (i < lines_.size()) {
      if (!aligned(lines_[i])) {
        ++i;
        continue;
      }
      std::size_t j = i, width = 0;
      for (; j < lines_.size() && aligned(lines_[j]); ++j)
        width = std::max(width, lines_[j].comment_at - kCommentGap);
      for (std::size_t k = i; k < j; ++k) {
        Line& l = lines_[k];
        std::size_t code = l.comment_at - kCommentGap;
        l.text.insert(code, width - code, ' ');
        l.comment_at += width - code;
      }
      i = j;
    }
  }
  static bool aligned(const Line& l) {
    return l.comment_at != std::string::npos && l.text.find('\n') == std::string::npos;
  }

  struct Open {
    char kind;   // '{', '(', '[' or 'v' (a vector's '<')
    int indent;  // the indentation of the line it opened on
  };

  std::string_view text_;
  const Marks& marks_;
  std::vector<Line> lines_;
  std::vector<Open> stack_;
  int line_indent_ = 0;
};

std::string tree_text(const Program& p) {
  std::ostringstream out;
  print_ast(out, p);
  return out.str();
}

}  // namespace

std::string format_source(const SourceFile& file) {
  Program program = parse(file);
  Marks marks;
  MarkCollector(file, marks).stmts(program.stmts());
  std::string out = Formatter(file.text(), marks).run();
  if (out == "\n") out.clear();  // an empty file stays empty

  SourceFile formatted(file.path(), out);
  Program again;
  try {
    again = parse(formatted);
  } catch (const LanguageError& e) {
    throw std::logic_error("rts fmt: the formatted text of " + file.path() +
                           " does not parse (a formatter bug): " + e.diag.message);
  }
  if (tree_text(again) != tree_text(program))
    throw std::logic_error("rts fmt: formatting " + file.path() +
                           " would change its syntax tree (a formatter bug); the file is left as it is");
  return out;
}

}  // namespace rts
