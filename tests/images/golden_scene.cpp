#include "tests/images/golden_scene.hpp"

#include <sstream>
#include <string_view>

namespace rts::images {

namespace {
constexpr std::string_view kArgsMarker = "// args:";
constexpr std::string_view kAovFlag = "--aov";

void split_commas(const std::string& list, std::vector<std::string>& out) {
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) out.push_back(item);
  }
}
}  // namespace

std::vector<std::string> scene_args(const std::string& scene_text) {
  std::vector<std::string> args;
  std::istringstream lines(scene_text);
  std::string line;
  while (std::getline(lines, line)) {
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, kArgsMarker.size(), kArgsMarker) != 0) {
      continue;
    }
    std::istringstream words(line.substr(start + kArgsMarker.size()));
    std::string word;
    while (words >> word) args.push_back(word);
  }
  return args;
}

std::vector<std::string> requested_aovs(const std::vector<std::string>& args) {
  std::vector<std::string> aovs;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == kAovFlag && i + 1 < args.size()) {
      split_commas(args[++i], aovs);
    } else if (a.size() > kAovFlag.size() && a.compare(0, kAovFlag.size(), kAovFlag) == 0 &&
               a[kAovFlag.size()] == '=') {
      split_commas(a.substr(kAovFlag.size() + 1), aovs);
    }
  }
  return aovs;
}

std::string aov_path(const std::string& output_png, const std::string& aov) {
  constexpr std::string_view kPng = ".png";
  std::string stem = output_png;
  if (stem.size() >= kPng.size() && stem.compare(stem.size() - kPng.size(), kPng.size(), kPng) == 0) {
    stem.resize(stem.size() - kPng.size());
  }
  return stem + "." + aov + ".png";
}

}  // namespace rts::images
