// Statement rules, block bodies and the whole program.
//
// Inside a block body (`sphere { ... }`, `x with { ... }`), `name = expr` is a PROPERTY;
// everywhere else (top level, if/for/while/macro bodies, even nested inside a block) it is
// an ASSIGNMENT to an existing binding. `name += expr` and friends are always assignments.
#pragma once

#include "grammar/expressions.hpp"

namespace rts::grammar {

struct statement;

// ---------------------------------------------------------------------------------------
// POV-Ray's '#' directives, where a statement or '}' was expected: a message naming the rts
// statement instead of "expected a statement".
// ---------------------------------------------------------------------------------------
struct pov_declare_word : sor<string<'d', 'e', 'c', 'l', 'a', 'r', 'e'>, string<'l', 'o', 'c', 'a', 'l'>> {};
struct no_pov_declare : not_at<one<'#'>, pov_declare_word> {};
struct no_pov_directive : not_at<one<'#'>> {};
struct no_directive : seq<must<no_pov_declare>, must<no_pov_directive>> {};

// POV-Ray's block words that are not rts's, where a statement starts: `light_source { ... }`
// stops at the word with the rts spelling (the body, `<0, 10, -10> color White`, would not
// parse as rts anyway, and `word {` is never valid rts for these words).
struct pov_light_source : reserved<'l', 'i', 'g', 'h', 't', '_', 's', 'o', 'u', 'r', 'c', 'e'> {};
struct pov_pigment : sor<reserved<'p', 'i', 'g', 'm', 'e', 'n', 't'>, reserved<'f', 'i', 'n', 'i', 's', 'h'>,
                         reserved<'t', 'e', 'x', 't', 'u', 'r', 'e'>> {};
struct pov_global_settings
    : reserved<'g', 'l', 'o', 'b', 'a', 'l', '_', 's', 'e', 't', 't', 'i', 'n', 'g', 's'> {};
struct pov_background : reserved<'b', 'a', 'c', 'k', 'g', 'r', 'o', 'u', 'n', 'd'> {};
template <typename Word>
struct no_pov_block : not_at<Word, skip, one<'{'>> {};
struct no_pov_blocks
    : seq<must<no_pov_block<pov_light_source>>, must<no_pov_block<pov_pigment>>,
          must<no_pov_block<pov_global_settings>>, must<no_pov_block<pov_background>>> {};

// ---------------------------------------------------------------------------------------
// Block bodies: properties and statements in source order
// ---------------------------------------------------------------------------------------
struct block_open : token<one<'{'>> {};
struct block_close : token<one<'}'>> {};
struct property_head : seq<field_name, equals> {};
struct property_value : seq<expression<true>> {};
struct property : seq<property_head, must<property_value>> {};
struct block_statement : seq<statement> {};
struct block_item : sor<semicolon, property, block_statement> {};
struct block_inner : seq<star<block_item>, no_directive, must<block_close>> {};
struct block_body : seq<block_open, block_inner> {};

// ---------------------------------------------------------------------------------------
// Statement bodies (if / else / for / while / macro)
// ---------------------------------------------------------------------------------------
struct body_open : token<one<'{'>> {};
struct body_close : token<one<'}'>> {};
struct body_inner : seq<star<sor<semicolon, statement>>, no_directive, must<body_close>> {};
struct body : seq<body_open, body_inner> {};
struct if_body : body {};
struct else_body : body {};
struct for_body : body {};
struct while_body : body {};
struct macro_body : body {};

// ---------------------------------------------------------------------------------------
// Statements
// ---------------------------------------------------------------------------------------
struct let_name : identifier {};
struct let_equals : equals {};
struct let_value : expression<true> {};
struct let_stmt : seq<kw_let, must<let_name>, must<let_equals>, must<let_value>> {};

struct assign_set : equals {};
struct assign_add : token<string<'+', '='>> {};
struct assign_sub : token<string<'-', '='>> {};
struct assign_mul : token<string<'*', '='>> {};
struct assign_div : token<string<'/', '='>> {};
struct assign_op : sor<assign_set, assign_add, assign_sub, assign_mul, assign_div> {};
struct assign_head : seq<identifier, assign_op> {};
struct assign_value : expression<true> {};
struct assign_stmt : seq<assign_head, must<assign_value>> {};

// `else if` chains: the nested `if` is its own rule so that the parser can tell it apart
// from a statement-level `if`.
struct if_condition : expression<false> {};
// `if a = 2`: a single '=' after a condition is a comparison meant as '=='.
struct no_assign_in_condition : not_at<equals> {};
struct else_clause;
struct if_stmt
    : seq<kw_if, must<if_condition>, must<no_assign_in_condition>, must<if_body>, opt<else_clause>> {};
struct else_if
    : seq<kw_if, must<if_condition>, must<no_assign_in_condition>, must<if_body>, opt<else_clause>> {};
struct else_target : sor<else_if, else_body> {};
struct else_clause : seq<kw_else, must<else_target>> {};

struct for_variable : identifier {};
struct for_in : kw_in {};
struct for_iterable : expression<false> {};
struct for_stmt
    : seq<kw_for, must<for_variable>, must<for_in>, must<for_iterable>, must<for_body>> {};

struct while_condition : expression<false> {};
struct while_stmt : seq<kw_while, must<while_condition>, must<no_assign_in_condition>, must<while_body>> {};

struct macro_name : identifier {};
struct params_open : token<one<'('>> {};
struct params_close : token<one<')'>> {};
struct param_name : identifier {};
struct param_default_value : expression<true> {};
struct param_default : seq<equals, must<param_default_value>> {};
struct param : seq<param_name, opt<param_default>> {};
struct params_inner : seq<opt<param, star<comma, param>, opt<comma>>, must<params_close>> {};
struct macro_stmt
    : seq<kw_macro, must<macro_name>, must<params_open>, params_inner, must<macro_body>> {};

struct return_value : expression<true> {};
struct return_stmt : seq<kw_return, opt<return_value>> {};
struct break_stmt : kw_break {};
struct continue_stmt : kw_continue {};

struct include_path : string_literal {};
struct include_stmt : seq<kw_include, must<include_path>> {};

struct expr_stmt : expression<true> {};

struct statement
    : seq<no_pov_blocks, sor<let_stmt, if_stmt, for_stmt, while_stmt, macro_stmt, return_stmt, break_stmt,
                             continue_stmt, include_stmt, assign_stmt, expr_stmt>> {};

// ---------------------------------------------------------------------------------------
// The program: statements (optionally separated by `;`) up to the end of the input.
// ---------------------------------------------------------------------------------------
struct end_of_input : eof {};
struct program : seq<skip, star<sor<semicolon, statement>>, no_directive, must<end_of_input>> {};

}  // namespace rts::grammar
