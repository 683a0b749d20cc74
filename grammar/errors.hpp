// Error messages, one per rule that appears under must<>: when such a rule fails to match,
// the parse stops with this message at the position where the rule was expected. This is
// PEGTL's must_if<> convention (see tao/pegtl/contrib/json_errors.hpp): `errors` plugs
// into tao::pegtl::must_if<grammar::errors>, and the rts parser's own control
// (parser/parse_control.hpp) reads the same table. Every rule used under must<> must have
// a message here; both controls check that at compile time.
#pragma once

#include "grammar/statements.hpp"

namespace rts::grammar {

template <typename Rule>
inline constexpr const char* error_message = nullptr;

// Lexical
template <> inline constexpr auto error_message<block_comment_rest> = "unterminated block comment (missing '*/')";
template <> inline constexpr auto error_message<number_end> = "unexpected letter right after a number";
template <> inline constexpr auto error_message<unicode_open> = "expected '{' after '\\u' in a string";
template <> inline constexpr auto error_message<unicode_digits> = "expected 1 to 6 hexadecimal digits in '\\u{...}'";
template <> inline constexpr auto error_message<unicode_close> = "expected '}' to close '\\u{...}'";
template <> inline constexpr auto error_message<escape_code> = "unknown escape sequence in a string (use \\n \\t \\r \\\\ \\\" \\0 or \\u{...})";
template <> inline constexpr auto error_message<string_close> = "expected '\"' to close the string (strings cannot span lines)";

// Primary and postfix
template <> inline constexpr auto error_message<paren_inner> = "expected an expression after '('";
template <> inline constexpr auto error_message<paren_close> = "expected ')' to close the parenthesis";
template <> inline constexpr auto error_message<list_close> = "expected ',' or ']' to close the list";
template <> inline constexpr auto error_message<vector_component> = "expected a vector component (an expression)";
template <> inline constexpr auto error_message<vector_comma> = "expected ',' after the first vector component (vectors have 2 to 4 components)";
template <> inline constexpr auto error_message<vector_close> = "expected '>' to close the vector (vectors have 2 to 4 components)";
template <> inline constexpr auto error_message<named_arg_value> = "expected an expression after '=' in the argument";
template <> inline constexpr auto error_message<call_close> = "expected ',' or ')' to close the argument list";
template <> inline constexpr auto error_message<index_inner> = "expected an index expression after '['";
template <> inline constexpr auto error_message<index_close> = "expected ']' to close the index";
template <> inline constexpr auto error_message<member_name> = "expected a member name after '.'";
template <> inline constexpr auto error_message<with_body> = "expected '{' after 'with'";

// Operators
template <bool B> inline constexpr auto error_message<pow_rhs<B>> = "expected an expression after '^'";
template <bool B> inline constexpr auto error_message<neg_operand<B>> = "expected an expression after '-'";
template <bool B> inline constexpr auto error_message<pos_operand<B>> = "expected an expression after '+'";
template <bool B> inline constexpr auto error_message<mul_rhs<B>> = "expected an expression after '*'";
template <bool B> inline constexpr auto error_message<div_rhs<B>> = "expected an expression after '/'";
template <bool B> inline constexpr auto error_message<mod_rhs<B>> = "expected an expression after '%'";
template <bool B> inline constexpr auto error_message<add_rhs<B>> = "expected an expression after '+'";
template <bool B> inline constexpr auto error_message<sub_rhs<B>> = "expected an expression after '-'";
template <bool B> inline constexpr auto error_message<range_end<B>> = "expected the end of the range after '..'";
template <bool B> inline constexpr auto error_message<step_value<B>> = "expected an expression after 'step'";
template <bool B> inline constexpr auto error_message<eq_rhs<B>> = "expected an expression after '=='";
template <bool B> inline constexpr auto error_message<ne_rhs<B>> = "expected an expression after '!='";
template <bool B> inline constexpr auto error_message<le_rhs<B>> = "expected an expression after '<='";
template <bool B> inline constexpr auto error_message<ge_rhs<B>> = "expected an expression after '>='";
template <bool B> inline constexpr auto error_message<lt_rhs<B>> = "expected an expression after '<'";
template <bool B> inline constexpr auto error_message<gt_rhs<B>> = "expected an expression after '>'";
template <> inline constexpr auto error_message<no_chained_comparison> = "comparisons cannot be chained; combine them with 'and'";
template <bool B> inline constexpr auto error_message<not_operand<B>> = "expected an expression after 'not'";
template <bool B> inline constexpr auto error_message<and_rhs<B>> = "expected an expression after 'and'";
template <bool B> inline constexpr auto error_message<or_rhs<B>> = "expected an expression after 'or'";
template <bool B> inline constexpr auto error_message<translate_arg<B>> = "expected an expression after 'translate'";
template <bool B> inline constexpr auto error_message<rotate_arg<B>> = "expected an expression after 'rotate'";
template <bool B> inline constexpr auto error_message<scale_arg<B>> = "expected an expression after 'scale'";
template <bool B> inline constexpr auto error_message<matrix_arg<B>> = "expected an expression after 'matrix'";

// Blocks and bodies
template <> inline constexpr auto error_message<property_value> = "expected an expression after '=' in the property";
template <> inline constexpr auto error_message<block_close> = "expected '}' to close the block";
template <> inline constexpr auto error_message<body_close> = "expected '}' to close the body";

// Statements
template <> inline constexpr auto error_message<no_pov_declare> = "rts has no '#' directives: POV-Ray's '#declare NAME = VALUE;' is 'let NAME = VALUE' (see docs/from-povray.md)";
template <> inline constexpr auto error_message<no_pov_directive> = "rts has no '#' directives: write 'include', 'if', 'for', 'while', 'macro' without '#' (see docs/from-povray.md)";
template <> inline constexpr auto error_message<no_pov_block<pov_light_source>> = "POV-Ray's 'light_source' is 'point_light { position = ... }' in rts (or 'spot_light', 'area_light'; see docs/from-povray.md)";
template <> inline constexpr auto error_message<no_pov_block<pov_pigment>> = "POV-Ray's 'texture', 'pigment' and 'finish' are one 'material { color = ... diffuse = ... }' in rts, given as a shape's 'material' (see docs/from-povray.md)";
template <> inline constexpr auto error_message<no_pov_block<pov_global_settings>> = "POV-Ray's 'global_settings' is 'settings { ... }' in rts (see docs/from-povray.md)";
template <> inline constexpr auto error_message<no_pov_block<pov_background>> = "POV-Ray's 'background' is 'settings { background = rgb(...) }' in rts (see docs/from-povray.md)";
template <> inline constexpr auto error_message<no_assign_in_condition> = "'=' assigns; to compare in a condition write '=='";
template <> inline constexpr auto error_message<let_name> = "expected a name after 'let'";
template <> inline constexpr auto error_message<let_equals> = "expected '=' after the name in 'let'";
template <> inline constexpr auto error_message<let_value> = "expected an expression after '=' in 'let'";
template <> inline constexpr auto error_message<assign_value> = "expected an expression after the assignment operator";
template <> inline constexpr auto error_message<if_condition> = "expected a condition after 'if'";
template <> inline constexpr auto error_message<if_body> = "expected '{' to start the body of 'if'";
template <> inline constexpr auto error_message<else_target> = "expected '{' or 'if' after 'else'";
template <> inline constexpr auto error_message<for_variable> = "expected a loop variable name after 'for'";
template <> inline constexpr auto error_message<for_in> = "expected 'in' after the loop variable";
template <> inline constexpr auto error_message<for_iterable> = "expected a range or list after 'in'";
template <> inline constexpr auto error_message<for_body> = "expected '{' to start the body of 'for'";
template <> inline constexpr auto error_message<while_condition> = "expected a condition after 'while'";
template <> inline constexpr auto error_message<while_body> = "expected '{' to start the body of 'while'";
template <> inline constexpr auto error_message<macro_name> = "expected a macro name after 'macro'";
template <> inline constexpr auto error_message<params_open> = "expected '(' after the macro name";
template <> inline constexpr auto error_message<params_close> = "expected ',' or ')' to close the parameter list";
template <> inline constexpr auto error_message<param_default_value> = "expected a default value after '='";
template <> inline constexpr auto error_message<macro_body> = "expected '{' to start the body of 'macro'";
template <> inline constexpr auto error_message<include_path> = "expected a file name string after 'include'";
template <> inline constexpr auto error_message<end_of_input> = "expected a statement";

// The must_if<> adapter.
struct errors {
  template <typename Rule>
  static constexpr auto message = error_message<Rule>;
};

}  // namespace rts::grammar
