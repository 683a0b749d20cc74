// Whole-number and memory-size options. Anything but a whole number inside the option's range
// (a sign, a fraction, a number past the range, text) is a usage error (exit 2) that states
// the range in words: "--max-iterations must be a whole number from 1 to 1,000,000,000,000,
// got '-1'". CLI11's own conversion wraps "-1" into 2^64-1 for unsigned targets, which made
// the limits "unlimited" by accident.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace rts::cli {

// "1,000,000": numbers in messages and help.
std::string with_commas(uint64_t n);

// Registers option `names` taking a whole number in [lo, hi], passed to `set` when given.
CLI::Option* add_whole_option(CLI::App& cmd, const std::string& names, uint64_t lo, uint64_t hi,
                              std::function<void(uint64_t)> set, const std::string& help);

template <typename T>
CLI::Option* add_whole_option(CLI::App& cmd, const std::string& names, T& target, uint64_t lo, uint64_t hi,
                              const std::string& help, bool show_default = true) {
  CLI::Option* o = add_whole_option(
      cmd, names, lo, hi, [&target](uint64_t v) { target = static_cast<T>(v); }, help);
  if (show_default) o->default_str(with_commas(static_cast<uint64_t>(target)));
  return o;
}

// A memory size: bytes, or a number with K, M, G or T (powers of 1024, "GiB" and "GB" read
// the same), at least `lo` bytes.
CLI::Option* add_size_option(CLI::App& cmd, const std::string& names, std::size_t& target, std::size_t lo,
                             const std::string& help);

}  // namespace rts::cli
