// `rts render`'s modes that render a scene more than once: an animation's frames (each
// evaluated afresh at its clock, docs/scale-out.md), a video, and --watch.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cli/evaluate.hpp"
#include "cli/file_watch.hpp"
#include "cli/manifest.hpp"
#include "cli/render_command.hpp"

namespace rts::cli {

namespace fs = std::filesystem;

namespace {

// --watch: an editor's save is a few events within milliseconds; wait this long for quiet.
constexpr int kWatchSettleMs = 100;

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


// The files a scene read besides its sources: image textures and OBJ meshes.
void add_scene_inputs(const render::SceneDesc& scene, std::vector<std::string>& files) {
  for (const render::TextureDesc& t : scene.textures) {
    files.push_back(t.image_path);
    files.insert(files.end(), t.face_paths.begin(), t.face_paths.end());
  }
  for (const auto& m : scene.meshes) files.push_back(m->source);
}


}  // namespace

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
      render_scene(quick, cmd, ev, out, spec, sink, nullptr, nullptr, nullptr, SceneAfterRender::Kept);
      ev.scene.settings.samples = scene_samples;
      superseded = watcher.changed();
    }
    if (superseded) continue;
    if (ok) render_scene(c, cmd, ev, out, spec, sink, nullptr);
    std::cerr << fmt::format("rts: watching {} file{} for changes (Ctrl-C stops)\n", watched, watched == 1 ? "" : "s");
    watcher.wait_for_change(std::chrono::milliseconds(kWatchSettleMs));
  }
}

}  // namespace rts::cli
