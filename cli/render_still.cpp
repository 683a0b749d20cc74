// `rts render`'s steps for one still: evaluate the scene (a POV-Ray scene translated in memory),
// render it, write its images (atomically: a failure never truncates an existing image), and the
// same still over mpirun's ranks or a checkpoint journal.
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <climits>
#include <utility>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/command.hpp"
#include "cli/manifest.hpp"
#include "cli/render_command.hpp"
#include "cli/eval_options.hpp"
#include "cli/evaluate.hpp"
#include "dist/checkpoint.hpp"
#include "dist/mpi_session.hpp"
#include "dist/tile_exchange.hpp"
#include "dist/tile_log.hpp"
#include "cli/stats_report.hpp"
#include "cli/pov_scene.hpp"
#include "parser/diagnostics.hpp"
#include "runtime/stdlib_path.hpp"
#include "render/image/image_output.hpp"
#include "render/renderer.hpp"
#include "runtime/evaluator.hpp"


namespace rts::cli {

namespace fs = std::filesystem;

namespace {

void print_warnings(const std::vector<render::Warning>& warnings) {
  for (const render::Warning& w : warnings) {
    if (w.where.file && *w.where.file)
      std::cerr << fmt::format("{}:{}:{}: warning: {}\n", w.where.file, w.where.line, w.where.col, w.message);
    else
      std::cerr << "rts: warning: " << w.message << "\n";
  }
}

// The time limit or the sample cap cut an adaptive or time-limited render short.
void print_sampling_warnings(const std::string& out, const render::RenderStats& st) {
  const render::ErrorEstimate& e = st.error;
  if (e.stopped_by_time)
    std::cerr << fmt::format("rts: warning: {}: the time limit of {}s ran out; wrote the image with {:.1f} "
                             "samples per pixel on average\n", out, e.time_limit, e.mean_spp);
  else if (e.target_error > 0 && !e.known)
    std::cerr << fmt::format("rts: warning: {}: --target-error needs at least 2 samples per pixel as the cap "
                             "(--samples); rendered 1 sample per pixel\n", out);
  else if (e.target_error > 0 && !e.target_reached && e.known)
    std::cerr << fmt::format("rts: warning: {}: estimated error {:.3g} did not reach the target {} within "
                             "{} samples per pixel (raise --samples)\n", out, e.rmse, e.target_error, st.samples);
}

// Evaluates the scene; on failure reports the located error and returns its exit code.
// A POV-Ray scene (scene.pov) is translated in memory; its own include files go to a
// temporary folder that the evaluation searches, removed afterwards.
struct PovScene {
  std::string rts;
  fs::path include_dir;
  ~PovScene() {
    std::error_code ec;
    if (!include_dir.empty()) fs::remove_all(include_dir, ec);
  }
};

int import_pov_scene(const RenderCommand& c, EvalOptions& eval, PovScene& pov) {
  import::pov::PovOptions opt;
  opt.source_path = c.scene;
  opt.include_dirs = c.eval.include_paths;
  opt.strict = c.strict;
  opt.stdlib_dir = c.eval.stdlib_dir.empty() ? runtime::find_standard_library() : c.eval.stdlib_dir;
  import::pov::PovResult result;
  std::string why;
  if (!c.ini.empty() && !read_pov_ini(c.ini, opt, why)) {
    if (!why.empty()) std::cerr << "rts: " << why << "\n";
    return why.empty() ? kExitLanguageError : kExitUsage;
  }
  if (!import_pov_file(c.scene, opt, result, why)) {
    if (!why.empty()) std::cerr << "rts: " << why << "\n";
    return kExitLanguageError;
  }
  pov.rts = std::move(result.rts);
  if (!result.includes.empty()) {
    std::string pattern = (fs::temp_directory_path() / "rts-pov-XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
      std::cerr << "rts: cannot make a temporary folder for the scene's include files\n";
      return kExitRenderError;
    }
    pov.include_dir = pattern;
    for (const import::pov::PovOutputFile& f : result.includes) {
      std::ofstream o(pov.include_dir / f.name, std::ios::binary);
      o << f.text;
    }
    eval.include_paths.push_back(pov.include_dir.string());
    eval.allow_read.push_back(pov.include_dir.string());
  }
  return kExitOk;
}


// The options that change pixels, for a checkpoint's key: the command line without the ones
// that do not (threads, output name, progress and statistics flags, the checkpoint itself).
std::string pixel_options(const std::vector<std::string>& args) {
  static const std::vector<std::string> kWithValue = {"--threads",    "-o",         "--output",  "--checkpoint",
                                                      "--stats-json", "--tile-log", "--progress"};
  static const std::vector<std::string> kFlags = {"--no-progress", "--stats"};
  std::string out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto named = [&](const std::string& n) { return a == n || a.rfind(n + "=", 0) == 0; };
    bool skip = false;
    for (const std::string& n : kWithValue)
      if (named(n)) {
        skip = true;
        if (a == n) ++i;  // its value is the next word
      }
    for (const std::string& n : kFlags) skip = skip || a == n;
    if (!skip) out += (out.empty() ? "" : " ") + a;
  }
  return out;
}

}  // namespace

