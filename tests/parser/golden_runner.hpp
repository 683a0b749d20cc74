// Support for golden-file tests: listing inputs, reading/writing files, and a line diff to
// show what changed when an output no longer matches its golden file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rts::testing {

// The files in `dir` whose name ends with `extension`, sorted by name.
std::vector<std::filesystem::path> files_with_extension(const std::filesystem::path& dir,
                                                        const std::string& extension);

std::string read_file(const std::filesystem::path& path);
void write_file(const std::filesystem::path& path, const std::string& text);

// A unified-style diff ("-" expected, "+" actual, " " common) of two texts, with a few
// lines of context around each change; "" when they are equal.
std::string line_diff(const std::string& expected, const std::string& actual);

// True when RTS_UPDATE_GOLDEN=1: golden tests rewrite their expectation files instead of
// comparing (scripts/update-golden-parse sets it).
bool updating_golden();

}  // namespace rts::testing
