// PEGTL actions: which node builder runs when which grammar rule has matched. Rules without
// an action here build nothing. An action's input begins at the rule's first character, so
// `at(in)` is the location of the construct (a keyword, an operator, a name).
#pragma once

#include <tao/pegtl.hpp>

#include "grammar/grammar.hpp"
#include "parser/node_builders.hpp"
#include "parser/parse_state.hpp"

namespace rts::parse_detail {

namespace pegtl = tao::pegtl;
namespace g = rts::grammar;

template <typename Rule>
struct action : pegtl::nothing<Rule> {};

template <typename Input>
SourceLoc at(const Input& in, const ParseState& st) {
  return st.loc(in.begin());
}

template <typename Input>
std::string_view word_of(const Input& in) {
  return word_at(in.begin(), in.end());
}

// Declares action<RULE> whose apply() runs BODY with `in` and `st` in scope.
#define RTS_ACTION(RULE, BODY)                                        \
  template <>                                                         \
  struct action<RULE> {                                               \
    template <typename Input>                                         \
    static void apply(const Input& in, ParseState& st) {              \
      (void)in;                                                       \
      BODY;                                                           \
    }                                                                 \
  };
#define RTS_ACTION_B(RULE, BODY)                                      \
  template <bool B>                                                   \
  struct action<RULE<B>> {                                            \
    template <typename Input>                                         \
    static void apply(const Input& in, ParseState& st) {              \
      (void)in;                                                       \
      BODY;                                                           \
    }                                                                 \
  };

// Leaves
RTS_ACTION(g::number, push_number(st, at(in, st), in.string_view()))
RTS_ACTION(g::string_open, open_bracket(st, at(in, st), '"', 0))
RTS_ACTION(g::string_body, st.string_body = in.string_view(); st.string_body_loc = at(in, st))
RTS_ACTION(g::string_literal, push_string(st, close_bracket(st).loc))
RTS_ACTION(g::include_path, close_bracket(st); st.include_path = decode_string(st))
RTS_ACTION(g::true_literal, push_bool(st, at(in, st), true))
RTS_ACTION(g::false_literal, push_bool(st, at(in, st), false))
RTS_ACTION(g::none_literal, push_none(st, at(in, st)))
RTS_ACTION(g::name_ref, push_name_ref(st, at(in, st), word_of(in)))

// Names that a later action pops
RTS_ACTION(g::block_kind, push_name(st, at(in, st), word_of(in)))
RTS_ACTION(g::member_name, push_name(st, at(in, st), word_of(in)))
RTS_ACTION(g::named_arg_head, push_name(st, at(in, st), word_of(in)))
RTS_ACTION(g::property_head, push_name(st, at(in, st), word_of(in)))
RTS_ACTION(g::assign_head, push_name(st, at(in, st), word_of(in)); st.assign_ops.push_back(st.assign_op))
RTS_ACTION(g::let_name, push_name(st, at(in, st), word_of(in)))
RTS_ACTION(g::for_variable, push_name(st, at(in, st), word_of(in)))
RTS_ACTION(g::macro_name, push_name(st, at(in, st), word_of(in)))
RTS_ACTION(g::param_name, push_name(st, at(in, st), word_of(in)))

// Brackets
RTS_ACTION(g::paren_open, open_bracket(st, at(in, st), '(', 0))
RTS_ACTION(g::paren_inner, close_bracket(st))
RTS_ACTION(g::list_open, open_bracket(st, at(in, st), '[', static_cast<uint32_t>(st.exprs.size())))
RTS_ACTION(g::list_inner, finish_list(st))
RTS_ACTION(g::vector_open, open_bracket(st, at(in, st), '<', static_cast<uint32_t>(st.exprs.size())))
RTS_ACTION(g::vector_inner, finish_vector(st))
RTS_ACTION(g::call_open, open_bracket(st, at(in, st), '(', static_cast<uint32_t>(st.args.size())))
RTS_ACTION(g::call_inner, finish_call(st))
RTS_ACTION(g::index_open, open_bracket(st, at(in, st), '[', 0))
RTS_ACTION(g::index_inner, finish_index(st))
RTS_ACTION(g::block_open, open_bracket(st, at(in, st), '{', static_cast<uint32_t>(st.items.size())))
RTS_ACTION(g::block_inner, finish_block_body(st))
RTS_ACTION(g::body_open, open_bracket(st, at(in, st), '{', static_cast<uint32_t>(st.stmts.size())))
RTS_ACTION(g::body_inner, finish_body(st))
RTS_ACTION(g::params_open, open_bracket(st, at(in, st), '(', static_cast<uint32_t>(st.params.size())))
RTS_ACTION(g::params_inner, finish_params(st))

// Postfix, blocks, arguments, properties
RTS_ACTION(g::member_tail, build_member(st))
RTS_ACTION(g::with_tail, build_with(st))
RTS_ACTION(g::block_expr, build_block(st))
RTS_ACTION(g::named_arg, build_named_arg(st))
RTS_ACTION(g::positional_arg, build_positional_arg(st))
RTS_ACTION(g::property, build_property(st))
RTS_ACTION(g::block_statement, build_block_statement(st))

// Operators
RTS_ACTION_B(g::pow_tail, build_binary(st, at(in, st), ast::BinaryOp::Pow))
RTS_ACTION_B(g::negation, build_unary(st, at(in, st), ast::UnaryOp::Neg))
RTS_ACTION_B(g::unary_plus, build_unary(st, at(in, st), ast::UnaryOp::Plus))
RTS_ACTION_B(g::logical_not, build_unary(st, at(in, st), ast::UnaryOp::Not))
RTS_ACTION_B(g::mul_tail, build_binary(st, at(in, st), ast::BinaryOp::Mul))
RTS_ACTION_B(g::div_tail, build_binary(st, at(in, st), ast::BinaryOp::Div))
RTS_ACTION_B(g::mod_tail, build_binary(st, at(in, st), ast::BinaryOp::Mod))
RTS_ACTION_B(g::add_tail, build_binary(st, at(in, st), ast::BinaryOp::Add))
RTS_ACTION_B(g::sub_tail, build_binary(st, at(in, st), ast::BinaryOp::Sub))
RTS_ACTION_B(g::eq_tail, build_binary(st, at(in, st), ast::BinaryOp::Eq))
RTS_ACTION_B(g::ne_tail, build_binary(st, at(in, st), ast::BinaryOp::Ne))
RTS_ACTION_B(g::le_tail, build_binary(st, at(in, st), ast::BinaryOp::Le))
RTS_ACTION_B(g::ge_tail, build_binary(st, at(in, st), ast::BinaryOp::Ge))
RTS_ACTION_B(g::lt_tail, build_binary(st, at(in, st), ast::BinaryOp::Lt))
RTS_ACTION_B(g::gt_tail, build_binary(st, at(in, st), ast::BinaryOp::Gt))
RTS_ACTION_B(g::and_tail, build_binary(st, at(in, st), ast::BinaryOp::And))
RTS_ACTION_B(g::or_tail, build_binary(st, at(in, st), ast::BinaryOp::Or))
RTS_ACTION_B(g::range_step, st.has_step = true)
// The input starts at `..` or `..=`.
RTS_ACTION_B(g::range_tail, build_range(st, in.size() > 2 && in.begin()[2] == '='))
RTS_ACTION_B(g::translate_tail, build_transform(st, at(in, st), ast::TransformOp::Translate))
RTS_ACTION_B(g::rotate_tail, build_transform(st, at(in, st), ast::TransformOp::Rotate))
RTS_ACTION_B(g::scale_tail, build_transform(st, at(in, st), ast::TransformOp::Scale))
RTS_ACTION_B(g::matrix_tail, build_transform(st, at(in, st), ast::TransformOp::Matrix))

// Statements
RTS_ACTION(g::let_stmt, build_let(st, at(in, st)))
RTS_ACTION(g::assign_set, st.assign_op = ast::AssignOp::Set)
RTS_ACTION(g::assign_add, st.assign_op = ast::AssignOp::Add)
RTS_ACTION(g::assign_sub, st.assign_op = ast::AssignOp::Sub)
RTS_ACTION(g::assign_mul, st.assign_op = ast::AssignOp::Mul)
RTS_ACTION(g::assign_div, st.assign_op = ast::AssignOp::Div)
RTS_ACTION(g::assign_stmt, build_assign(st))
RTS_ACTION(g::else_clause, st.has_else = true)
RTS_ACTION(g::if_stmt, build_if(st, at(in, st), false))
RTS_ACTION(g::else_if, build_if(st, at(in, st), true))
RTS_ACTION(g::for_stmt, build_for(st, at(in, st)))
RTS_ACTION(g::while_stmt, build_while(st, at(in, st)))
RTS_ACTION(g::param_default, st.has_default = true)
RTS_ACTION(g::param, build_param(st))
RTS_ACTION(g::macro_stmt, build_macro(st, at(in, st)))
RTS_ACTION(g::return_value, st.has_return_value = true)
RTS_ACTION(g::return_stmt, build_return(st, at(in, st)))
RTS_ACTION(g::break_stmt, build_break(st, at(in, st)))
RTS_ACTION(g::continue_stmt, build_continue(st, at(in, st)))
RTS_ACTION(g::include_stmt, build_include(st, at(in, st)))
RTS_ACTION(g::expr_stmt, build_expr_stmt(st))

#undef RTS_ACTION
#undef RTS_ACTION_B

}  // namespace rts::parse_detail
