// `rts check`'s lint: warnings about what a scene declares and never uses. Internal to runtime/.
#pragma once

#include <span>

#include "parser/diagnostics.hpp"
#include "parser/source.hpp"
#include "runtime/binding.hpp"

namespace rts::runtime {

// Warns about each material, texture, object and macro among `globals` (the top-level
// bindings once the scene has run) declared in `main` and never named again; a declared
// file that does not exist is named too.
void warn_unused(std::span<const Binding> globals, const SourceFile& main, DiagnosticSink& warnings);

}  // namespace rts::runtime
