// What `rts render` is made of, shared by its files: the command's options (RenderCommand), an
// evaluated scene (Evaluated), and the steps every mode goes through — evaluate, render one still
// and write it (cli/render_still.cpp) — and the modes built on them: a distributed still (same
// file), an animation's frames, a video and --watch (cli/render_sequence.cpp). The command
// line itself and the choice of mode are in cli/cmd_render.cpp.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/eval_options.hpp"
#include "cli/frames.hpp"
#include "cli/stats_report.hpp"
#include "dist/mpi_session.hpp"
#include "parser/diagnostics.hpp"
#include "render/image/image_output.hpp"
#include "render/image/video_writer.hpp"
#include "render/progress.hpp"
#include "render/renderer.hpp"

namespace CLI {
class App;
}
namespace rts::dist {
class TileQueueExchange;
}

namespace rts::cli {

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
  std::string ini;      // a POV-Ray scene: its .ini file (Width, Height, Antialias)
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

// The scene evaluated at one point of the animation clock, with the sources its locations
// point into.
struct Evaluated {
  std::unique_ptr<SourceManager> sources = std::make_unique<SourceManager>();
  render::SceneDesc scene;
  double eval_seconds = 0, parse_seconds = 0;
  bool uses_clock = false;
};

// How long work shows itself on stderr: --progress (auto: a bar on a terminal, else nothing).
render::ProgressMode progress_mode(const RenderCommand& c);

// Fails early (before evaluating or rendering) with a RenderError when the output folder cannot
// take the file.
void check_output_writable(const std::string& out);

// Evaluates the scene (a POV-Ray scene is translated in memory first); on failure reports the
// located error and returns its exit code.
int evaluate_scene(const RenderCommand& c, const EvalOptions& eval_in, DiagnosticSink& sink, Evaluated& out,
                   render::ProgressMode progress = render::ProgressMode::None);

// Whether render_scene may take the evaluated scene: its shapes and graph are then released
// once the world holds them (a large scene's peak without its description) and ev.scene is left
// empty. Kept: the caller renders the same evaluation again (the watch mode's quick pass).
enum class SceneAfterRender : uint8_t { Released, Kept };

// Renders an evaluated scene and writes its images to `out`; `stats_out` receives the figures.
// With `video`, the image goes to the video instead of a file (AOVs are refused earlier).
int render_scene(const RenderCommand& c, const CLI::App& cmd, Evaluated& ev, const std::string& out,
                 const render::OutputSpec& spec, DiagnosticSink& sink, render::RenderStats* stats_out,
                 render::VideoWriter* video = nullptr, const Distribution* dist = nullptr,
                 SceneAfterRender after = SceneAfterRender::Released);

// A still over mpirun's ranks and/or with a checkpoint journal.
int run_distributed(const RenderCommand& c, const CLI::App& cmd, const CommandContext& ctx, const std::string& out,
                    const render::OutputSpec& spec, Evaluated& ev, DiagnosticSink& sink);

// An animation's frames this process is given, each evaluated afresh at its clock.
int run_frames(const RenderCommand& c, const CLI::App& cmd, const CommandContext& ctx, const std::string& pattern,
               const render::OutputSpec& spec, const FrameRange& animation, const FrameRange& selected,
               const TaskSlice& task, Evaluated probe, const AnimationClock& probe_clock, DiagnosticSink& sink);

// The frames in order into one video file (written whole at the end, or not at all).
int run_video(const RenderCommand& c, const CLI::App& cmd, const CommandContext& ctx, const std::string& out,
              render::VideoFormat format, const FrameRange& animation, const FrameRange& selected, Evaluated probe,
              const AnimationClock& probe_clock, DiagnosticSink& sink);

// --watch: the still, then again whenever the scene or a file it includes or reads changes.
int run_watch(const RenderCommand& c, const CLI::App& cmd, const CommandContext& ctx, const std::string& out,
              const render::OutputSpec& spec);

}  // namespace rts::cli