// Fails early (before evaluating or rendering) when the output folder cannot take the file.
// A directory can look writable (root, W_OK) and still refuse new files (/proc, a read-only
// mount): the only sure test is to create a file there, so one is created and removed.
void check_output_writable(const std::string& out) {
  std::error_code ec;
  fs::file_status st = fs::status(out, ec);
  if (fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st)) {
    // A device or pipe (-o /dev/stdout): written in place, so it must itself be writable.
    if (access(out.c_str(), W_OK) != 0)
      throw render::RenderError({}, fmt::format("cannot write '{}': not writable", out));
    return;
  }
  fs::path dir = fs::path(out).parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir, ec))
    throw render::RenderError({}, fmt::format("cannot write '{}': directory '{}' does not exist", out, dir.string()));
  if (fs::is_directory(out, ec))
    throw render::RenderError({}, fmt::format("cannot write '{}': it is a directory", out));
  std::string probe = (dir / ".rts-write-probe-XXXXXX").string();
  int fd = mkstemp(probe.data());
  if (fd < 0) {
    const int err = errno;
    // ENOENT on an existing directory: a virtual file system (/proc, /sys) that makes no files.
    std::string why = err == ENOENT  ? "it does not accept new files"
                      : err == EROFS ? "it is on a read-only file system"
                      : err == EACCES || err == EPERM ? "it is not writable (permission denied)"
                      : err == ENOSPC || err == EDQUOT ? "it is full"
                                       : std::string("a file cannot be created there: ") + std::strerror(err);
    throw render::RenderError({}, fmt::format("cannot write '{}': directory '{}': {}", out, dir.string(), why));
  }
  close(fd);
  unlink(probe.c_str());
}

// How long work shows itself on stderr: --progress (auto: a bar on a terminal, else nothing).
render::ProgressMode progress_mode(const RenderCommand& c) {
  if (c.no_progress || c.progress == "none") return render::ProgressMode::None;
  if (c.progress == "lines") return render::ProgressMode::Lines;
  if (c.progress == "bar") return render::ProgressMode::Bar;
  return isatty(STDERR_FILENO) ? render::ProgressMode::Bar : render::ProgressMode::None;
}

