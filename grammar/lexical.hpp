// Lexical rules of the rts language: whitespace and comments, identifiers and reserved
// words, numbers, strings, punctuation. PEGTL rules only; no actions live in grammar/.
//
// Convention: every token rule consumes the whitespace and comments that FOLLOW it (the
// `skip` at its end), and `program` skips leading whitespace once. So every rule starts on
// the first character of a real token, which is what locations and error carets point at.
#pragma once

#include <string_view>

#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/analyze_traits.hpp>

namespace rts::grammar {

namespace pegtl = tao::pegtl;
using pegtl::any;
using pegtl::at;
using pegtl::digit;
using pegtl::eof;
using pegtl::eolf;
using pegtl::must;
using pegtl::not_at;
using pegtl::not_one;
using pegtl::one;
using pegtl::opt;
using pegtl::plus;
using pegtl::ranges;
using pegtl::rep_min_max;
using pegtl::seq;
using pegtl::sor;
using pegtl::star;
using pegtl::string;
using pegtl::until;
using pegtl::xdigit;

// ---------------------------------------------------------------------------------------
// Hand-written rules. These run at every token, so they are custom PEGTL rules (a
// struct with match()) rather than combinators: one pass over the bytes, no memcmp calls.
// ---------------------------------------------------------------------------------------
inline constexpr bool is_ident_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}
inline constexpr bool is_ident_first(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

// The reserved words of the language (docs/language.md lists the same; a test checks).
inline bool is_reserved_word(std::string_view w) {
  auto is = [w](std::string_view k) { return w == k; };
  switch (w.empty() ? '\0' : w[0]) {
    case 'a': return is("and");
    case 'b': return is("break");
    case 'c': return is("continue");
    case 'e': return is("else");
    case 'f': return is("for") || is("false");
    case 'i': return is("if") || is("in") || is("include");
    case 'l': return is("let");
    case 'm': return is("macro") || is("matrix");
    case 'n': return is("none") || is("not");
    case 'o': return is("or");
    case 'r': return is("return") || is("rotate");
    case 's': return is("scale") || is("step");
    case 't': return is("true") || is("translate");
    case 'w': return is("while") || is("with");
    default: return false;
  }
}

inline constexpr bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

// Zero or more whitespace characters (space, tab, CR, LF, FF, VT).
struct blanks {
  using rule_t = blanks;
  using subs_t = pegtl::empty_list;
  template <typename ParseInput>
  [[nodiscard]] static bool match(ParseInput& in) {
    while (!in.empty()) {
      char c = in.peek_char();
      if (c == '\n') in.bump_to_next_line(1);
      else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') in.bump_in_this_line(1);
      else break;
    }
    return true;
  }
};

// An identifier-shaped word that is not reserved: [A-Za-z_][A-Za-z0-9_]*
struct name_word {
  using rule_t = name_word;
  using subs_t = pegtl::empty_list;
  template <typename ParseInput>
  [[nodiscard]] static bool match(ParseInput& in) {
    const char* begin = in.current();
    const char* end = in.end();
    if (begin == end || !is_ident_first(*begin)) return false;
    const char* p = begin + 1;
    while (p != end && is_ident_char(*p)) ++p;
    std::size_t n = static_cast<std::size_t>(p - begin);
    if (is_reserved_word(std::string_view(begin, n))) return false;
    in.bump_in_this_line(n);
    return true;
  }
};

// The reserved word spelled Cs, not followed by an identifier character (`letter` is a name).
template <char... Cs>
struct reserved {
  using rule_t = reserved;
  using subs_t = pegtl::empty_list;
  template <typename ParseInput>
  [[nodiscard]] static bool match(ParseInput& in) {
    constexpr std::size_t n = sizeof...(Cs);
    const char* p = in.current();
    std::size_t available = static_cast<std::size_t>(in.end() - p);
    if (available < n) return false;
    std::size_t i = 0;
    if (!((p[i++] == Cs) && ...)) return false;
    if (available > n && is_ident_char(p[n])) return false;
    in.bump_in_this_line(n);
    return true;
  }
};

// Succeeds without consuming when the next character is one of Cs: a cheap gate in front
// of a group of alternatives that all start with one of those characters.
template <char... Cs>
struct next_is {
  using rule_t = next_is;
  using subs_t = pegtl::empty_list;
  template <typename ParseInput>
  [[nodiscard]] static bool match(ParseInput& in) {
    if (in.empty()) return false;
    char c = in.peek_char();
    return ((c == Cs) || ...);
  }
};

// ---------------------------------------------------------------------------------------
// Whitespace and comments
// ---------------------------------------------------------------------------------------
struct line_comment : seq<one<'/'>, until<eolf>> {};  // after the first '/'
struct block_comment_rest : until<string<'*', '/'>> {};  // not nested: the first */ closes
struct block_comment : seq<one<'*'>, must<block_comment_rest>> {};  // after the '/'
struct comment : seq<one<'/'>, sor<line_comment, block_comment>> {};
struct comments : star<comment, blanks> {};

// skip <- blanks comments. Runs after every token, so the blanks are consumed here directly
// and the comment rules are only entered when a '/' follows.
struct skip {
  using rule_t = skip;
  using subs_t = pegtl::type_list<blanks, comments>;
  template <pegtl::apply_mode A, pegtl::rewind_mode M, template <typename...> class Action,
            template <typename...> class Control, typename ParseInput, typename... States>
  [[nodiscard]] static bool match(ParseInput& in, States&&... st) {
    (void)blanks::match(in);
    if (in.empty() || in.peek_char() != '/') return true;
    return Control<comments>::template match<A, M, Action, Control>(in, st...);
  }
};

// ---------------------------------------------------------------------------------------
// Identifiers and reserved words
// ---------------------------------------------------------------------------------------
struct kw_let : seq<reserved<'l', 'e', 't'>, skip> {};
struct kw_if : seq<reserved<'i', 'f'>, skip> {};
struct kw_else : seq<reserved<'e', 'l', 's', 'e'>, skip> {};
struct kw_for : seq<reserved<'f', 'o', 'r'>, skip> {};
struct kw_in : seq<reserved<'i', 'n'>, skip> {};
struct kw_while : seq<reserved<'w', 'h', 'i', 'l', 'e'>, skip> {};
struct kw_macro : seq<reserved<'m', 'a', 'c', 'r', 'o'>, skip> {};
struct kw_return : seq<reserved<'r', 'e', 't', 'u', 'r', 'n'>, skip> {};
struct kw_break : seq<reserved<'b', 'r', 'e', 'a', 'k'>, skip> {};
struct kw_continue : seq<reserved<'c', 'o', 'n', 't', 'i', 'n', 'u', 'e'>, skip> {};
struct kw_include : seq<reserved<'i', 'n', 'c', 'l', 'u', 'd', 'e'>, skip> {};
struct kw_true : seq<reserved<'t', 'r', 'u', 'e'>, skip> {};
struct kw_false : seq<reserved<'f', 'a', 'l', 's', 'e'>, skip> {};
struct kw_none : seq<reserved<'n', 'o', 'n', 'e'>, skip> {};
struct kw_and : seq<reserved<'a', 'n', 'd'>, skip> {};
struct kw_or : seq<reserved<'o', 'r'>, skip> {};
struct kw_not : seq<reserved<'n', 'o', 't'>, skip> {};
struct kw_with : seq<reserved<'w', 'i', 't', 'h'>, skip> {};
struct kw_translate : seq<reserved<'t', 'r', 'a', 'n', 's', 'l', 'a', 't', 'e'>, skip> {};
struct kw_rotate : seq<reserved<'r', 'o', 't', 'a', 't', 'e'>, skip> {};
struct kw_scale : seq<reserved<'s', 'c', 'a', 'l', 'e'>, skip> {};
struct kw_matrix : seq<reserved<'m', 'a', 't', 'r', 'i', 'x'>, skip> {};
struct kw_step : seq<reserved<'s', 't', 'e', 'p'>, skip> {};

// A name: a word that is not reserved.
struct identifier : seq<name_word, skip> {};
struct ident_other : ranges<'a', 'z', 'A', 'Z', '0', '9', '_'> {};

// Words that are reserved in expressions but still usable as property, named-argument and
// member names (`checker { scale = 2 }`, `f(step = 1)`, `t.scale`): the operator keywords.
struct soft_keyword : sor<kw_translate, kw_rotate, kw_scale, kw_matrix, kw_step> {};
struct field_name : sor<identifier, soft_keyword> {};

// ---------------------------------------------------------------------------------------
// Numbers: 12  1.5  .5  1e-3  2.5E+4. A fraction needs a digit after the dot, so `0..20`
// is `0 .. 20`. A letter glued to a number (`3x`, `1e`) is an error, not two tokens.
// ---------------------------------------------------------------------------------------
// number_chars is hand-written for speed; in PEG notation it is
//   digits ('.' digits)? exponent? / '.' digits exponent?   with exponent <- [eE] [+-]? digits
struct number_chars {
  using rule_t = number_chars;
  using subs_t = pegtl::empty_list;
  template <typename ParseInput>
  [[nodiscard]] static bool match(ParseInput& in) {
    const char* p = in.current();
    const char* end = in.end();
    auto digit_at = [end](const char* q) { return q != end && *q >= '0' && *q <= '9'; };
    auto skip_digits = [&](const char* q) { while (digit_at(q)) ++q; return q; };
    const char* q = skip_digits(p);
    bool int_part = q != p;
    if (q != end && *q == '.' && digit_at(q + 1)) q = skip_digits(q + 1);
    else if (!int_part) return false;
    if (q != end && (*q == 'e' || *q == 'E')) {
      const char* e = q + 1;
      if (e != end && (*e == '+' || *e == '-')) ++e;
      if (digit_at(e)) q = skip_digits(e);
    }
    in.bump_in_this_line(static_cast<std::size_t>(q - p));
    return true;
  }
};
struct number_end : not_at<ident_other> {};
struct number : seq<number_chars, must<number_end>> {};
struct number_literal : seq<number, skip> {};

// ---------------------------------------------------------------------------------------
// Strings: "..." with escapes \n \t \r \\ \" \0 \u{1F600}; no raw newline inside.
// ---------------------------------------------------------------------------------------
struct string_open : one<'"'> {};
struct string_close : one<'"'> {};
struct unicode_open : one<'{'> {};
struct unicode_digits : rep_min_max<1, 6, xdigit> {};
struct unicode_close : one<'}'> {};
struct unicode_escape : seq<one<'u'>, must<unicode_open>, must<unicode_digits>, must<unicode_close>> {};
struct escape_code : sor<one<'n', 't', 'r', '\\', '"', '0'>, unicode_escape> {};
struct escape : seq<one<'\\'>, must<escape_code>> {};
struct plain_char : not_one<'"', '\\', '\n', '\r'> {};
struct string_body : star<sor<plain_char, escape>> {};
struct string_literal : seq<string_open, string_body, must<string_close>, skip> {};

// ---------------------------------------------------------------------------------------
// Punctuation. Each consumes the skip after it.
// ---------------------------------------------------------------------------------------
template <typename Rule>
struct token : seq<Rule, skip> {};

struct comma : token<one<','>> {};
struct semicolon : token<one<';'>> {};
// `=` but not `==`
struct equals : token<seq<one<'='>, not_at<one<'='>>>> {};

}  // namespace rts::grammar

// What PEGTL's grammar analysis needs to know about the hand-written rules: `blanks` may
// succeed without consuming; the others consume whenever they succeed.
namespace tao::pegtl {
template <typename Name>
struct analyze_traits<Name, rts::grammar::blanks> : analyze_opt_traits<> {};
template <typename Name>
struct analyze_traits<Name, rts::grammar::name_word> : analyze_any_traits<> {};
template <typename Name, char... Cs>
struct analyze_traits<Name, rts::grammar::reserved<Cs...>> : analyze_any_traits<> {};
template <typename Name>
struct analyze_traits<Name, rts::grammar::number_chars> : analyze_any_traits<> {};
template <typename Name, char... Cs>
struct analyze_traits<Name, rts::grammar::next_is<Cs...>> : analyze_opt_traits<> {};
template <typename Name>
struct analyze_traits<Name, rts::grammar::skip> : analyze_opt_traits<rts::grammar::comments> {};
}  // namespace tao::pegtl
