// The parser's PEGTL control: how a failed must<> becomes a LanguageError, and where the
// nesting limit is enforced. Messages come from grammar/errors.hpp (the must_if<> table).
#pragma once

#include <string>

#include <fmt/format.h>
#include <tao/pegtl.hpp>

#include "grammar/grammar.hpp"
#include "parser/comma_hint.hpp"
#include "parser/parse_state.hpp"

namespace rts::parse_detail {

namespace pegtl = tao::pegtl;
namespace g = rts::grammar;

// Rules entered once per level of nesting: the inside of a bracket or body (after its
// opener), and the operand of a prefix or right-associative operator. Counting them bounds
// the parser's recursion whatever the input.
template <typename Rule> inline constexpr bool counts_nesting = false;
template <> inline constexpr bool counts_nesting<g::paren_inner> = true;
template <> inline constexpr bool counts_nesting<g::list_inner> = true;
template <> inline constexpr bool counts_nesting<g::vector_inner> = true;
template <> inline constexpr bool counts_nesting<g::call_inner> = true;
template <> inline constexpr bool counts_nesting<g::index_inner> = true;
template <> inline constexpr bool counts_nesting<g::block_inner> = true;
template <> inline constexpr bool counts_nesting<g::body_inner> = true;
template <bool B> inline constexpr bool counts_nesting<g::neg_operand<B>> = true;
template <bool B> inline constexpr bool counts_nesting<g::pos_operand<B>> = true;
template <bool B> inline constexpr bool counts_nesting<g::not_operand<B>> = true;
template <bool B> inline constexpr bool counts_nesting<g::pow_rhs<B>> = true;

// Rules whose failure means an opened bracket was never closed: the error gets a note
// pointing at the opener.
template <typename Rule> inline constexpr bool closes_bracket = false;
template <> inline constexpr bool closes_bracket<g::paren_close> = true;
template <> inline constexpr bool closes_bracket<g::list_close> = true;
template <> inline constexpr bool closes_bracket<g::vector_close> = true;
template <> inline constexpr bool closes_bracket<g::call_close> = true;
template <> inline constexpr bool closes_bracket<g::index_close> = true;
template <> inline constexpr bool closes_bracket<g::block_close> = true;
template <> inline constexpr bool closes_bracket<g::body_close> = true;
template <> inline constexpr bool closes_bracket<g::params_close> = true;
template <> inline constexpr bool closes_bracket<g::string_close> = true;

// Describes the character where the parse stopped, for "found ..." in messages.
std::string describe_found(const char* current, const char* end);

[[noreturn]] void throw_nesting_too_deep(SourceLoc loc, unsigned limit);

// An error found at the end of the input points just after the last token instead (on the
// line the user was writing, not on an empty line after it).
SourceLoc after_last_token(const SourceFile& file);

template <typename Rule>
struct control : pegtl::normal<Rule> {
  static constexpr bool has_message = g::error_message<Rule> != nullptr;

  // Rules with a message are matched with rewinding so that, on failure, the input is back
  // where the rule was expected: that is where the error points.
  template <pegtl::apply_mode A, pegtl::rewind_mode M, template <typename...> class Action,
            template <typename...> class Control, typename ParseInput>
  [[nodiscard]] static bool match(ParseInput& in, ParseState& st) {
    constexpr pegtl::rewind_mode mode = has_message ? pegtl::rewind_mode::required : M;
    if constexpr (counts_nesting<Rule>) {
      if (st.depth >= st.limits.max_nesting)
        throw_nesting_too_deep(st.loc(in.current()), st.limits.max_nesting);
      ++st.depth;
      struct Leave {
        ParseState& s;
        ~Leave() { --s.depth; }
      } leave{st};
      return pegtl::normal<Rule>::template match<A, mode, Action, Control>(in, st);
    } else {
      return pegtl::normal<Rule>::template match<A, mode, Action, Control>(in, st);
    }
  }

  template <typename ParseInput>
  [[noreturn]] static void raise(const ParseInput& in, ParseState& st) {
    static_assert(has_message, "every rule under must<> needs a message in grammar/errors.hpp");
    SourceLoc at = in.empty() ? after_last_token(*st.file) : st.loc(in.current());
    std::string message = g::error_message<Rule>;
    if constexpr (std::is_same_v<Rule, g::block_comment_rest>) {
      at = at.advanced(-2);  // point at the `/*` that was never closed, not just after it
    }
    if constexpr (std::is_same_v<Rule, g::end_of_input>) {
      message += ", found " + describe_found(in.current(), in.end());
    }
    if constexpr (std::is_same_v<Rule, g::block_close>) {
      // POV-Ray's positional arguments or commas between properties (parser/comma_hint.hpp).
      if (!in.empty() && in.peek_char() == ',' && !st.opens.empty()) {
        Diagnostic d = comma_in_block_error(
            *st.file, st.opens.back().loc, static_cast<std::size_t>(in.current() - st.file->text().data()));
        d.loc = at;
        throw LanguageError(std::move(d));
      }
    }
    Diagnostic d{Severity::Error, at, std::move(message), {}};
    if constexpr (closes_bracket<Rule>) {
      if (!st.opens.empty()) {
        const Open& o = st.opens.back();
        d.notes.push_back(Note{o.loc, fmt::format("to match this '{}'", o.ch)});
      }
    }
    throw LanguageError(std::move(d));
  }
};

}  // namespace rts::parse_detail