int evaluate_scene(const RenderCommand& c, const EvalOptions& eval_in, DiagnosticSink& sink, Evaluated& out,
                   render::ProgressMode progress) {
  EvalOptions eval = eval_in;
  PovScene pov;
  std::string path = c.scene;
  if (is_pov_path(c.scene)) {
    if (int rc = import_pov_scene(c, eval, pov); rc != kExitOk) return rc;
    // The translation, in memory beside the scene (its relative paths stay the scene's).
    path = c.scene + ".rts";
    out.sources->add(path, std::move(pov.rts));
  }
  // Evaluation (and the OBJ files it loads) can take a while: its time and the objects placed
  // so far are shown, from another thread, once it has run half a second.
  std::atomic<uint64_t> placed{0};
  if (progress != render::ProgressMode::None) eval.placed = &placed;
  render::PhaseProgress phase(progress, "evaluating " + c.scene, &placed, "objects placed");
  EvalResult evaluated;
  const bool ok = evaluate_reporting(*out.sources, path, eval, sink, evaluated, SceneWarnings{true, c.integrator});
  phase.done();
  if (!ok)
    return kExitLanguageError;
  out.eval_seconds = evaluated.seconds;
  out.parse_seconds = evaluated.parse_seconds;
  out.uses_clock = evaluated.uses_clock;
  out.scene = std::move(evaluated.scene);
  return kExitOk;
}

// Renders an evaluated scene and writes its images to `out`; `stats` receives the figures.
// With `video`, the image goes to the video instead of a file (AOVs are refused earlier).
int render_scene(const RenderCommand& c, const CLI::App& cmd, Evaluated& ev, const std::string& out,
                 const render::OutputSpec& spec, DiagnosticSink& sink, render::RenderStats* stats_out,
                 render::VideoWriter* video, const Distribution* dist, SceneAfterRender after) {
  render::RenderOptions opts;
  opts.threads = c.threads;
  if (cmd.count("--seed")) opts.seed = c.seed;
  if (cmd.count("--width")) opts.width = c.width;
  if (cmd.count("--height")) opts.height = c.height;
  if (cmd.count("--samples")) opts.samples = c.samples;
  if (cmd.count("--max-depth")) opts.max_depth = c.max_depth;
  // The scene's settings say which images a plain render writes; the command line overrides.
  const render::Settings& st = ev.scene.settings;
  opts.aovs = !c.aovs.empty() || video ? c.aovs : st.aovs;
  if (!c.sampler.empty()) {
    render::SamplerKind kind = render::SamplerKind::Sobol;
    render::parse_sampler(c.sampler, kind);  // CLI11 checked the name
    opts.sampler = kind;
  }
  if (!c.integrator.empty()) {
    render::IntegratorKind kind = render::IntegratorKind::Whitted;
    render::parse_integrator(c.integrator, kind);  // CLI11 checked the name
    opts.integrator = kind;
  }
  opts.target_error = c.target_error;
  opts.time_limit = c.time_limit;
  opts.max_memory = c.eval.limits.max_memory;
  if (!c.depth_range.empty()) opts.depth_range = std::make_pair(c.depth_range[0], c.depth_range[1]);
  else if (st.has_depth_range) opts.depth_range = std::make_pair(st.depth_near, st.depth_far);
  opts.depth_miss = cmd.count("--depth-miss") ? c.depth_miss : static_cast<float>(st.depth_miss);
  opts.normal_miss = cmd.count("--normal-miss") ? c.normal_miss : static_cast<float>(st.normal_miss);
  opts.progress = progress_mode(c);
  opts.specialize = !c.no_specialize;
  if (dist) {
    opts.exchange = dist->exchange;
    opts.progress = render::ProgressMode::None;
  }
  const bool several = dist && dist->mpi->size() > 1;
  // A rank that fails while the others wait for it ends the job, naming itself.
  auto rank_failure = [&](const std::string& message, int code) {
    std::cerr << fmt::format("rts: rank {}: error: {}\n", dist->mpi->rank(), message);
    dist->mpi->abort(code);
  };

  try {
    if (!video && !dist) check_output_writable(out);
    render::RenderResult result = after == SceneAfterRender::Released ? render::render(std::move(ev.scene), opts)
                                                                      : render::render(ev.scene, opts);
    if (dist && !dist->root()) return kExitOk;  // rank 0 writes the image
    print_warnings(result.warnings);
    result.stats.eval_seconds = ev.eval_seconds;
    result.stats.parse_seconds = ev.parse_seconds;
    auto write_start = std::chrono::steady_clock::now();
    if (video)
      video->add_frame(result.color);
    else
      render::write_images(out, spec, result.color, result.aovs);
    result.stats.write_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();
    std::cerr << "rts: " << out << ": " << result.stats.summary() << "\n";
    if (dist) {
      const dist::ExchangeStats& x = dist->exchange->stats();
      const std::string rounds =
          x.rounds > 1 ? fmt::format(" over {} rounds ({} left alone: nothing to add)", x.rounds, x.skipped) : "";
      std::cerr << fmt::format("rts: {}: {} tiles{}: {} rendered by rank 0, {} by the other {} rank(s), {} from the "
                               "checkpoint\n", out, x.tiles, rounds, x.rendered_here, x.rendered_remote,
                               dist->mpi->size() - 1, x.from_checkpoint);
      if (c.stats.print && x.rendered_here > 0) {
        const double per_tile = x.render_seconds_here / x.rendered_here;
        const double per_remote =
            x.rendered_remote ? (x.fold_seconds + x.serve_seconds) / x.rendered_remote : 0.0;
        std::cerr << fmt::format("  rank 0: {:.3f} ms rendering a tile; {:.1f} us receiving, storing and journaling "
                                 "one from another rank ({} kB in all){}\n", per_tile * 1e3, per_remote * 1e6,
                                 x.bytes_received / 1024,
                                 per_remote > 0 ? fmt::format("; one root feeds about {:.0f} ranks of this speed",
                                                              per_tile / per_remote)
                                                : "");
      }
    }
    if (dist && !c.tile_log.empty()) {
      const int tiles_per_round = dist->exchange->stats().rounds > 0
                                      ? dist->exchange->stats().tiles / dist->exchange->stats().rounds
                                      : 1;
      dist::write_tile_log(c.tile_log, dist->exchange->stats(), dist->mpi->size(), std::max(tiles_per_round, 1),
                           result.stats);
    }
    print_sampling_warnings(out, result.stats);
    report_stats(c.stats, result.stats);
    if (stats_out) *stats_out = result.stats;
  } catch (const render::RenderError& e) {
    if (several) rank_failure(e.what(), kExitRenderError);
    print_error(e.where, e.what(), *ev.sources, sink);
    return kExitRenderError;
  } catch (const std::bad_alloc&) {
    if (several) rank_failure("out of memory", kExitRenderError);
    print_error({}, "out of memory (lower the image size, samples or scene, or check ulimit -v)", *ev.sources, sink);
    return kExitRenderError;
  }
  return kExitOk;
}

