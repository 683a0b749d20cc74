// evaluate_file(): runs the interpreter on a thread with a large stack and times it.
#include "runtime/evaluator.hpp"

#include <malloc.h>
#include <pthread.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <utility>

#include "runtime/interpreter.hpp"

namespace rts {

namespace {

// The evaluator recurses in C++ for every macro call and nested expression; give it a stack
// big enough for the recursion limit (memory is only committed as it is touched).
constexpr std::size_t kMinStackBytes = 256u << 20;
constexpr std::size_t kStackBytesPerMacroLevel = 64u << 10;
constexpr std::size_t kMaxStackBytes = std::size_t(8) << 30;
// Where address space is limited (ulimit -v), the request is halved down to this.
constexpr std::size_t kSmallestStackBytes = 16u << 20;
// Evaluation fails cleanly (a located error) with this much stack still free: enough for the
// frames between two checks (one statement's expressions, a builtin, formatting the error).
constexpr std::size_t kStackReserveBytes = 4u << 20;

// The lowest address the calling thread's stack may use before the reserve, and its size.
std::pair<std::uintptr_t, std::size_t> stack_floor_of_this_thread() {
  pthread_attr_t attr;
  void* addr = nullptr;
  std::size_t size = 0;
  if (pthread_getattr_np(pthread_self(), &attr) != 0) return {0, 0};
  pthread_attr_getstack(&attr, &addr, &size);
  pthread_attr_destroy(&attr);
  if (!addr || size <= 2 * kStackReserveBytes) return {0, size};
  return {reinterpret_cast<std::uintptr_t>(addr) + kStackReserveBytes, size};
}

using StackFn = std::function<void(std::uintptr_t floor, std::size_t bytes)>;

void run_with_big_stack(std::size_t stack_bytes, const StackFn& fn) {
  struct Job {
    const StackFn* fn;
    std::exception_ptr error;
  } job{&fn, nullptr};
  auto start = [&](std::size_t bytes, pthread_t& thread) {
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    bool ok = pthread_attr_setstacksize(&attr, bytes) == 0 &&
              pthread_create(
                  &thread, &attr,
                  [](void* p) -> void* {
                    auto* j = static_cast<Job*>(p);
                    try {
                      auto [floor, size] = stack_floor_of_this_thread();
                      (*j->fn)(floor, size);
                    } catch (...) {
                      j->error = std::current_exception();
                    }
                    return nullptr;
                  },
                  &job) == 0;
    pthread_attr_destroy(&attr);
    return ok;
  };
  pthread_t thread;
  // A huge request can fail where address space is limited (ulimit -v): ask for less, and
  // let the stack check end a recursion the smaller stack cannot hold.
  bool started = false;
  for (std::size_t bytes = stack_bytes; !started && bytes >= kSmallestStackBytes; bytes /= 2)
    started = start(bytes, thread);
  if (!started) {
    auto [floor, size] = stack_floor_of_this_thread();
    fn(floor, size);  // no thread available: run here, with this thread's stack
    return;
  }
  pthread_join(thread, nullptr);
  if (job.error) std::rethrow_exception(job.error);
}

// Scenes grow a few very large vectors (shapes, materials, instances) by doubling. glibc
// serves such blocks with mmap and unmaps them when freed, so every growth step faults in
// fresh zeroed pages; keeping them in the heap lets freed blocks be reused instead (about 15%
// faster on 90,000 objects). rts is a one-shot process, so never trimming is harmless.
//
// One arena: evaluation runs on a thread of its own (run_with_big_stack), which glibc gives an
// arena of its own, and malloc_trim cannot give back that arena's top (only the main arena's
// shrinks), so what the description held there stayed resident through the world's build.
// Profile finding (RSS trace and malloc_info, 1M placements of a group: the thread arena held
// 58 MB free after the description's placements were released). Peaks: 1M placements 218 ->
// 166 MB, 1M spheres 158 -> 148 MB, 4M spheres 391 -> 404 MB (the allocator's layout; still
// under 100 bytes a sphere). The render allocates nothing per ray, so the workers do not
// contend for the lock: mesh2m, grid90k, terrain and 1M spheres took the same CPU time.
void keep_large_blocks_in_heap() {
#ifdef __GLIBC__
  constexpr int kLargeBlockBytes = 1 << 30;
  mallopt(M_MMAP_THRESHOLD, kLargeBlockBytes);
  mallopt(M_TRIM_THRESHOLD, kLargeBlockBytes);
  mallopt(M_ARENA_MAX, 1);
#endif
}

// What evaluation freed stays resident (the blocks the description's vectors grew out of, the
// interpreter's values and the evaluation thread's arena), and the build that follows did not
// reuse all of it. Profile finding (RSS trace and heaptrack, 1M and 4M spheres): the peak moved
// by tens of MB with the allocator's layout alone (which arena served what). Handing the free
// pages back once, when a large scene is described, makes the build's peak what it allocates.
void release_evaluation_memory(std::size_t items) {
#ifdef __GLIBC__
  constexpr std::size_t kLargeSceneItems = 100'000;
  if (items >= kLargeSceneItems) malloc_trim(0);
#else
  (void)items;
#endif
}

// The interpreter, or the located error Interpreter::run gives when the system refuses memory
// (here before the scene runs: under a tight `ulimit -v`, the tables the constructor makes).
std::unique_ptr<runtime::Interpreter> make_interpreter(SourceManager& sources, const EvalOptions& options,
                                                       DiagnosticSink& warnings, const SourceFile& file) {
  try {
    return std::make_unique<runtime::Interpreter>(sources, options, warnings);
  } catch (const std::bad_alloc&) {
    Diagnostic d;
    d.loc = SourceLoc::at(&file, 1, 1);
    d.message = "out of memory: the system refused memory before the scene could run (check ulimit -v)";
    throw LanguageError(std::move(d));
  }
}

}  // namespace

EvalResult evaluate_source(SourceManager& sources, const SourceFile& file, const EvalOptions& options,
                           DiagnosticSink& warnings) {
  EvalResult result;
  keep_large_blocks_in_heap();
  auto start = std::chrono::steady_clock::now();
  std::size_t stack =
      std::clamp<std::size_t>(kMinStackBytes + std::size_t(options.limits.max_recursion) * kStackBytesPerMacroLevel,
                              kMinStackBytes, kMaxStackBytes);
  // Under `ulimit -v` the stack's whole range counts, touched or not: a quarter of what is left
  // at most, so the scene's own memory has the rest. (Asking for the most that would map left
  // a small file's evaluation a few MB: "std::bad_alloc" under 100 MB but not under 80.)
  if (const std::size_t left = ast::address_space_left(); left != SIZE_MAX)
    stack = std::max(std::min(stack, left / 4), kSmallestStackBytes);
  run_with_big_stack(stack, [&](std::uintptr_t floor, std::size_t bytes) {
    auto interp = make_interpreter(sources, options, warnings, file);
    interp->set_stack_floor(floor, bytes);
    interp->run(file);
    result.world_shapes = interp->world_shapes();
    result.world_lights = interp->world_lights();
    result.uses_clock = interp->uses_clock();
    if (options.describe_globals) result.globals = interp->describe_globals(options.describe_globals);
    result.scene = interp->finish();
    result.parse_seconds = interp->parse_seconds();
  });
  release_evaluation_memory(result.scene.shapes.size() + result.scene.nodes.size());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

EvalResult evaluate_file(SourceManager& sources, const std::string& path, const EvalOptions& options,
                         DiagnosticSink& warnings) {
  auto start = std::chrono::steady_clock::now();
  const SourceFile* file = sources.load(path);
  EvalResult r = evaluate_source(sources, *file, options, warnings);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

bool parse_define(const std::string& text, Define& out) {
  std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) return false;
  std::string name = text.substr(0, eq);
  if (!(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  out.name = name;
  out.value = text.substr(eq + 1);
  return true;
}

}  // namespace rts
