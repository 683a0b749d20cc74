// The evaluator: runs a scene program (an rts::ast::Program) and builds a render::SceneDesc
// through render::SceneBuilder. Entry point for `rts check`, `rts eval` and `rts render`.
//
//   rts::EvalOptions opts;                       // -I, -D and limits (see add_eval_options)
//   rts::DiagnosticSink warnings(std::cerr);
//   rts::EvalResult r = rts::evaluate_file(sources, "scene.rts", opts, warnings);
//
// Errors: a syntax or runtime error in any file is thrown as LanguageError (located, with
// "in call to macro" / "in file included from here" notes, innermost first); a main file that
// cannot be read is thrown as SourceError. Warnings (e.g. a -D define that matches no `let`)
// go to `warnings`.
#pragma once

#include <atomic>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "parser/diagnostics.hpp"
#include "parser/source.hpp"
#include "render/scene/scene.hpp"

namespace rts {

// -D name=value: `value` is an rts expression (2, "x", <1,2,3>, rgb(1,0,0)...). It replaces
// the expression of the FIRST top-level `let name = ...` of the main file.
struct Define {
  std::string name, value;
};

// Limits no sensible scene reaches; each has a command-line flag to raise it
// (docs/reliability.md lists them).
struct EvalLimits {
  uint64_t max_iterations = 10'000'000;         // --max-iterations: loop iterations, in total
  // --max-steps: loop iterations + macro calls + list elements and string bytes built.
  uint64_t max_steps = 100'000'000;
  unsigned max_recursion = 1000;                // --max-recursion: macro call depth
  // --max-objects: object placements, and objects in the world once groups are expanded.
  std::size_t max_objects = 10'000'000;
  std::size_t max_mesh_triangles = 50'000'000;  // --max-mesh-triangles: OBJ + inline meshes
  // --max-memory: bytes the process may hold (checked where big values are made); 0: none.
  std::size_t max_memory = 0;
  // Wall-clock seconds evaluation may run (checked with the memory, every 65,536 steps);
  // 0: none. The language server's budget, so that a runaway loop never freezes an editor.
  double max_seconds = 0;
};

// The animation clock a frame is evaluated at: the built-in constants `clock` (0 at the first
// frame, 1 at the last, as in POV-Ray), `frame` (the frame number) and `frames` (their count).
// A still is frame 0 of 1, clock 0.
struct AnimationClock {
  double clock = 0.0;
  int64_t frame = 0;
  int64_t frames = 1;
};

struct EvalOptions {
  std::vector<std::string> include_paths;  // -I, searched after the including file's folder
  // The standard library's folder, searched after the -I folders; "" finds it
  // (runtime/stdlib_path.hpp: $RTS_STDLIB, the install, or the source tree when uninstalled).
  std::string stdlib_dir;
  std::vector<Define> defines;             // -D
  EvalLimits limits;
  bool warn_unused = false;                // `rts check`: warn about unused declarations
  // Folders a scene may read from besides its own, the -I folders and the current folder
  // (--allow-read; "/" lifts the restriction). restrict_reads = false: read anything (tests).
  std::vector<std::string> allow_read;
  bool restrict_reads = false;
  AnimationClock animation;                // `rts render --frames`
  // Non-null: the objects placed in the world so far are stored here after each placement,
  // for a progress display on another thread.
  std::atomic<uint64_t>* placed = nullptr;
  // Keep a text of each top-level variable's value, at most this many bytes each, in
  // EvalResult::globals (the language server's hover); 0: none.
  std::size_t describe_globals = 0;
};

// A top-level variable of the main file once evaluation finished, its value as text.
struct GlobalValue {
  std::string name;
  SourceLoc loc;      // where it was declared
  std::string value;  // cut at EvalOptions::describe_globals bytes, then "…"
};

struct EvalResult {
  render::SceneDesc scene;
  double seconds = 0.0;  // wall-clock time of parsing + evaluation
  double parse_seconds = 0.0;  // the parsing part of `seconds` (every file, included ones too)
  // Shapes and lights in the world once groups are expanded (for "renders nothing" warnings).
  uint64_t world_shapes = 0, world_lights = 0;
  // The program read `clock`, `frame` or `frames` (an animation whose frames differ).
  bool uses_clock = false;
  std::vector<GlobalValue> globals;  // with EvalOptions::describe_globals
};

// Parses and evaluates the scene file at `path` (loaded through `sources`, which must outlive
// the result: SourceRefs in the scene point into it). Runs on a thread with a large stack so
// that deep macro recursion (up to limits.max_recursion) cannot overflow the C++ stack.
EvalResult evaluate_file(SourceManager& sources, const std::string& path, const EvalOptions& options,
                         DiagnosticSink& warnings);

// The same for an already loaded file (tests: SourceManager::add of in-memory text).
EvalResult evaluate_source(SourceManager& sources, const SourceFile& file, const EvalOptions& options,
                           DiagnosticSink& warnings);

// Parses a -D argument "name=value" into a Define; returns false when it has no '=' or the
// name is not an identifier.
bool parse_define(const std::string& text, Define& out);

}  // namespace rts
