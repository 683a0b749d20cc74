#include "cli/number_flags.hpp"

#include <cctype>
#include <charconv>

#include <fmt/format.h>

#include "render/scene/resource_limits.hpp"

namespace rts::cli {

std::string with_commas(uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

namespace {

// Digits only, no sign or spaces; false on anything else or on overflow.
bool parse_whole(const std::string& text, uint64_t& out) {
  if (text.empty()) return false;
  for (char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  auto r = std::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

std::string option_name(const CLI::Option* o, const std::string& names) {
  if (o) return o->get_name();
  return names.substr(0, names.find(','));
}

}  // namespace

CLI::Option* add_whole_option(CLI::App& cmd, const std::string& names, uint64_t lo, uint64_t hi,
                              std::function<void(uint64_t)> set, const std::string& help) {
  auto opt = std::make_shared<CLI::Option*>(nullptr);
  CLI::Option* o = cmd.add_option_function<std::string>(
      names,
      [opt, names, lo, hi, set = std::move(set)](const std::string& text) {
        uint64_t v = 0;
        if (!parse_whole(text, v) || v < lo || v > hi)
          throw CLI::ValidationError(option_name(*opt, names),
                                     fmt::format("must be a whole number from {} to {}, got '{}'", with_commas(lo),
                                                 with_commas(hi), text));
        set(v);
      },
      fmt::format("{} ({} to {})", help, with_commas(lo), with_commas(hi)));
  *opt = o;
  o->type_name("N");
  return o;
}

CLI::Option* add_size_option(CLI::App& cmd, const std::string& names, std::size_t& target, std::size_t lo,
                             const std::string& help) {
  auto opt = std::make_shared<CLI::Option*>(nullptr);
  CLI::Option* o = cmd.add_option_function<std::string>(
      names,
      [opt, names, &target, lo](const std::string& text) {
        std::size_t digits = 0;
        while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
        uint64_t n = 0;
        std::string unit = text.substr(digits);
        for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        int shift = -1;
        if (unit.empty() || unit == "B") shift = 0;
        else if (unit == "K" || unit == "KB" || unit == "KIB") shift = 10;
        else if (unit == "M" || unit == "MB" || unit == "MIB") shift = 20;
        else if (unit == "G" || unit == "GB" || unit == "GIB") shift = 30;
        else if (unit == "T" || unit == "TB" || unit == "TIB") shift = 40;
        constexpr uint64_t kMax = uint64_t(1) << 60;
        if (shift < 0 || !parse_whole(text.substr(0, digits), n) || n > (kMax >> shift) || (n << shift) < lo)
          throw CLI::ValidationError(
              option_name(*opt, names),
              fmt::format("must be a size of at least {} such as 512M or 8G (K, M, G, T: powers of 1024), got '{}'",
                          render::size_in_words(lo), text));
        target = static_cast<std::size_t>(n << shift);
      },
      help);
  *opt = o;
  o->type_name("SIZE");
  return o;
}

}  // namespace rts::cli
