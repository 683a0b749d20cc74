#include "golden_runner.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace rts::testing {
namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

constexpr std::size_t kContextLines = 2;
// Beyond this many lines on either side the LCS table would be too big: show the texts'
// first difference only.
constexpr std::size_t kMaxDiffLines = 4000;

}  // namespace

std::vector<std::filesystem::path> files_with_extension(const std::filesystem::path& dir,
                                                        const std::string& extension) {
  std::vector<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == extension) out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string line_diff(const std::string& expected, const std::string& actual) {
  if (expected == actual) return "";
  std::vector<std::string> a = split_lines(expected), b = split_lines(actual);
  if (a.size() > kMaxDiffLines || b.size() > kMaxDiffLines) {
    std::size_t i = 0;
    while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
    return "first difference at line " + std::to_string(i + 1) + ":\n-" + (i < a.size() ? a[i] : "<end>") +
           "\n+" + (i < b.size() ? b[i] : "<end>") + "\n";
  }
  // Longest common subsequence of lines, then walk it to emit -, + and context lines.
  std::vector<std::vector<uint32_t>> lcs(a.size() + 1, std::vector<uint32_t>(b.size() + 1, 0));
  for (std::size_t i = a.size(); i-- > 0;)
    for (std::size_t j = b.size(); j-- > 0;)
      lcs[i][j] = a[i] == b[j] ? lcs[i + 1][j + 1] + 1 : std::max(lcs[i + 1][j], lcs[i][j + 1]);
  struct Line {
    char tag;
    std::string text;
  };
  std::vector<Line> script;
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (i < a.size() && j < b.size() && a[i] == b[j]) {
      script.push_back({' ', a[i]});
      ++i, ++j;
    } else if (i < a.size() && (j == b.size() || lcs[i + 1][j] >= lcs[i][j + 1])) {
      script.push_back({'-', a[i++]});  // removals first, as diff -u shows them
    } else {
      script.push_back({'+', b[j++]});
    }
  }
  std::string out = "--- expected\n+++ actual\n";
  std::size_t last_printed = 0;
  bool printed_any = false;
  for (std::size_t k = 0; k < script.size(); ++k) {
    bool near_change = false;
    for (std::size_t d = k >= kContextLines ? k - kContextLines : 0; d <= k + kContextLines && d < script.size(); ++d)
      near_change = near_change || script[d].tag != ' ';
    if (!near_change) continue;
    if (printed_any && k > last_printed + 1) out += "@@\n";
    out += script[k].tag;
    out += script[k].text;
    out += '\n';
    last_printed = k;
    printed_any = true;
  }
  return out;
}

bool updating_golden() {
  const char* v = std::getenv("RTS_UPDATE_GOLDEN");
  return v != nullptr && std::string(v) == "1";
}

}  // namespace rts::testing
