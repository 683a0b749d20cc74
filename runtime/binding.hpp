// One name bound to a value in the interpreter's flat stack of bindings (runtime/interpreter.hpp).
#pragma once

#include "parser/ast.hpp"
#include "parser/source.hpp"
#include "runtime/value.hpp"

namespace rts::runtime {

struct Binding {
  ast::Symbol name;
  Value value;
  SourceLoc loc;  // where it was declared, for "already defined" notes
  bool used = false;  // looked up at least once (for the unused-declaration warnings)
};

}  // namespace rts::runtime
