// The syntax tree of a POV-Ray scene as the reader (reader.hpp) builds it and the writer
// (writer.hpp) turns into rts text. It keeps POV-Ray's structure — directives, declarations,
// macros, loops, blocks of keyword items — rather than evaluated values, so the translation
// stays a program a person can edit.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace rts::import::pov {

struct Loc {
  int line = 0, col = 0;
};

struct Block;
struct Expr;
using ExprPtr = std::shared_ptr<Expr>;

// An expression. POV-Ray's colour keywords (`rgb <1, 0, 0>`, `rgbf ...`) are a prefix
// operator here (kind Color, `text` the keyword); `color X` is Color with text "color".
struct Expr {
  enum Kind { Number, String, Name, Vector, Call, Unary, Binary, Ternary, Member, Index, Color, Array, BlockValue };
  Kind kind = Number;
  Loc loc;
  double number = 0;          // Number
  std::string text;           // String (unescaped as written), Name, Call's name, operator, member, colour keyword
  std::vector<ExprPtr> args;  // operands, components, call arguments, array elements
  std::shared_ptr<Block> block;  // BlockValue: `#declare S = sphere { ... }`
};

// One entry of a block or of a program: POV-Ray mixes positional values, keywords with their
// values, nested blocks and directives freely, so they share one type.
struct Item {
  enum Kind {
    Value,      // a positional value: `<0, 1, 0>`, `0.5`, `Red`, `M(1)`
    Keyword,    // `translate <1, 0, 0>`, `phong 0.5`, `open` (args may be empty)
    Nested,     // `pigment { ... }` (block)
    MapEntry,   // `[0.5 color Red]` in a color_map (args: the values)
    Declare,    // `#declare NAME = value;` / `#local` (local = true); value in args[0]
    Macro,      // `#macro NAME(params) body #end`
    While,      // args[0] the condition
    For,        // `#for (NAME, from, to[, step])`: args from, to, step
    If,         // args[0] the condition; body, else_body
    Switch,     // args[0] the value; body holds Case items
    Case,       // `#case (v)` (args v), `#range (a, b)` (name "range"), `#else` (name "else")
    Include,    // name: the file
    Version,    // args[0]
    Default,    // block: `#default { finish { ... } }`
    Message,    // `#debug`, `#warning`, `#error` (name), args[0] the message
    Ignored,    // a directive with no effect on the picture (`#undef`, `#fopen`, ...): name
  };
  Kind kind = Value;
  Loc loc;
  std::string name;                   // keyword, declared or macro name, include file, directive
  std::vector<ExprPtr> args;
  std::shared_ptr<Block> block;       // Nested, Default
  std::vector<std::string> params;    // Macro
  std::vector<Item> body, else_body;  // Macro, While, For, If, Switch, Case
  std::vector<std::string> comments;  // comments just before the item, without markers
  bool local = false;                 // Declare: #local
  bool ifdef = false;                 // If: #ifdef / #ifndef (args[0] a Name; negate for #ifndef)
  bool negate = false;
};

// `kind { items }`: objects, pigments, finishes, cameras, lights, maps.
struct Block {
  std::string kind;
  Loc loc;
  std::vector<Item> items;
};

struct Program {
  std::string file;           // as named (for locations)
  std::vector<Item> items;
  std::vector<std::string> trailing_comments;
};

}  // namespace rts::import::pov
