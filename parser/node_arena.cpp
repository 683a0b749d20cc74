// NodeArena's range of address space, and the check behind a link (parser/ast.hpp).
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>

#include <algorithm>
#include <new>
#include <stdexcept>

#include <fmt/format.h>

#include "parser/ast.hpp"

namespace rts::ast {
namespace {

constexpr std::size_t kPage = 4096;
// The smallest range worth trying when the address space is limited (ulimit -v), and the
// first and largest steps of committing pages (committed pages cost nothing until touched,
// but count against a strict overcommit limit, so they follow the parse).
constexpr std::size_t kSmallestReserve = std::size_t{1} << 20;
constexpr std::size_t kFirstCommit = std::size_t{64} << 10;
constexpr std::size_t kLargestCommit = std::size_t{16} << 20;

std::size_t round_to_pages(std::size_t n) { return (n + kPage - 1) & ~(kPage - 1); }

}  // namespace

// A reserved range counts against `ulimit -v` even untouched, so under one the arena's range is
// at most three quarters of what is left (the rest of the parse needs some), and the part the
// parse did not use goes back when it ends (NodeArena::release_unused).
std::size_t address_space_left() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return SIZE_MAX;
  std::size_t pages = 0;
  if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%zu", &pages) != 1) pages = 0;
    std::fclose(statm);
  }
  const std::size_t used = pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  return limit.rlim_cur > used ? static_cast<std::size_t>(limit.rlim_cur) - used : 0;
}

NodeArena::NodeArena(std::size_t text_size) {
  std::size_t want = text_size > (kMaxReserve - kMinReserve) / kReservePerTextByte
                         ? kMaxReserve
                         : kMinReserve + kReservePerTextByte * text_size;
  if (const std::size_t left = address_space_left(); left != SIZE_MAX) want = std::min(want, left / 4 * 3);
  want = round_to_pages(std::min(want, kMaxReserve));
  // Reserved, not committed: PROT_NONE pages take no memory and no overcommit charge.
  for (; want >= kSmallestReserve; want = round_to_pages(want / 2)) {
    void* at = ::mmap(nullptr, want, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (at != MAP_FAILED) {
      base_ = static_cast<std::byte*>(at);
      reserved_ = want;
      return;
    }
  }
  throw std::bad_alloc();
}

NodeArena::~NodeArena() {
  if (base_) ::munmap(base_, reserved_);
}

void NodeArena::commit(std::size_t end) {
  if (end > reserved_)
    throw ArenaFull(fmt::format(
        "the file's syntax tree needs more than the {} MiB of address space reserved for it "
        "(split the file into included parts)",
        reserved_ >> 20));
  std::size_t step = std::clamp(committed_, kFirstCommit, kLargestCommit);
  std::size_t to = std::min(reserved_, round_to_pages(std::max(end, committed_ + step)));
  if (::mprotect(base_ + committed_, to - committed_, PROT_READ | PROT_WRITE) != 0) throw std::bad_alloc();
  committed_ = to;
}

void NodeArena::release_unused() {
  if (!base_ || committed_ == reserved_) return;
  ::munmap(base_ + committed_, reserved_ - committed_);
  reserved_ = committed_;
  if (reserved_ == 0) base_ = nullptr;
}

void RawLink::unreachable(const void* target) const {
  throw std::logic_error(fmt::format("AST link at {} cannot reach {}: a node may only link to what was "
                                     "built before it in the same arena",
                                     static_cast<const void*>(this), target));
}

}  // namespace rts::ast