// A still over mpirun's ranks and/or with a checkpoint journal.
int run_distributed(const RenderCommand& c, const CLI::App& cmd, const CommandContext& ctx, const std::string& out,
                    const render::OutputSpec& spec, Evaluated& ev, DiagnosticSink& sink) {
  const dist::MpiSession& mpi = *ctx.mpi;
  int pre = kExitOk;
  std::unique_ptr<dist::Checkpoint> journal;
  if (mpi.rank() == 0) {
    try {
      check_output_writable(out);
      if (!c.checkpoint.empty())
        journal = std::make_unique<dist::Checkpoint>(
            c.checkpoint, fmt::format("rts 1; scene {}; options {}", scene_hash(*ev.sources), pixel_options(ctx.args)));
      if (journal && journal->torn_bytes() > 0)
        std::cerr << fmt::format("rts: {}: resuming; a torn last record ({} bytes) was dropped\n", journal->path(),
                                 journal->torn_bytes());
    } catch (const render::RenderError& e) {
      std::cerr << "rts: error: " << e.what() << "\n";
      pre = kExitRenderError;
    }
  }
  if (int all = mpi.agree(pre); all != kExitOk) return all;  // every rank stops together
  dist::TileQueueExchange exchange(mpi, journal.get());
  Distribution d{&mpi, &exchange};
  return render_scene(c, cmd, ev, out, spec, sink, nullptr, nullptr, &d);
}

}  // namespace rts::cli
