// `rts render SCENE.rts [-o OUT.png|.pfm|.exr] ...`: evaluate the scene, render it, write the
// image(s). Nothing is written unless evaluation and rendering both succeed; each file is
// written atomically, so a failure never truncates an existing image.
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
#include "cli/eval_options.hpp"
#include "cli/evaluate.hpp"
#include "cli/file_watch.hpp"
#include "cli/frames.hpp"
#include "cli/manifest.hpp"
#include "dist/checkpoint.hpp"
#include "dist/mpi_session.hpp"
#include "dist/tile_exchange.hpp"
#include "dist/tile_log.hpp"
#include "cli/stats_report.hpp"
#include "cli/number_flags.hpp"
#include "cli/pov_scene.hpp"
#include "parser/diagnostics.hpp"
#include "runtime/stdlib_path.hpp"
#include "render/image/image_output.hpp"
#include "render/image/video_writer.hpp"
#include "render/renderer.hpp"
#include "runtime/evaluator.hpp"

namespace rts::cli {
namespace {

namespace fs = std::filesystem;

constexpr uint64_t kMaxThreads = 1024;
constexpr uint64_t kMaxSeed = uint64_t(1) << 53;  // as settings.seed: every seed a double holds exactly
constexpr uint64_t kMaxImageSide = 1'000'000;      // the pixel count has its own limit
// --watch: an editor's save is a few events within milliseconds; wait this long for quiet.
constexpr int kWatchSettleMs = 100;

struct RenderCommand {
  std::string scene;
  std::string output;
  int threads = 0;
  uint64_t seed = 0;
  int width = 0, height = 0, samples = 0, max_depth = 0;
  std::vector<std::string> aovs;
  std::string sampler;
  std::string integrator;
  double target_error = 0, time_limit = 0;
  int bits = 0;  // 0: the format's default
  bool linear = false, aov_files = false;
  std::vector<double> depth_range;
  float depth_miss = 0.0f, normal_miss = 0.0f;
  bool no_progress = false;
  std::string progress = "auto";  // --progress: auto, bar, lines, none
  bool no_specialize = false;
  bool strict = false;  // a POV-Ray scene: what rts cannot express is an error
  StatsOptions stats;
  EvalOptions eval;
  // Animation (cli/frames.hpp).
  std::string frames, manifest;
  int64_t task_index = 0, task_count = 1;
  bool skip_existing = false;
  int fps = 24;
  std::string checkpoint;  // --checkpoint DIR (dist/checkpoint.hpp)
  std::string tile_log;    // --tile-log FILE (dist/tile_log.hpp)
  bool watch = false;      // --watch: render again on every change (cli/file_watch.hpp)
};

// A still shared by ranks (mpirun) or journaled (--checkpoint): the tile queue, and whether
// this process writes the image.
struct Distribution {
  const dist::MpiSession* mpi = nullptr;
  dist::TileQueueExchange* exchange = nullptr;
  bool root() const { return mpi == nullptr || mpi->rank() == 0; }
};

void print_warnings(const std::vector<render::Warning>& warnings) {
  for (const render::Warning& w : warnings) {
    if (w.where.file && *w.where.file)
      std::cerr << fmt::format("{}:{}:{}: warning: {}\n", w.where.file, w.where.line, w.where.col, w.message);
    else
      std::cerr << "rts: warning: " << w.message << "\n";
  }
}

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

// The scene evaluated at one point of the animation clock, with the sources its locations
// point into.
struct Evaluated {
  std::unique_ptr<SourceManager> sources = std::make_unique<SourceManager>();
  render::SceneDesc scene;
  double eval_seconds = 0, parse_seconds = 0;
  bool uses_clock = false;
};

// How long work shows itself on stderr: --progress (auto: a bar on a terminal, else nothing).
render::ProgressMode progress_mode(const RenderCommand& c) {
  if (c.no_progress || c.progress == "none") return render::ProgressMode::None;
  if (c.progress == "lines") return render::ProgressMode::Lines;
  if (c.progress == "bar") return render::ProgressMode::Bar;
  return isatty(STDERR_FILENO) ? render::ProgressMode::Bar : render::ProgressMode::None;
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

int evaluate_scene(const RenderCommand& c, const EvalOptions& eval_in, DiagnosticSink& sink, Evaluated& out,
                   render::ProgressMode progress = render::ProgressMode::None) {
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
                 render::VideoWriter* video = nullptr, const Distribution* dist = nullptr) {
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
    render::RenderResult result = render::render(ev.scene, opts);
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

bool same_clock(const AnimationClock& a, const AnimationClock& b) {
  return a.clock == b.clock && a.frame == b.frame && a.frames == b.frames;
}

// The scene at `clock` into `out`: the probe itself when it was evaluated at this very clock
// (evaluating again would give the same scene; it is moved, so used once), else a fresh
// evaluation. Returns its exit code after reporting an evaluation error.
int scene_at(const RenderCommand& c, const CommandContext& ctx, const AnimationClock& clock, Evaluated& probe,
             const AnimationClock& probe_clock, Evaluated& out) {
  if (probe.sources && same_clock(clock, probe_clock)) {
    out = std::move(probe);
    return kExitOk;
  }
  EvalOptions eval = c.eval;
  eval.animation = clock;
  DiagnosticSink frame_sink(std::cerr, ctx.color);
  return evaluate_scene(c, eval, frame_sink, out);
}

// Every frame of an animation that never reads the clock is the same image: say so once.
void warn_if_static(const RenderCommand& c, const Evaluated& probe, const FrameRange& animation) {
  if (!probe.uses_clock && animation.count() > 1)
    std::cerr << fmt::format("rts: warning: {}: the scene never reads clock, frame or frames: every frame "
                             "is the same image\n", c.scene);
}

// Renders the frames of an animation this process is given (docs/scale-out.md): each frame is
// evaluated afresh at its clock, so it depends on its number alone, never on which frames
// this process rendered before it.
int run_frames(const RenderCommand& c, const CLI::App& cmd, const CommandContext& ctx, const std::string& pattern,
               const render::OutputSpec& spec, const FrameRange& animation, const FrameRange& selected,
               const TaskSlice& task, Evaluated probe, const AnimationClock& probe_clock, DiagnosticSink& sink) {
  const std::string manifest = c.manifest.empty() ? default_manifest_path(pattern) : c.manifest;
  const std::vector<int64_t> frames = task_frames(selected, task);
  warn_if_static(c, probe, animation);
  std::size_t done = 0, skipped = 0;
  for (int64_t f : frames) {
    const std::string out = frame_path(pattern, f);
    std::error_code ec;
    if (c.skip_existing && fs::exists(out, ec)) {  // written whole: files are renamed into place
      ++skipped;
      continue;
    }
    auto start = std::chrono::steady_clock::now();
    AnimationClock clock{frame_clock(animation, f), f, animation.count()};
    Evaluated ev;
    if (int rc = scene_at(c, ctx, clock, probe, probe_clock, ev); rc != kExitOk) return rc;
    render::RenderStats stats;
    if (int rc = render_scene(c, cmd, ev, out, spec, sink, &stats); rc != kExitOk) return rc;
    FrameRecord r;
    r.frame = f;
    r.clock = clock.clock;
    r.file = out;
    r.checksum = file_checksum(out);
    r.scene = c.scene;
    r.scene_hash = scene_hash(*ev.sources);
    r.args = ctx.args;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stats.error.known) r.error_rmse = stats.error.rmse;
    r.samples_per_pixel = stats.error.mean_spp;
    r.task_index = task.index;
    r.task_count = task.count;
    try {
      append_manifest(manifest, r);
    } catch (const render::RenderError& e) {
      std::cerr << "rts: error: " << e.what() << "\n";
      return kExitRenderError;
    }
    ++done;
  }
  std::cerr << fmt::format("rts: frames {}..{}{}: rendered {}, skipped {} already written; manifest {}\n",
                           selected.first, selected.last,
                           task.count > 1 ? fmt::format(" (task {} of {})", task.index, task.count) : "", done,
                           skipped, manifest);
  return kExitOk;
}

// Renders the frames in order into one video file (written whole at the end, or not at all).
int run_video(const RenderCommand& c, const CLI::App& cmd, const CommandContext& ctx, const std::string& out,
              render::VideoFormat format, const FrameRange& animation, const FrameRange& selected, Evaluated probe,
              const AnimationClock& probe_clock, DiagnosticSink& sink) {
  auto start = std::chrono::steady_clock::now();
  std::unique_ptr<render::VideoWriter> video;
  render::OutputSpec spec;  // unused: frames go to the video
  warn_if_static(c, probe, animation);
  try {
    check_output_writable(out);
  } catch (const render::RenderError& e) {
    std::cerr << "rts: error: " << e.what() << "\n";
    return kExitRenderError;
  }
  for (int64_t f = selected.first; f <= selected.last; ++f) {
    AnimationClock clock{frame_clock(animation, f), f, animation.count()};
    Evaluated ev;
    if (int rc = scene_at(c, ctx, clock, probe, probe_clock, ev); rc != kExitOk) return rc;
    if (!video) {
      const int w = cmd.count("--width") ? c.width : ev.scene.settings.width;
      const int h = cmd.count("--height") ? c.height : ev.scene.settings.height;
      try {
        render::VideoOptions vo;
        vo.fps = c.fps;
        video = std::make_unique<render::VideoWriter>(out, format, w, h, vo);
      } catch (const render::RenderError& e) {
        std::cerr << "rts: error: " << e.what() << "\n";
        return kExitRenderError;
      }
    }
    const std::string label = fmt::format("{} frame {}", out, f);
    if (int rc = render_scene(c, cmd, ev, label, spec, sink, nullptr, video.get()); rc != kExitOk) return rc;
  }
  try {
    video->finish();
  } catch (const render::RenderError& e) {
    std::cerr << "rts: error: " << e.what() << "\n";
    return kExitRenderError;
  }
  std::cerr << fmt::format("rts: {}: {} frames ({}..{}), {} at {} fps, {:.1f}s\n", out, video->frames(),
                           selected.first, selected.last, video->codec_name(), c.fps,
                           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return kExitOk;
}

// The files a scene read besides its sources: image textures and OBJ meshes.
void add_scene_inputs(const render::SceneDesc& scene, std::vector<std::string>& files) {
  for (const render::TextureDesc& t : scene.textures) {
    files.push_back(t.image_path);
    files.insert(files.end(), t.face_paths.begin(), t.face_paths.end());
  }
  for (const auto& m : scene.meshes) files.push_back(m->source);
}

// --watch: renders the still, then again whenever the scene or a file it includes or reads
// changes: first one sample per pixel (seen at once), then the full render unless another
// change came meanwhile. A failing round reports its error and leaves the last image alone.
int run_watch(const RenderCommand& c, const CLI::App& cmd, const CommandContext& ctx, const std::string& out,
              const render::OutputSpec& spec) {
  std::unique_ptr<FileWatcher> watching;
  try {
    watching = std::make_unique<FileWatcher>();
  } catch (const std::runtime_error& e) {
    std::cerr << "rts: error: " << e.what() << "\n";
    return kExitRenderError;
  }
  FileWatcher& watcher = *watching;
  for (;;) {
    DiagnosticSink sink(std::cerr, ctx.color);
    Evaluated ev;
    const bool ok = evaluate_scene(c, c.eval, sink, ev) == kExitOk;
    std::vector<std::string> files{c.scene};
    for (const SourceFile* f : ev.sources->files()) files.push_back(f->path());
    if (ok) add_scene_inputs(ev.scene, files);
    const std::size_t watched = watcher.watch(files);
    const int samples = cmd.count("--samples") ? c.samples : ev.scene.settings.samples;
    bool superseded = false;
    if (ok && (samples > 1 || c.target_error > 0)) {
      RenderCommand quick = c;
      quick.samples = 1;
      quick.target_error = quick.time_limit = 0;
      const int scene_samples = std::exchange(ev.scene.settings.samples, 1);
      render_scene(quick, cmd, ev, out, spec, sink, nullptr);
      ev.scene.settings.samples = scene_samples;
      superseded = watcher.changed();
    }
    if (superseded) continue;
    if (ok) render_scene(c, cmd, ev, out, spec, sink, nullptr);
    std::cerr << fmt::format("rts: watching {} file{} for changes (Ctrl-C stops)\n", watched, watched == 1 ? "" : "s");
    watcher.wait_for_change(std::chrono::milliseconds(kWatchSettleMs));
  }
}

int run(const RenderCommand& c, const CLI::App& cmd, const CommandContext& ctx) {
  const bool frames_flag = cmd.count("--frames") > 0;
  FrameRange flag_range;
  if (frames_flag) {
    if (std::string err = parse_frame_range(c.frames, flag_range); !err.empty())
      throw CLI::ValidationError("--frames", err);
  }
  TaskSlice task;
  std::optional<int64_t> task_index, task_count;
  if (cmd.count("--task-index")) task_index = c.task_index;
  if (cmd.count("--task-count")) task_count = c.task_count;
  if (std::string err = resolve_task(task_index, task_count, task); !err.empty())
    throw CLI::ValidationError("--task-index/--task-count", err);

  std::string out = c.output;
  if (out.empty()) out = frames_flag ? default_frame_pattern(c.scene) : fs::path(c.scene).stem().string() + ".png";
  // A usage error, before any work: never write one format's bytes under another's name.
  const std::optional<render::VideoFormat> video = render::video_format_for_path(out);
  render::OutputSpecResult spec;
  if (video) {
    spec.spec = render::OutputSpec{};
    if (!c.aovs.empty()) throw CLI::ValidationError("--aov", "AOVs are images: render the frames to a '#' pattern for them");
    if (task.count > 1 || c.skip_existing)
      throw CLI::ValidationError("--output", "a video is made by one process in one go: render frames to a '#' "
                                             "pattern to split or resume them");
    if (cmd.count("--bits") || c.linear) throw CLI::ValidationError("--bits/--linear", "apply to image files, not video");
  } else {
    spec = render::output_spec(out, c.bits, c.linear, c.aov_files);
    if (!spec.spec) throw CLI::ValidationError("--output", spec.error);
  }
  if (!c.depth_range.empty() && !(std::isfinite(c.depth_range[0]) && std::isfinite(c.depth_range[1]) &&
                                  c.depth_range[0] <= c.depth_range[1]))
    throw CLI::ValidationError("--depth-range", "expects two finite numbers NEAR,FAR with NEAR <= FAR");
  if (!std::isfinite(c.depth_miss) || !std::isfinite(c.normal_miss))
    throw CLI::ValidationError("--depth-miss/--normal-miss", "expects a finite number");
  if (frames_flag && flag_range.count() > 1 && !video && !has_frame_pattern(out))
    throw CLI::ValidationError("--output", fmt::format("'{}' has no '#' run for the frame number: with several "
                                                       "frames, name them like out/ball_####.png", out));

  const dist::MpiSession& mpi = *ctx.mpi;
  // --tile-log alone runs a still through the same tile queue, on one process.
  const bool distributed = mpi.active() || !c.checkpoint.empty() || !c.tile_log.empty();
  // An output that cannot be written fails now, not after the evaluation and the render (the
  // first frame's folder stands for the others; a video's file is written whole at the end).
  if (!distributed) {
    try {
      check_output_writable(video || !has_frame_pattern(out) ? out
                                                             : frame_path(out, frames_flag ? flag_range.first : 0));
    } catch (const render::RenderError& e) {
      std::cerr << "rts: error: " << e.what() << "\n";
      return kExitRenderError;
    }
  }
  if (c.watch) {
    if (frames_flag || video || task.count > 1 || distributed)
      throw CLI::ValidationError("--watch", "re-renders a still: not with --frames, a video, --task-*, --checkpoint, --tile-log or mpirun");
    return run_watch(c, cmd, ctx, out, *spec.spec);
  }
  if (distributed && (frames_flag || video || task.count > 1))
    throw CLI::ValidationError("--checkpoint/--tile-log/mpirun", "distribute one still; for an animation's frames use "
                                                      "--task-index/--task-count or a Slurm array (docs/scale-out.md)");
  // Under mpirun every rank evaluates the scene; rank 0 alone reports what it finds.
  std::ostringstream rank_messages;
  DiagnosticSink sink(mpi.rank() == 0 ? std::cerr : rank_messages, ctx.color && mpi.rank() == 0);
  // The first evaluation tells whether the scene is an animation (settings.frames).
  AnimationClock probe_clock{0.0, frames_flag ? flag_range.first : 0, frames_flag ? flag_range.count() : 1};
  Evaluated probe;
  {
    EvalOptions eval = c.eval;
    eval.animation = probe_clock;
    int rc = evaluate_scene(c, eval, sink, probe, mpi.active() ? render::ProgressMode::None : progress_mode(c));
    if (mpi.active()) {
      const int root_rc = mpi.from_root(rc);
      if (int all = mpi.agree(rc); all != kExitOk) {
        if (rc != kExitOk && root_rc == kExitOk)  // this rank alone failed: it names itself
          std::cerr << fmt::format("rts: rank {}: {}", mpi.rank(), rank_messages.str());
        return rc != kExitOk ? rc : all;
      }
    } else if (rc != kExitOk) {
      return rc;
    }
  }
  // settings { output_gamma = "linear" } (an imported POV-Ray scene without assumed_gamma 1.0)
  // is --linear written in the scene.
  if (!video && probe.scene.settings.output_linear) spec.spec->linear = true;
  const int64_t scene_frames = probe.scene.settings.frames;
  if (distributed) {
    if (scene_frames > 1)
      throw CLI::ValidationError("--checkpoint/mpirun", "the scene is an animation (settings.frames): distribute its "
                                                        "frames with --task-index/--task-count or a Slurm array");
    return run_distributed(c, cmd, ctx, out, *spec.spec, probe, sink);
  }
  if (!frames_flag && scene_frames == 1 && !video) {
    if (task.count > 1)
      throw CLI::ValidationError("--task-index/--task-count",
                                 "splits an animation's frames: give --frames or settings { frames = N }");
    // A still, as rts always rendered it.
    return render_scene(c, cmd, probe, has_frame_pattern(out) ? frame_path(out, 0) : out, *spec.spec, sink, nullptr);
  }

  // The animation: the scene's own frames (--frames then picks some of them; the clock still
  // runs over the whole animation, so a frame looks the same whichever range renders it), or
  // the --frames range.
  FrameRange animation = flag_range, selected = flag_range;
  if (scene_frames > 1) {
    animation = FrameRange{0, scene_frames - 1};
    if (!frames_flag) {
      selected = animation;
    } else if (flag_range.last > animation.last) {
      std::cerr << fmt::format("rts: error: --frames {} goes past the scene's last frame {} (settings.frames = {})\n",
                               c.frames, animation.last, scene_frames);
      return kExitUsage;
    }
  }
  if (video) return run_video(c, cmd, ctx, out, *video, animation, selected, std::move(probe), probe_clock, sink);
  if (c.output.empty()) out = default_frame_pattern(c.scene);
  if (selected.count() > 1 && !has_frame_pattern(out))
    throw CLI::ValidationError("--output", fmt::format("'{}' has no '#' run for the frame number: the scene is an "
                                                       "animation of {} frames; name them like out/ball_####.png",
                                                       out, animation.count()));
  return run_frames(c, cmd, ctx, out, *spec.spec, animation, selected, task, std::move(probe), probe_clock, sink);
}

}  // namespace

void add_render_command(CLI::App& app, CommandContext& ctx) {
  auto c = std::make_shared<RenderCommand>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to an image (PNG, PFM or EXR)");
  cmd->add_option("scene", c->scene, "The scene file (.rts, or a POV-Ray .pov translated in memory)")->required();
  cmd->add_option("-o,--output", c->output, "Output image: .png, .pfm or .exr, by extension (default: the scene's name with .png, here); "
                  "an animation's frames: a '#' pattern (out/f_####.png) or a video (.mp4, .webm)")
      ->check(CLI::Validator([](std::string& s) { return s.empty() ? std::string("the file name is empty") : ""; },
                             ""));
  // Whole numbers in a stated range: "-1" or "99999999999999999999" are usage errors.
  add_whole_option(*cmd, "--threads", c->threads, 0, kMaxThreads, "Worker threads (default 0: all cores)", false);
  add_whole_option(*cmd, "--seed", c->seed, 0, kMaxSeed, "Random seed (overrides the scene's settings.seed)", false);
  add_whole_option(*cmd, "--width", c->width, 1, kMaxImageSide, "Image width in pixels", false);
  add_whole_option(*cmd, "--height", c->height, 1, kMaxImageSide, "Image height in pixels", false);
  add_whole_option(*cmd, "--samples", c->samples, 1, render::kMaxSamplesPerPixel, "Samples per pixel", false);
  add_whole_option(*cmd, "--max-depth", c->max_depth, 0, INT_MAX, "Reflection/refraction depth", false);
  cmd->add_option("--aov", c->aovs,
                  "Extra images: normal,depth,albedo,error,error_map (written as OUT.<name>.<ext>; error_map: "
                  "relative error in false colour)")
      ->delimiter(',')
      ->check(CLI::IsMember({"normal", "depth", "albedo", "error", "error_map"}));
  cmd->add_option("--sampler", c->sampler, "Sample placement: random, stratified or sobol")
      ->check(CLI::IsMember({"random", "stratified", "sobol"}));
  cmd->add_option("--integrator", c->integrator,
                  "whitted (ray tracing) or path (path tracing, docs/path-tracing.md); overrides settings.integrator")
      ->check(CLI::IsMember({"whitted", "path"}));
  cmd->add_option("--target-error", c->target_error,
                  "Adaptive: sample until the estimated RMSE is at most this (--samples is the cap)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--time-limit", c->time_limit, "Stop adding samples after this many seconds")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--bits", c->bits, "Bits per channel: png 8 (default) or 16; exr 32 (default) or 16 (half)")
      ->check(CLI::IsMember({8, 16, 32}));
  cmd->add_flag("--strict", c->strict, "A POV-Ray scene (.pov): what rts cannot express is an error, not a warning");
  cmd->add_flag("--linear", c->linear, "PNG: store linear values, not sRGB (as the courses do)");
  cmd->add_flag("--aov-files", c->aov_files, "EXR: write AOVs as separate files, not layers");
  cmd->add_option("--depth-range", c->depth_range, "Depth AOV: NEAR,FAR map linearly to black..white")
      ->delimiter(',')
      ->expected(2)
      ->check(CLI::Number);
  cmd->add_option("--depth-miss", c->depth_miss, "Depth AOV value where nothing is hit (default 0)");
  cmd->add_option("--normal-miss", c->normal_miss, "Normal AOV value where nothing is hit (default 0)");
  cmd->add_flag("--no-progress", c->no_progress, "Never show progress (as --progress=none)");
  cmd->add_option("--progress", c->progress,
                  "Progress of evaluation, build and render on stderr: auto (a bar when stderr is a terminal, "
                  "else nothing), bar, lines (plain lines, for logs), none")
      ->check(CLI::IsMember({"auto", "bar", "lines", "none"}));
  cmd->add_flag("--stats", c->stats.print, "Print features used and left out, rays, memory and time per phase");
  cmd->add_option("--stats-json", c->stats.json_path, "Write the same figures as JSON to FILE ('-': stdout)");
  cmd->add_flag("--no-specialize", c->no_specialize, "Render through the generic path (for benchmarks)");
  cmd->add_option("--frames", c->frames,
                  "Animation: render frames A..B (both included; or one frame N) to -o's '#' pattern "
                  "(default: settings.frames)");
  add_whole_option(*cmd, "--task-index", c->task_index, 0, render::kMaxFrames,
                   "Animation: this task's index among --task-count (default: SLURM_ARRAY_TASK_ID)", false);
  add_whole_option(*cmd, "--task-count", c->task_count, 1, render::kMaxFrames,
                   "Animation: render every N-th frame of the range, from --task-index", false);
  cmd->add_option("--checkpoint", c->checkpoint,
                  "Journal finished tiles in DIR; the same command resumes there after a crash (stills; mpirun too)");
  cmd->add_option("--tile-log", c->tile_log,
                  "Still: write each tile's rank, seconds and size as JSON Lines to FILE (docs/scale-out.md)");
  add_whole_option(*cmd, "--fps", c->fps, 1, 1000, "Video (-o .mp4/.webm): frames per second (default 24)", false);
  cmd->add_flag("--watch", c->watch,
                "Render again whenever the scene or a file it includes or reads changes (1 sample per pixel "
                "first, then the full render); a failing change keeps the last good image");
  cmd->add_flag("--skip-existing", c->skip_existing, "Animation: skip frames whose image is already written");
  cmd->add_option("--manifest", c->manifest,
                  "Animation: JSON Lines file of rendered frames (default: OUT-without-####.manifest.jsonl)");
  add_eval_options(*cmd, c->eval);
  cmd->callback([c, cmd, &ctx] { ctx.exit_code = run(*c, *cmd, ctx); });
}

}  // namespace rts::cli
