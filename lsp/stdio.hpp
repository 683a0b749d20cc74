// `rts lsp`: the server on standard input and output until `exit` or end of input.
#pragma once

#include "lsp/server.hpp"

namespace rts::lsp {

// Returns the process exit code (0 after shutdown + exit; 1 when the input ends or `exit`
// comes without `shutdown`).
int run_stdio(ServerOptions options);

}  // namespace rts::lsp
