// parse(): runs the PEGTL grammar over the file's text in place (memory_input, no copy)
// with the actions and control of parse_actions.hpp / parse_control.hpp.
#include "parser/parser.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <tao/pegtl.hpp>

#include "grammar/grammar.hpp"
#include "parser/parse_actions.hpp"
#include "parser/parse_control.hpp"
#include "parser/parse_state.hpp"

namespace rts {
namespace parse_detail {

std::string describe_found(const char* current, const char* end) {
  if (current == end) return "the end of the file";
  unsigned char c = static_cast<unsigned char>(*current);
  if (c >= 0x20 && c < 0x7F) return fmt::format("'{}'", static_cast<char>(c));
  if (c >= 0x80) {
    // A whole UTF-8 sequence (the source manager has validated the text).
    std::size_t len = (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : 4;
    len = std::min<std::size_t>(len, static_cast<std::size_t>(end - current));
    return fmt::format("'{}'", std::string_view(current, len));
  }
  return fmt::format("the control character 0x{:02X}", c);
}

void throw_nesting_too_deep(SourceLoc loc, unsigned limit) {
  throw LanguageError(loc, fmt::format("nesting too deep (more than {} levels)", limit));
}

SourceLoc after_last_token(const SourceFile& file) {
  std::string_view text = file.text();
  std::size_t end = text.size();
  while (end > 0 && grammar::is_blank(text[end - 1])) --end;
  // text[end - 1] ends the last token (or comment) and is not a newline.
  return SourceLoc::at_offset(&file, end);
}

}  // namespace parse_detail

ast::Program parse(const SourceFile& file, const ParseLimits& limits) {
  namespace pegtl = tao::pegtl;
  using parse_detail::ParseState;
  const std::string& text = file.text();
  pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf> in(
      text.data(), text.data() + text.size(), "");
  ParseState st(file, limits);
  // Rough sizes for a typical scene (one statement per ~50 bytes, a few pieces each).
  constexpr std::size_t kBytesPerStatement = 64;
  constexpr std::size_t kStackReserve = 64;
  st.top_level.reserve(text.size() / kBytesPerStatement + kStackReserve);
  st.stmts.reserve(kStackReserve);
  st.exprs.reserve(kStackReserve);
  st.items.reserve(kStackReserve);
  st.names.reserve(kStackReserve);
  st.opens.reserve(kStackReserve);

  try {
    pegtl::parse<grammar::program, parse_detail::action, parse_detail::control>(in, st);
  } catch (const ast::ArenaFull& e) {
    // PEGTL has rewound the input by now; the latest piece built is where the parse stopped.
    SourceLoc at = SourceLoc::at_offset(&file, 0);
    auto later = [&](SourceLoc l) {
      if (l.valid() && l.offset() > at.offset()) at = l;
    };
    if (!st.top_level.empty()) later(st.top_level.back()->loc);
    if (!st.exprs.empty()) later(st.exprs.back().node->loc);
    if (!st.opens.empty()) later(st.opens.back().loc);
    throw LanguageError(at, e.what());
  } catch (const pegtl::parse_error& e) {
    // Every must<> failure is raised by parse_control as a LanguageError; this is a
    // safety net for anything PEGTL itself might report.
    const auto& p = e.positions().front();
    throw LanguageError(SourceLoc::at(&file, static_cast<uint32_t>(p.line), static_cast<uint32_t>(p.column)),
                        std::string(e.message()));
  }

  ast::Program program;
  program.file = &file;
  // Every bracket closed, so every statement is the program's own (parse_detail::push_stmt).
  if (!st.stmts.empty()) throw std::logic_error("parser: statements left inside a closed bracket");
  // The program's statements listed in its arena (4 bytes each), after the last of them.
  if (!st.top_level.empty()) {
    const ast::ListPiece<ast::StmtLink> list =
        st.arena->list<ast::StmtLink>(st.top_level.begin(), st.top_level.end(), [](ast::StmtPtr s) { return s; });
    program.top_level = st.arena->make<ast::StmtList>(list).get();
  }
  std::vector<ast::StmtPtr>().swap(st.top_level);
  st.arena->release_unused();
  program.arena = std::move(st.arena);
  return program;
}

}  // namespace rts
