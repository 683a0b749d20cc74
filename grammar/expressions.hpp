// Expression rules, one struct per precedence level. Every level is templated on `B`:
// whether a bare `name {` may start a block literal. It is false in the condition of
// if/while and the iterable of for (so `while n < limit {` opens the body), and brackets,
// parentheses, argument lists and block bodies switch it back to true.
//
// Precedence, lowest first: transform postfix, or, and, not, comparison (non-associative),
// range, additive, multiplicative, unary prefix, power (right-assoc), postfix, primary.
//
// Rules named *_rhs / *_operand / *_arg / *_inner are the part after an operator or an
// opening bracket; they exist as distinct types so that each has its own error message
// (grammar/errors.hpp) and so that the parser can count nesting on them. Where such a rule
// refers to a rule defined further down, it wraps it in seq<> (a base class must be complete).
#pragma once

#include "grammar/lexical.hpp"

namespace rts::grammar {

template <bool B> struct expression;
template <bool B> struct or_expr;
template <bool B> struct additive;
template <bool B> struct unary;
struct block_body;

// ---------------------------------------------------------------------------------------
// Primary expressions
// ---------------------------------------------------------------------------------------
struct name_ref : identifier {};

struct paren_open : token<one<'('>> {};
struct paren_close : token<one<')'>> {};
struct paren_inner : seq<expression<true>, must<paren_close>> {};
struct paren_expr : seq<paren_open, must<paren_inner>> {};

struct list_open : token<one<'['>> {};
struct list_close : token<one<']'>> {};
struct list_element : seq<expression<true>> {};
struct list_inner
    : seq<opt<list_element, star<comma, list_element>, opt<comma>>, must<list_close>> {};
struct list_expr : seq<list_open, list_inner> {};

// <x, y> to <x, y, z, w>. Components are additive-level so that `>` closes the vector.
struct vector_open : token<one<'<'>> {};
struct vector_close : token<one<'>'>> {};
struct vector_component : seq<additive<true>> {};
struct vector_comma : comma {};
struct vector_inner
    : seq<must<vector_component>, must<vector_comma>, must<vector_component>,
          opt<comma, must<vector_component>>, opt<comma, must<vector_component>>,
          must<vector_close>> {};
struct vector_expr : seq<vector_open, vector_inner> {};

// kind { items }: the kind is a name whose next token is `{`.
struct block_kind : seq<identifier, at<one<'{'>>> {};
struct block_expr : seq<block_kind, block_body> {};

struct true_literal : kw_true {};
struct false_literal : kw_false {};
struct none_literal : kw_none {};

template <bool B> struct primary;
template <>
struct primary<true>
    : sor<number_literal, string_literal, true_literal, false_literal, none_literal, block_expr,
          name_ref, vector_expr, list_expr, paren_expr> {};
template <>
struct primary<false>
    : sor<number_literal, string_literal, true_literal, false_literal, none_literal, name_ref,
          vector_expr, list_expr, paren_expr> {};

// ---------------------------------------------------------------------------------------
// Postfix: call, index, member, with
// ---------------------------------------------------------------------------------------
struct call_open : token<one<'('>> {};
struct call_close : token<one<')'>> {};
struct named_arg_head : seq<field_name, equals> {};
struct named_arg_value : seq<expression<true>> {};
struct named_arg : seq<named_arg_head, must<named_arg_value>> {};
struct positional_arg : seq<expression<true>> {};
struct argument : sor<named_arg, positional_arg> {};
struct call_inner : seq<opt<argument, star<comma, argument>, opt<comma>>, must<call_close>> {};
struct call_tail : seq<call_open, call_inner> {};

struct index_open : token<one<'['>> {};
struct index_close : token<one<']'>> {};
struct index_inner : seq<expression<true>, must<index_close>> {};
struct index_tail : seq<index_open, must<index_inner>> {};

// `.` but not `..` (a range)
struct member_dot : token<seq<one<'.'>, not_at<one<'.'>>>> {};
struct member_name : field_name {};
struct member_tail : seq<member_dot, must<member_name>> {};

struct with_body : seq<block_body> {};
struct with_tail : seq<kw_with, must<with_body>> {};

struct postfix_op : seq<next_is<'(', '[', '.', 'w'>, sor<call_tail, index_tail, member_tail, with_tail>> {};
template <bool B>
struct postfix : seq<primary<B>, star<postfix_op>> {};

// ---------------------------------------------------------------------------------------
// Power (right-associative, tighter than unary minus: -2^2 is -(2^2); 2^-1 is allowed)
// ---------------------------------------------------------------------------------------
struct caret : token<one<'^'>> {};
template <bool B> struct pow_rhs : unary<B> {};
template <bool B> struct pow_tail : seq<caret, must<pow_rhs<B>>> {};
template <bool B> struct power : seq<postfix<B>, opt<next_is<'^'>, pow_tail<B>>> {};

// ---------------------------------------------------------------------------------------
// Unary prefix - and +
// ---------------------------------------------------------------------------------------
struct minus_sign : token<one<'-'>> {};
struct plus_sign : token<one<'+'>> {};
template <bool B> struct neg_operand : unary<B> {};
template <bool B> struct pos_operand : unary<B> {};
template <bool B> struct negation : seq<minus_sign, must<neg_operand<B>>> {};
template <bool B> struct unary_plus : seq<plus_sign, must<pos_operand<B>>> {};
template <bool B> struct unary : sor<seq<next_is<'-', '+'>, sor<negation<B>, unary_plus<B>>>, power<B>> {};

// ---------------------------------------------------------------------------------------
// Multiplicative and additive (left-associative)
// ---------------------------------------------------------------------------------------
struct star_op : token<one<'*'>> {};
struct slash_op : token<one<'/'>> {};
struct percent_op : token<one<'%'>> {};
template <bool B> struct mul_rhs : unary<B> {};
template <bool B> struct div_rhs : unary<B> {};
template <bool B> struct mod_rhs : unary<B> {};
template <bool B> struct mul_tail : seq<star_op, must<mul_rhs<B>>> {};
template <bool B> struct div_tail : seq<slash_op, must<div_rhs<B>>> {};
template <bool B> struct mod_tail : seq<percent_op, must<mod_rhs<B>>> {};
template <bool B>
struct multiplicative
    : seq<unary<B>, star<next_is<'*', '/', '%'>, sor<mul_tail<B>, div_tail<B>, mod_tail<B>>>> {};

template <bool B> struct add_rhs : multiplicative<B> {};
template <bool B> struct sub_rhs : multiplicative<B> {};
template <bool B> struct add_tail : seq<plus_sign, must<add_rhs<B>>> {};
template <bool B> struct sub_tail : seq<minus_sign, must<sub_rhs<B>>> {};
template <bool B>
struct additive
    : seq<multiplicative<B>, star<next_is<'+', '-'>, sor<add_tail<B>, sub_tail<B>>>> {};

// ---------------------------------------------------------------------------------------
// Range: a .. b, a ..= b, optional `step s`
// ---------------------------------------------------------------------------------------
struct range_op : token<sor<string<'.', '.', '='>, string<'.', '.'>>> {};
struct step_keyword : seq<kw_step, not_at<equals>> {};
template <bool B> struct range_end : additive<B> {};
template <bool B> struct step_value : additive<B> {};
template <bool B> struct range_step : seq<step_keyword, must<step_value<B>>> {};
template <bool B> struct range_tail : seq<range_op, must<range_end<B>>, opt<range_step<B>>> {};
template <bool B> struct range_expr : seq<additive<B>, opt<next_is<'.'>, range_tail<B>>> {};

// ---------------------------------------------------------------------------------------
// Comparison (non-associative: a < b < c is an error)
// ---------------------------------------------------------------------------------------
struct eq_op : token<string<'=', '='>> {};
struct ne_op : token<string<'!', '='>> {};
struct le_op : token<string<'<', '='>> {};
struct ge_op : token<string<'>', '='>> {};
struct lt_op : token<one<'<'>> {};
struct gt_op : token<one<'>'>> {};
struct comparison_op : sor<eq_op, ne_op, le_op, ge_op, lt_op, gt_op> {};
template <bool B> struct eq_rhs : range_expr<B> {};
template <bool B> struct ne_rhs : range_expr<B> {};
template <bool B> struct le_rhs : range_expr<B> {};
template <bool B> struct ge_rhs : range_expr<B> {};
template <bool B> struct lt_rhs : range_expr<B> {};
template <bool B> struct gt_rhs : range_expr<B> {};
template <bool B> struct eq_tail : seq<eq_op, must<eq_rhs<B>>> {};
template <bool B> struct ne_tail : seq<ne_op, must<ne_rhs<B>>> {};
template <bool B> struct le_tail : seq<le_op, must<le_rhs<B>>> {};
template <bool B> struct ge_tail : seq<ge_op, must<ge_rhs<B>>> {};
template <bool B> struct lt_tail : seq<lt_op, must<lt_rhs<B>>> {};
template <bool B> struct gt_tail : seq<gt_op, must<gt_rhs<B>>> {};
template <bool B>
struct comparison_tail
    : sor<eq_tail<B>, ne_tail<B>, le_tail<B>, ge_tail<B>, lt_tail<B>, gt_tail<B>> {};
struct no_chained_comparison : not_at<comparison_op> {};
template <bool B>
struct comparison
    : seq<range_expr<B>,
          opt<next_is<'=', '!', '<', '>'>, comparison_tail<B>, must<no_chained_comparison>>> {};

// ---------------------------------------------------------------------------------------
// not (prefix, looser than comparison), and, or
// ---------------------------------------------------------------------------------------
template <bool B> struct not_expr;
template <bool B> struct not_operand : not_expr<B> {};
template <bool B> struct logical_not : seq<kw_not, must<not_operand<B>>> {};
template <bool B> struct not_expr : sor<logical_not<B>, comparison<B>> {};

template <bool B> struct and_rhs : not_expr<B> {};
template <bool B> struct and_tail : seq<kw_and, must<and_rhs<B>>> {};
template <bool B> struct and_expr : seq<not_expr<B>, star<and_tail<B>>> {};

template <bool B> struct or_rhs : and_expr<B> {};
template <bool B> struct or_tail : seq<kw_or, must<or_rhs<B>>> {};
template <bool B> struct or_expr : seq<and_expr<B>, star<or_tail<B>>> {};

// ---------------------------------------------------------------------------------------
// Transform postfix, the loosest level: e translate e2 rotate e3 (left-associative). The
// keyword followed by `=` is a property named like it (`checker { scale = 2 }`), so it
// ends the expression instead.
// ---------------------------------------------------------------------------------------
template <typename Keyword> struct transform_keyword : seq<Keyword, not_at<equals>> {};
template <bool B> struct translate_arg : or_expr<B> {};
template <bool B> struct rotate_arg : or_expr<B> {};
template <bool B> struct scale_arg : or_expr<B> {};
template <bool B> struct matrix_arg : or_expr<B> {};
template <bool B> struct translate_tail : seq<transform_keyword<kw_translate>, must<translate_arg<B>>> {};
template <bool B> struct rotate_tail : seq<transform_keyword<kw_rotate>, must<rotate_arg<B>>> {};
template <bool B> struct scale_tail : seq<transform_keyword<kw_scale>, must<scale_arg<B>>> {};
template <bool B> struct matrix_tail : seq<transform_keyword<kw_matrix>, must<matrix_arg<B>>> {};
template <bool B>
struct transform_tail : sor<translate_tail<B>, rotate_tail<B>, scale_tail<B>, matrix_tail<B>> {};
template <bool B>
struct expression : seq<or_expr<B>, star<next_is<'t', 'r', 's', 'm'>, transform_tail<B>>> {};

}  // namespace rts::grammar
