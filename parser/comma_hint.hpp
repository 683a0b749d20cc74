// The syntax error for a ',' inside a block, written for POV-Ray habits: positional
// arguments (`sphere { <0, 1, 0>, 1 }`) and commas between properties (`center = <0, 1, 0>,
// radius = 1`) both stop the parse at a comma where '}' was expected. The error says that rts
// properties are named and separated by blanks, with the block rewritten when that is safe.
#pragma once

#include <cstddef>

#include "parser/diagnostics.hpp"
#include "parser/source.hpp"

namespace rts {

// `open` is the block's '{', `comma` the byte offset of the comma in file.text().
Diagnostic comma_in_block_error(const SourceFile& file, SourceLoc open, std::size_t comma);

}  // namespace rts
