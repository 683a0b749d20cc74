// Runs the bare grammar (no actions) over a string, with the must_if<> control that turns
// a failed must<> into its message from grammar/errors.hpp.
#pragma once

#include <optional>
#include <string>

#include <tao/pegtl.hpp>

#include "grammar/grammar.hpp"

namespace rts::grammar::testing {

struct GrammarResult {
  bool accepted = false;
  std::string message;  // the error message when rejected
  std::size_t line = 0, column = 0;
};

// must_if<> with one change, the same as the rts parser's control: a rule that has a
// message rewinds when it fails, so the error points where the rule was expected rather
// than wherever its partial match stopped.
template <typename Rule>
struct must_if_control : tao::pegtl::must_if<errors>::control<Rule> {
  template <tao::pegtl::apply_mode A, tao::pegtl::rewind_mode M, template <typename...> class Action,
            template <typename...> class Control, typename ParseInput, typename... States>
  [[nodiscard]] static bool match(ParseInput& in, States&&... st) {
    constexpr auto mode = error_message<Rule> != nullptr ? tao::pegtl::rewind_mode::required : M;
    return tao::pegtl::must_if<errors>::control<Rule>::template match<A, mode, Action, Control>(in, st...);
  }
};

template <typename Rule = program>
GrammarResult run_grammar(const std::string& text) {
  tao::pegtl::memory_input in(text, "test");
  GrammarResult r;
  try {
    r.accepted = tao::pegtl::parse<Rule, tao::pegtl::nothing, must_if_control>(in);
  } catch (const tao::pegtl::parse_error& e) {
    r.message = std::string(e.message());
    r.line = e.positions().front().line;
    r.column = e.positions().front().column;
  }
  return r;
}

}  // namespace rts::grammar::testing
