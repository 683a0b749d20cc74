// NodeArena's range of address space, and the check behind a link (parser/ast.hpp).
#include <sys/mman.h>

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

NodeArena::NodeArena(std::size_t text_size) {
  std::size_t want = text_size > (kMaxReserve - kMinReserve) / kReservePerTextByte
                         ? kMaxReserve
                         : kMinReserve + kReservePerTextByte * text_size;
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
    throw std::length_error(fmt::format(
        "the file's syntax tree needs more than the {} MiB of address space reserved for it "
        "(split the file into included parts)",
        reserved_ >> 20));
  std::size_t step = std::clamp(committed_, kFirstCommit, kLargestCommit);
  std::size_t to = std::min(reserved_, round_to_pages(std::max(end, committed_ + step)));
  if (::mprotect(base_ + committed_, to - committed_, PROT_READ | PROT_WRITE) != 0) throw std::bad_alloc();
  committed_ = to;
}

void RawLink::unreachable(const void* target) const {
  throw std::logic_error(fmt::format("AST link at {} cannot reach {}: a node may only link to what was "
                                     "built before it in the same arena",
                                     static_cast<const void*>(this), target));
}

}  // namespace rts::ast
