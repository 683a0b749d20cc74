#include "parser/node_builders.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <unordered_map>

#include <fmt/format.h>

namespace rts::parse_detail {
namespace {

using namespace rts::ast;

[[noreturn]] void too_high(const ParseState& st, SourceLoc loc) {
  throw LanguageError(loc, fmt::format("expression nested too deeply (the syntax tree would be "
                                       "deeper than {} levels; split it with 'let')",
                                       st.max_height));
}

uint32_t checked_height(const ParseState& st, uint32_t h, SourceLoc loc) {
  if (h > st.max_height) too_high(st, loc);
  return h;
}

void push_expr(ParseState& st, ExprPtr e, uint32_t height) {
  SourceLoc loc = e->loc;
  st.exprs.push_back({std::move(e), checked_height(st, height, loc)});
}

void push_stmt(ParseState& st, StmtPtr s, uint32_t height) {
  SourceLoc loc = s->loc;
  checked_height(st, height, loc);
  // Outside every bracket a statement is the program's own: nothing will collect it into a
  // body, so it goes straight to the program's list (no height, no second copy at the end).
  if (st.opens.empty()) st.top_level.push_back(s);
  else st.stmts.push_back({s, height});
}

Sized<ExprPtr> pop_expr(ParseState& st) {
  Sized<ExprPtr> e = std::move(st.exprs.back());
  st.exprs.pop_back();
  return e;
}

NamePiece pop_name(ParseState& st) {
  NamePiece n = st.names.back();
  st.names.pop_back();
  return n;
}

template <typename T>
Sized<T> pop(std::vector<Sized<T>>& v) {
  Sized<T> x = std::move(v.back());
  v.pop_back();
  return x;
}

// Moves the pieces pushed on `stack` since `mark` into a list in the arena, in order, first
// passing each to `check` (which may throw); returns their tallest height (0 when there are none).
// `out` is a ListPiece<T> or a node's NodeList<T>; T is built from each piece.
template <typename T, typename Piece, typename Out, typename Check>
uint32_t collect(ParseState& st, std::vector<Sized<Piece>>& stack, uint32_t mark, Out& out, Check check) {
  uint32_t tallest = 0;
  for (std::size_t i = mark; i < stack.size(); ++i) {
    check(stack[i].node);
    tallest = std::max(tallest, stack[i].height);
  }
  out = st.arena->list<T>(stack.begin() + mark, stack.end(), [](const Sized<Piece>& piece) { return piece.node; });
  stack.resize(mark);
  return tallest;
}

template <typename T, typename Piece, typename Out>
uint32_t collect(ParseState& st, std::vector<Sized<Piece>>& stack, uint32_t mark, Out& out) {
  return collect<T>(st, stack, mark, out, [](const Piece&) {});
}

void append_utf8(std::string& out, uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

constexpr uint32_t kMaxCodePoint = 0x10FFFF;
constexpr uint32_t kSurrogateFirst = 0xD800;
constexpr uint32_t kSurrogateLast = 0xDFFF;

}  // namespace

// ---------------------------------------------------------------------------------------
// Leaves
// ---------------------------------------------------------------------------------------
void push_number(ParseState& st, SourceLoc loc, std::string_view text) {
  // Most literals are short decimals: their node needs no conversion (NumberExpr).
  if (auto n = make_short_number(*st.arena, loc, text)) {
    push_expr(st, n, 1);
    return;
  }
  double value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) {
    // from_chars leaves the value unset on overflow and underflow; strtod tells them apart.
    value = std::strtod(std::string(text).c_str(), nullptr);
    if (std::isinf(value))
      throw LanguageError(loc, fmt::format("number '{}' is too large", text));
  } else if (ec != std::errc() || end != text.data() + text.size()) {
    throw LanguageError(loc, fmt::format("malformed number '{}'", text));
  }
  push_expr(st, make_number(*st.arena, loc, value), 1);
}

std::string decode_string(ParseState& st) {
  std::string_view raw = st.string_body;
  std::string out;
  out.reserve(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    char c = raw[i];
    if (c != '\\') {
      out += c;
      continue;
    }
    std::size_t escape_start = i;
    char code = raw[++i];  // the grammar guarantees a valid escape code follows
    switch (code) {
      case 'n': out += '\n'; break;
      case 't': out += '\t'; break;
      case 'r': out += '\r'; break;
      case '0': out += '\0'; break;
      case '\\': out += '\\'; break;
      case '"': out += '"'; break;
      case 'u': {
        std::size_t open = i + 1, close = raw.find('}', open);
        std::string_view hex = raw.substr(open + 1, close - open - 1);
        uint32_t cp = 0;
        std::from_chars(hex.data(), hex.data() + hex.size(), cp, 16);
        if (cp > kMaxCodePoint || (cp >= kSurrogateFirst && cp <= kSurrogateLast)) {
          SourceLoc at = st.string_body_loc;
          at = at.advanced(static_cast<int32_t>(escape_start));
          throw LanguageError(at, fmt::format("'\\u{{{}}}' is not a valid Unicode code point", hex));
        }
        append_utf8(out, cp);
        i = close;
        break;
      }
      default: out += code; break;
    }
  }
  return out;
}

void push_string(ParseState& st, SourceLoc quote_loc) {
  push_expr(st, st.arena->make<StringExpr>(quote_loc, st.arena->text(decode_string(st))), 1);
}

void push_bool(ParseState& st, SourceLoc loc, bool value) {
  push_expr(st, st.arena->make<BoolExpr>(loc, value), 1);
}

void push_none(ParseState& st, SourceLoc loc) { push_expr(st, st.arena->make<NoneExpr>(loc), 1); }

void push_name_ref(ParseState& st, SourceLoc loc, std::string_view name) {
  push_expr(st, st.arena->make<NameExpr>(loc, st.symbol(name)), 1);
}

void push_name(ParseState& st, SourceLoc loc, std::string_view name) {
  st.names.push_back({st.symbol(name), loc});
}

// ---------------------------------------------------------------------------------------
// Brackets
// ---------------------------------------------------------------------------------------
void open_bracket(ParseState& st, SourceLoc loc, char ch, uint32_t mark) {
  st.opens.push_back({loc, mark, ch});
}

Open close_bracket(ParseState& st) {
  Open o = st.opens.back();
  st.opens.pop_back();
  return o;
}

void finish_list(ParseState& st) {
  Open o = close_bracket(st);
  ListPiece<ExprLink> elements;
  uint32_t h = collect<ExprLink>(st, st.exprs, o.mark, elements);
  auto list = st.arena->make<ListExpr>(o.loc);  // after its elements: links reach back only
  list->elements = elements;
  push_expr(st, list, h + 1);
}

// The stride in bytes when the pieces from `mark` on are number literals one after another
// in the arena at one stride (they were parsed one after another, all of one of
// NumberExpr's sizes but maybe the last); 0 when they are not.
uint32_t literal_stride(const ParseState& st, uint32_t mark) {
  const std::size_t n = st.exprs.size() - mark;
  if (mark >= st.exprs.size() || n >= (1u << 29)) return 0;
  auto address = [&](std::size_t k) { return reinterpret_cast<std::uintptr_t>(st.exprs[mark + k].node.get()); };
  const std::uintptr_t stride = n == 1 ? sizeof(NumberExpr) : address(1) - address(0);
  if (stride != 8 && stride != 12 && stride != 16) return 0;
  for (std::size_t k = 0; k < n; ++k)
    if (st.exprs[mark + k].node->kind != ExprKind::Number || address(k) != address(0) + k * stride) return 0;
  return static_cast<uint32_t>(stride);
}

void finish_vector(ParseState& st) {
  Open o = close_bracket(st);
  uint32_t h = 0;
  NodePtr<VectorExpr> vec;
  if (const uint32_t stride = literal_stride(st, o.mark)) {
    const auto count = static_cast<uint32_t>(st.exprs.size() - o.mark);
    const auto* first = static_cast<const NumberExpr*>(st.exprs[o.mark].node.get());
    vec = st.arena->make<VectorExpr>(o.loc);
    vec->components.set_literals(first, count, stride);
    h = 1;
    st.exprs.resize(o.mark);
  } else {
    ListPiece<ExprLink> links;
    h = collect<ExprLink>(st, st.exprs, o.mark, links);
    vec = st.arena->make<VectorExpr>(o.loc);  // after its list: links reach back only
    vec->components = links;
  }
  push_expr(st, vec, h + 1);
}

void finish_call(ParseState& st) {
  Open o = close_bracket(st);
  Sized<ExprPtr> callee = pop_expr(st);
  std::optional<SourceLoc> first_named;
  ListPiece<Argument> args;
  uint32_t h = std::max(callee.height, collect<Argument>(st, st.args, o.mark, args, [&](const ArgumentPiece& a) {
    if (a.name) {
      if (!first_named) first_named = a.loc;
    } else if (first_named) {
      LanguageError e(a.loc, "positional argument after a named argument");
      e.diag.notes.push_back(Note{*first_named, "the first named argument is here"});
      throw e;
    }
  }));
  // After its arguments, so that its links reach back to them.
  auto call = st.arena->make<CallExpr>(callee.node->loc, callee.node);
  call->args = args;
  push_expr(st, call, h + 1);
}

void finish_index(ParseState& st) {
  close_bracket(st);
  Sized<ExprPtr> index = pop_expr(st);
  Sized<ExprPtr> object = pop_expr(st);
  SourceLoc loc = object.node->loc;
  uint32_t h = std::max(index.height, object.height) + 1;
  push_expr(st, st.arena->make<IndexExpr>(loc, std::move(object.node), std::move(index.node)), h);
}

void finish_block_body(ParseState& st) {
  Open o = close_bracket(st);
  BlockBodyPiece body;
  body.open_loc = o.loc;
  uint32_t h = collect<BlockItem>(st, st.items, o.mark, body.items);
  st.block_bodies.push_back({std::move(body), h});
}

void finish_body(ParseState& st) {
  Open o = close_bracket(st);
  BodyPiece body;
  body.open_loc = o.loc;
  uint32_t h = collect<StmtLink>(st, st.stmts, o.mark, body.stmts);
  st.bodies.push_back({std::move(body), h});
}

void finish_params(ParseState& st) {
  Open o = close_bracket(st);
  ListPiece<Param> list;
  std::unordered_map<Symbol, SourceLoc> seen;
  std::optional<SourceLoc> first_default;
  uint32_t h = collect<Param>(st, st.params, o.mark, list, [&](const ParamPiece& p) {
    if (auto [it, inserted] = seen.try_emplace(p.name, p.loc); !inserted) {
      LanguageError e(p.loc, fmt::format("duplicate parameter '{}'", *p.name));
      e.diag.notes.push_back(Note{it->second, "first declared here"});
      throw e;
    }
    if (p.default_value) {
      if (!first_default) first_default = p.loc;
    } else if (first_default) {
      LanguageError e(p.loc, fmt::format("required parameter '{}' follows a parameter with a "
                                         "default value", *p.name));
      e.diag.notes.push_back(Note{*first_default, "the first parameter with a default is here"});
      throw e;
    }
  });
  st.param_lists.push_back({std::move(list), h});
}

// ---------------------------------------------------------------------------------------
// Expressions
// ---------------------------------------------------------------------------------------
void build_unary(ParseState& st, SourceLoc op_loc, UnaryOp op) {
  Sized<ExprPtr> operand = pop_expr(st);
  // A minus written before a number literal makes a negative literal, not a node above it:
  // vectors of negative coordinates are most of a generated scene's numbers, and the value
  // is the one negation would give (the operand is complete: `-2^2` negates the power). A
  // literal that is already negative (`--2`) keeps its operator.
  // The literal's node is this parse's alone: it becomes the negative literal in place.
  if (op == UnaryOp::Neg && operand.node->kind == ExprKind::Number) {
    auto& number = static_cast<NumberExpr&>(*operand.node);
    if (!std::signbit(number.value())) {
      number.negate();
      number.loc = op_loc;
      push_expr(st, operand.node, operand.height);
      return;
    }
  }
  push_expr(st, st.arena->make<UnaryExpr>(op_loc, op, std::move(operand.node)), operand.height + 1);
}

void build_binary(ParseState& st, SourceLoc op_loc, BinaryOp op) {
  Sized<ExprPtr> rhs = pop_expr(st);
  Sized<ExprPtr> lhs = pop_expr(st);
  SourceLoc loc = lhs.node->loc;
  uint32_t h = std::max(lhs.height, rhs.height) + 1;
  checked_height(st, h, op_loc);
  push_expr(st, make_with_operator<BinaryExpr>(*st.arena, op_loc, loc, op, lhs.node, rhs.node), h);
}

void build_range(ParseState& st, bool inclusive) {
  Sized<ExprPtr> step{nullptr, 0};
  if (st.has_step) step = pop_expr(st);
  st.has_step = false;
  Sized<ExprPtr> to = pop_expr(st);
  Sized<ExprPtr> from = pop_expr(st);
  SourceLoc loc = from.node->loc;
  uint32_t h = std::max({from.height, to.height, step.height}) + 1;
  push_expr(st, st.arena->make<RangeExpr>(loc, std::move(from.node), std::move(to.node),
                                            std::move(step.node), inclusive), h);
}

void build_transform(ParseState& st, SourceLoc op_loc, TransformOp op) {
  Sized<ExprPtr> arg = pop_expr(st);
  Sized<ExprPtr> object = pop_expr(st);
  SourceLoc loc = object.node->loc;
  uint32_t h = std::max(arg.height, object.height) + 1;
  checked_height(st, h, op_loc);
  push_expr(st, make_with_operator<TransformExpr>(*st.arena, op_loc, loc, object.node, op, arg.node), h);
}

void build_member(ParseState& st) {
  NamePiece member = pop_name(st);
  Sized<ExprPtr> object = pop_expr(st);
  SourceLoc loc = object.node->loc;
  checked_height(st, object.height + 1, member.loc);
  push_expr(st, st.arena->make<MemberExpr>(loc, std::move(object.node), member.name, member.loc),
            object.height + 1);
}

void build_with(ParseState& st) {
  Sized<BlockBodyPiece> body = pop(st.block_bodies);
  Sized<ExprPtr> base = pop_expr(st);
  auto with = st.arena->make<WithExpr>(base.node->loc, base.node);
  with->body = body.node;
  push_expr(st, std::move(with), std::max(base.height, body.height) + 1);
}

void build_block(ParseState& st) {
  Sized<BlockBodyPiece> body = pop(st.block_bodies);
  NamePiece kind = pop_name(st);
  auto block = st.arena->make<BlockExpr>(kind.loc, kind.name);
  block->body = body.node;
  push_expr(st, std::move(block), body.height + 1);
}

void build_named_arg(ParseState& st) {
  Sized<ExprPtr> value = pop_expr(st);
  NamePiece name = pop_name(st);
  st.args.push_back({ArgumentPiece{name.name, name.loc, value.node}, value.height + 1});
}

void build_positional_arg(ParseState& st) {
  Sized<ExprPtr> value = pop_expr(st);
  SourceLoc loc = value.node->loc;
  st.args.push_back({ArgumentPiece{nullptr, loc, value.node}, value.height + 1});
}

void build_property(ParseState& st) {
  Sized<ExprPtr> value = pop_expr(st);
  NamePiece name = pop_name(st);
  st.items.push_back({BlockItem::property_item(name.name, value.node, name.loc), value.height + 1});
}

void build_block_statement(ParseState& st) {
  Sized<StmtPtr> stmt = pop(st.stmts);
  st.items.push_back({BlockItem::statement_item(stmt.node, stmt.node->loc), stmt.height + 1});
}

// ---------------------------------------------------------------------------------------
// Statements
// ---------------------------------------------------------------------------------------
void build_let(ParseState& st, SourceLoc loc) {
  Sized<ExprPtr> value = pop_expr(st);
  NamePiece name = pop_name(st);
  push_stmt(st, st.arena->make<LetStmt>(loc, name.name, std::move(value.node), name.loc), value.height + 1);
}

void build_assign(ParseState& st) {
  Sized<ExprPtr> value = pop_expr(st);
  NamePiece name = pop_name(st);
  AssignOp op = st.assign_ops.back();
  st.assign_ops.pop_back();
  push_stmt(st, st.arena->make<AssignStmt>(name.loc, name.name, op, std::move(value.node)), value.height + 1);
}

void build_if(ParseState& st, SourceLoc loc, bool as_else_body) {
  NodePtr<Body> else_body;
  uint32_t h = 0;
  if (st.has_else) {
    Sized<BodyPiece> e = pop(st.bodies);
    h = e.height;
    else_body = st.arena->make<Body>(e.node);
  }
  st.has_else = false;
  Sized<BodyPiece> then_body = pop(st.bodies);
  Sized<ExprPtr> cond = pop_expr(st);
  h = std::max({h, then_body.height, cond.height}) + 1;
  auto stmt = st.arena->make<IfStmt>(loc, std::move(cond.node));
  stmt->then_body = then_body.node;
  stmt->else_body = else_body;
  if (!as_else_body) {
    push_stmt(st, std::move(stmt), h);
    return;
  }
  // `else if`: the nested if is the only statement of the else body.
  BodyPiece body;
  body.open_loc = loc;
  const StmtPtr only[] = {stmt};
  body.stmts = st.arena->list<StmtLink>(std::begin(only), std::end(only), [](StmtPtr s) { return s; });
  st.bodies.push_back({std::move(body), checked_height(st, h + 1, loc)});
}

void build_for(ParseState& st, SourceLoc loc) {
  Sized<BodyPiece> body = pop(st.bodies);
  Sized<ExprPtr> iterable = pop_expr(st);
  NamePiece var = pop_name(st);
  auto stmt = st.arena->make<ForStmt>(loc, var.name, var.loc, iterable.node);
  stmt->body = body.node;
  push_stmt(st, std::move(stmt), std::max(body.height, iterable.height) + 1);
}

void build_while(ParseState& st, SourceLoc loc) {
  Sized<BodyPiece> body = pop(st.bodies);
  Sized<ExprPtr> cond = pop_expr(st);
  auto stmt = st.arena->make<WhileStmt>(loc, cond.node);
  stmt->body = body.node;
  push_stmt(st, std::move(stmt), std::max(body.height, cond.height) + 1);
}

void build_param(ParseState& st) {
  Sized<ExprPtr> value{nullptr, 0};
  if (st.has_default) value = pop_expr(st);
  st.has_default = false;
  NamePiece name = pop_name(st);
  st.params.push_back({ParamPiece{name.name, name.loc, value.node}, value.height + 1});
}

void build_macro(ParseState& st, SourceLoc loc) {
  Sized<BodyPiece> body = pop(st.bodies);
  Sized<ListPiece<Param>> params = pop(st.param_lists);
  NamePiece name = pop_name(st);
  auto stmt = st.arena->make<MacroStmt>(loc, name.name);
  stmt->params = params.node;
  stmt->body = body.node;
  push_stmt(st, std::move(stmt), std::max(body.height, params.height) + 1);
}

void build_return(ParseState& st, SourceLoc loc) {
  Sized<ExprPtr> value{nullptr, 0};
  if (st.has_return_value) value = pop_expr(st);
  st.has_return_value = false;
  push_stmt(st, st.arena->make<ReturnStmt>(loc, std::move(value.node)), value.height + 1);
}

void build_break(ParseState& st, SourceLoc loc) { push_stmt(st, st.arena->make<BreakStmt>(loc), 1); }

void build_continue(ParseState& st, SourceLoc loc) {
  push_stmt(st, st.arena->make<ContinueStmt>(loc), 1);
}

void build_include(ParseState& st, SourceLoc loc) {
  push_stmt(st, st.arena->make<IncludeStmt>(loc, st.arena->text(st.include_path)), 1);
  st.include_path.clear();
}

void build_expr_stmt(ParseState& st) {
  Sized<ExprPtr> e = pop_expr(st);
  SourceLoc loc = e.node->loc;
  push_stmt(st, st.arena->make<ExprStmt>(loc, std::move(e.node)), e.height + 1);
}

}  // namespace rts::parse_detail
