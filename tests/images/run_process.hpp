// Runs a program (no shell) with its stdout and stderr sent to a log file.
#pragma once

#include <string>
#include <vector>

namespace rts::images {

// Returns the exit status, 128 + signal when killed by a signal, or -1 when it cannot start.
int run_process(const std::vector<std::string>& argv, const std::string& log_path);

}  // namespace rts::images
