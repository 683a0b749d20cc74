// The built-in functions' signatures and one-line meanings, for hover, completion and
// signature help. The runtime's table (runtime::builtin_table) says which builtins exist and
// their arity; tests/lsp/test_lsp_unit.cpp checks that this list names exactly those, with
// parameter counts inside their arity, so neither can drift from the other.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rts::lsp {

struct BuiltinDoc {
  std::string_view name;
  std::string_view signature;  // "atan2(y, x)"; optional parameters in [brackets]
  std::string_view meaning;
};

std::span<const BuiltinDoc> builtin_docs();
const BuiltinDoc* find_builtin_doc(std::string_view name);
// The parameters of a signature, "atan2(y, x)" → {"y", "x"}.
std::vector<std::string> signature_params(std::string_view signature);

// The language's reserved words (grammar/lexical.hpp), for completion.
std::span<const std::string_view> keywords();

}  // namespace rts::lsp
