// `rts render SCENE.rts [-o OUT.png|.pfm|.exr] ...`: evaluate the scene, render it, write the
// image(s). Nothing is written unless evaluation and rendering both succeed; each file is
// written atomically, so a failure never truncates an existing image.
//
// This file holds the command line and the choice of mode; cli/render_still.cpp evaluates,
// renders and writes one still, cli/render_sequence.cpp renders frames, videos and --watch.
#include <climits>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "cli/command.hpp"
#include "cli/number_flags.hpp"
#include "cli/render_command.hpp"
#include "dist/mpi_session.hpp"

namespace rts::cli {
namespace {

namespace fs = std::filesystem;

constexpr uint64_t kMaxThreads = 1024;
constexpr uint64_t kMaxSeed = uint64_t(1) << 53;  // as settings.seed: every seed a double holds exactly
constexpr uint64_t kMaxImageSide = 1'000'000;      // the pixel count has its own limit

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
  // settings { output_gamma = g } (an imported POV-Ray scene with assumed_gamma g).
  if (!video) spec.spec->power = probe.scene.settings.output_power;
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
  cmd->add_option("--ini", c->ini, "A POV-Ray scene (.pov): its .ini file (Width, Height, Antialias become settings)");
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
