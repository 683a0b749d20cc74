// The non-template half of the parser's actions: each function pops the pieces of one
// construct off the ParseState stacks and pushes the AST node made from them. The PEGTL
// actions (parse_actions.hpp) only say which builder runs for which rule and where.
#pragma once

#include <string_view>

#include "parser/parse_state.hpp"

namespace rts::parse_detail {

// Leaves
void push_number(ParseState& st, SourceLoc loc, std::string_view text);
void push_string(ParseState& st, SourceLoc quote_loc);  // from st.string_body
std::string decode_string(ParseState& st);              // st.string_body with escapes decoded
void push_bool(ParseState& st, SourceLoc loc, bool value);
void push_none(ParseState& st, SourceLoc loc);
void push_name_ref(ParseState& st, SourceLoc loc, std::string_view name);
void push_name(ParseState& st, SourceLoc loc, std::string_view name);

// Brackets: the opener records where its children start; the inner rule's action collects.
void open_bracket(ParseState& st, SourceLoc loc, char ch, uint32_t mark);
Open close_bracket(ParseState& st);
void finish_list(ParseState& st);
void finish_vector(ParseState& st);
void finish_call(ParseState& st);
void finish_index(ParseState& st);
void finish_block_body(ParseState& st);
void finish_body(ParseState& st);
void finish_params(ParseState& st);

// Expressions
void build_unary(ParseState& st, SourceLoc op_loc, ast::UnaryOp op);
void build_binary(ParseState& st, SourceLoc op_loc, ast::BinaryOp op);
void build_range(ParseState& st, bool inclusive);
void build_transform(ParseState& st, SourceLoc op_loc, ast::TransformOp op);
void build_member(ParseState& st);
void build_with(ParseState& st);
void build_block(ParseState& st);
void build_named_arg(ParseState& st);
void build_positional_arg(ParseState& st);
void build_property(ParseState& st);
void build_block_statement(ParseState& st);

// Statements
void build_let(ParseState& st, SourceLoc loc);
void build_assign(ParseState& st);
void build_if(ParseState& st, SourceLoc loc, bool as_else_body);
void build_for(ParseState& st, SourceLoc loc);
void build_while(ParseState& st, SourceLoc loc);
void build_param(ParseState& st);
void build_macro(ParseState& st, SourceLoc loc);
void build_return(ParseState& st, SourceLoc loc);
void build_break(ParseState& st, SourceLoc loc);
void build_continue(ParseState& st, SourceLoc loc);
void build_include(ParseState& st, SourceLoc loc);
void build_expr_stmt(ParseState& st);

}  // namespace rts::parse_detail
