// `rts converge SCENE.rts`: error against render time per sampler. Renders (or reads) a
// reference, then the scene at 1, 2, 4, ... N samples per pixel with each sampler, and records
// wall time, RMSE, relative MSE, PSNR and the render's own error estimate per run; writes
// convergence.csv and log-log SVG plots, prints fitted slopes, an equal-time table and, with
// --adaptive, the time adaptive sampling saves at equal measured error.
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/command.hpp"
#include "cli/eval_options.hpp"
#include "cli/evaluate.hpp"
#include "cli/svg_plot.hpp"
#include "parser/diagnostics.hpp"
#include "render/image/image.hpp"
#include "render/image/image_metrics.hpp"
#include "render/image/float_image_io.hpp"
#include "render/prepared_scene.hpp"
#include "render/renderer.hpp"
#include "render/sample/sampler.hpp"
#include "runtime/evaluator.hpp"

namespace rts::cli {
namespace {

namespace fs = std::filesystem;

struct ConvergeCommand {
  std::string scene, out_dir, reference;
  int reference_samples = 0, min_samples = 1, max_samples = 256;
  std::vector<std::string> samplers{"random", "stratified", "sobol"};
  bool adaptive = false;
  std::string clock = "wall";  // or "cpu": what "time" means in plots, slopes and tables
  std::string integrator;      // "whitted" or "path" overrides settings.integrator
  int threads = 0, width = 0, height = 0;
  uint64_t seed = 0;
  EvalOptions eval;
};

struct Run {
  std::string sampler;  // "random", "stratified", "sobol", "adaptive"
  int spp = 0;          // samples per pixel asked for (the cap when adaptive)
  double mean_spp = 0;  // taken, on average
  double seconds = 0;   // render wall time (after the scene is built)
  double cpu_seconds = 0;  // process CPU time (all threads) of the whole render call
  render::ImageError measured;
  render::ErrorEstimate estimate;
};

double cpu_seconds_now() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out.flush()) throw render::RenderError({}, fmt::format("cannot write '{}'", path.string()));
}

std::string csv(const std::vector<Run>& runs) {
  std::string s = "sampler,spp,mean_spp,seconds,cpu_seconds,rmse,rel_mse,psnr,est_rmse,est_rel_mse,est_over_measured\n";
  for (const Run& r : runs) {
    std::string est = r.estimate.known ? fmt::format("{:.6g},{:.6g},{:.4f}", r.estimate.rmse, r.estimate.rel_mse,
                                                     r.estimate.rmse / r.measured.rmse)
                                       : "n/a,n/a,n/a";
    s += fmt::format("{},{},{:.2f},{:.6f},{:.4f},{:.6g},{:.6g},{:.3f},{}\n", r.sampler, r.spp, r.mean_spp, r.seconds,
                     r.cpu_seconds, r.measured.rmse, r.measured.rel_mse, r.measured.psnr, est);
  }
  return s;
}

std::vector<const Run*> runs_of(const std::vector<Run>& runs, const std::string& sampler) {
  std::vector<const Run*> out;
  for (const Run& r : runs)
    if (r.sampler == sampler) out.push_back(&r);
  return out;
}

std::vector<double> column(const std::vector<const Run*>& rs, double Run::*field) {
  std::vector<double> v;
  for (const Run* r : rs) v.push_back(r->*field);
  return v;
}
std::vector<double> rmse_column(const std::vector<const Run*>& rs) {
  std::vector<double> v;
  for (const Run* r : rs) v.push_back(r->measured.rmse);
  return v;
}

LogLogPlot make_plot(const std::string& scene, const std::vector<Run>& runs, const std::vector<std::string>& names,
                     bool by_time, double Run::*time) {
  LogLogPlot plot;
  const bool cpu = time == &Run::cpu_seconds;
  plot.title = fmt::format("{}: RMSE against {}", scene, by_time ? (cpu ? "CPU time" : "render time") : "samples per pixel");
  plot.x_label = by_time ? (cpu ? "render CPU time, all threads (s)" : "render wall time (s)") : "samples per pixel";
  plot.y_label = "RMSE (linear RGB)";
  double gx = 0, gy = 0, xmin = 1e300, xmax = 0;
  for (const std::string& name : names) {
    std::vector<const Run*> rs = runs_of(runs, name);
    if (rs.empty()) continue;
    PlotSeries s{name, by_time ? column(rs, time) : column(rs, &Run::mean_spp), rmse_column(rs)};
    if (gx == 0 && s.x[0] > 0) gx = s.x[0], gy = s.y[0];
    for (double x : s.x)
      if (x > 0) xmin = std::min(xmin, x), xmax = std::max(xmax, x);
    plot.series.push_back(std::move(s));
  }
  if (gx > 0 && xmax > xmin) {
    // Slope -1/2 through the first run: what independent samples achieve.
    PlotSeries guide{"slope -1/2", {xmin, xmax}, {gy * std::sqrt(gx / xmin), gy * std::sqrt(gx / xmax)}, true};
    plot.series.push_back(guide);
  }
  return plot;
}

render::Image load_reference(const std::string& path) {
  fs::path p(path);
  if (p.extension() == ".pfm") return render::read_pfm(path);
  return render::read_png(path, {}, render::Encoding::SRGB);
}

int run_converge(const ConvergeCommand& c, const CLI::App& cmd, const CommandContext& ctx) {
  SourceManager sources;
  DiagnosticSink sink(std::cerr, ctx.color);
  EvalResult evaluated;
  if (!evaluate_reporting(sources, c.scene, c.eval, sink, evaluated)) return kExitLanguageError;
  const render::SceneDesc scene = std::move(evaluated.scene);
  if (c.max_samples < c.min_samples) {
    std::cerr << "rts: --max-samples must be at least --min-samples\n";
    return kExitUsage;
  }

  render::RenderOptions base;
  base.threads = c.threads;
  if (cmd.count("--seed")) base.seed = c.seed;
  if (cmd.count("--width")) base.width = c.width;
  if (cmd.count("--height")) base.height = c.height;
  if (!c.integrator.empty()) {
    render::IntegratorKind kind = render::IntegratorKind::Whitted;
    render::parse_integrator(c.integrator, kind);  // CLI11 checked the name
    base.integrator = kind;
  }
  const uint64_t seed = base.seed.value_or(scene.settings.seed);
  const std::string name = fs::path(c.scene).stem().string();
  fs::path dir = c.out_dir.empty() ? fs::path(name + "-convergence") : fs::path(c.out_dir);

  try {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (!fs::is_directory(dir)) throw render::RenderError({}, fmt::format("cannot create directory '{}'", dir.string()));

    // Built once (flattening, BVHs, lights, textures): every run below renders the same scene.
    const render::PreparedScene prepared = render::prepare_scene(scene, base);
    render::Image reference;
    if (!c.reference.empty()) {
      reference = load_reference(c.reference);
      std::cerr << fmt::format("converge: reference {} ({}x{})\n", c.reference, reference.width, reference.height);
    } else {
      render::RenderOptions o = base;
      o.samples = c.reference_samples > 0 ? c.reference_samples : 16 * c.max_samples;
      o.seed = render::mix64(seed + 1);  // independent of every run's noise
      o.sampler = render::SamplerKind::Sobol;
      std::cerr << fmt::format("converge: rendering the reference at {} spp...\n", *o.samples);
      render::RenderResult ref = render::render(prepared, o);
      reference = std::move(ref.color);
      render::write_pfm((dir / "reference.pfm").string(), reference);
      std::cerr << fmt::format("converge: reference: {:.2f}s, its own estimated rmse {:.3g} ({})\n",
                               ref.stats.render_seconds, ref.stats.error.rmse, (dir / "reference.pfm").string());
    }

    std::vector<Run> runs;
    auto record = [&](const std::string& label, const render::RenderOptions& o) {
      double cpu_start = cpu_seconds_now();
      render::RenderResult r = render::render(prepared, o);
      Run run{label, *o.samples, r.stats.error.mean_spp, r.stats.render_seconds, cpu_seconds_now() - cpu_start,
              render::image_error(r.color, reference), r.stats.error};
      std::cerr << fmt::format("converge: {:>10} {:>5} spp ({:7.1f} taken) {:8.3f}s  rmse {:.4g}  est. {}\n", label,
                               run.spp, run.mean_spp, run.seconds, run.measured.rmse,
                               run.estimate.known ? fmt::format("{:.4g} ({:+.0f}%)", run.estimate.rmse,
                                                                100 * (run.estimate.rmse / run.measured.rmse - 1))
                                                  : "n/a");
      runs.push_back(run);
      return run;
    };
    for (const std::string& s : c.samplers) {
      render::SamplerKind kind = render::SamplerKind::Sobol;
      render::parse_sampler(s, kind);  // CLI11 checked the name
      for (int n = c.min_samples; n <= c.max_samples; n *= 2) {
        render::RenderOptions o = base;
        o.samples = n;
        o.sampler = kind;
        record(s, o);
      }
    }
    std::vector<std::string> names = c.samplers;
    if (c.adaptive) {
      // Adaptive Sobol aiming at each uniform Sobol run's measured error, allowed 8x its samples.
      std::vector<const Run*> uniform = runs_of(runs, "sobol");
      std::vector<Run> targets;
      for (const Run* u : uniform) targets.push_back(*u);
      if (targets.empty()) std::cerr << "converge: --adaptive needs the sobol sampler in --samplers\n";
      for (const Run& u : targets) {
        if (u.spp < 16) continue;  // below, the first adaptive pass alone already has 8 spp
        render::RenderOptions o = base;
        o.samples = 8 * u.spp;
        o.sampler = render::SamplerKind::Sobol;
        o.target_error = u.measured.rmse;
        record("adaptive", o);
      }
      names.push_back("adaptive");
    }

    write_text(dir / "convergence.csv", csv(runs));
    double Run::*time = c.clock == "cpu" ? &Run::cpu_seconds : &Run::seconds;
    write_text(dir / "convergence.svg", render_svg(make_plot(name, runs, names, true, time)));
    write_text(dir / "convergence-spp.svg", render_svg(make_plot(name, runs, names, false, time)));

    std::cout << fmt::format("{}: fitted slopes of log RMSE (slope -0.5: independent samples)\n", name);
    std::cout << fmt::format("  {:<11} {:>9} {:>9} {:>22}\n", "sampler", "vs time", "vs spp", "est./measured rmse");
    for (const std::string& s : names) {
      std::vector<const Run*> rs = runs_of(runs, s);
      double lo = 1e300, hi = 0;
      for (const Run* r : rs)
        if (r->estimate.known) {
          double q = r->estimate.rmse / r->measured.rmse;
          lo = std::min(lo, q), hi = std::max(hi, q);
        }
      std::cout << fmt::format("  {:<11} {:>9.3f} {:>9.3f} {:>22}\n", s,
                               render::log_log_slope(column(rs, time), rmse_column(rs)),
                               render::log_log_slope(column(rs, &Run::mean_spp), rmse_column(rs)),
                               hi > 0 ? fmt::format("{:.2f} .. {:.2f}", lo, hi) : "n/a");
    }
    // Equal time: each sampler's RMSE interpolated at the times the last sampler took.
    std::vector<const Run*> base_runs = runs_of(runs, c.samplers.back());
    std::cout << fmt::format("equal-time RMSE at {} seconds (log-log interpolation; '-' outside a sampler's "
                             "measured range)\n", c.clock == "cpu" ? "CPU" : "wall");
    std::cout << fmt::format("  {:>10}", "seconds");
    for (const std::string& s : names) std::cout << fmt::format(" {:>11}", s);
    std::cout << "\n";
    for (const Run* b : base_runs) {
      std::cout << fmt::format("  {:>10.4f}", b->*time);
      for (const std::string& s : names) {
        std::vector<const Run*> rs = runs_of(runs, s);
        double e = render::log_log_interpolate(column(rs, time), rmse_column(rs), b->*time);
        std::cout << (std::isnan(e) ? fmt::format(" {:>11}", "-") : fmt::format(" {:>11.4g}", e));
      }
      std::cout << "\n";
    }
    if (c.adaptive) {
      std::vector<const Run*> uniform = runs_of(runs, "sobol");
      std::cout << "adaptive against uniform sobol at equal measured RMSE\n";
      for (const Run* a : runs_of(runs, "adaptive")) {
        double t = render::log_log_interpolate(rmse_column(uniform), column(uniform, time), a->measured.rmse);
        std::cout << fmt::format("  rmse {:.4g}: adaptive {:.3f}s, uniform {}{}\n", a->measured.rmse, a->*time,
                                 std::isnan(t) ? "outside the measured range" : fmt::format("{:.3f}s", t),
                                 std::isnan(t) ? "" : fmt::format(" -> {:.2f}x faster", t / (a->*time)));
      }
    }
    std::cerr << fmt::format("converge: wrote {}/convergence.csv, convergence.svg, convergence-spp.svg\n",
                             dir.string());
  } catch (const render::RenderError& e) {
    std::cerr << "rts: error: " << e.what() << "\n";
    return kExitRenderError;
  }
  return kExitOk;
}

}  // namespace

void add_converge_command(CLI::App& app, CommandContext& ctx) {
  auto c = std::make_shared<ConvergeCommand>();
  CLI::App* cmd = app.add_subcommand("converge", "Measure error against render time per sampler");
  cmd->add_option("scene", c->scene, "The scene file (.rts)")->required();
  cmd->add_option("-o,--output-dir", c->out_dir, "Where to write convergence.csv and the plots (default: <scene>-convergence)");
  cmd->add_option("--reference", c->reference, "Reference image (.pfm, or a 16-bit sRGB .png) instead of rendering one");
  cmd->add_option("--reference-samples", c->reference_samples, "Samples per pixel of the rendered reference (default: 16 x --max-samples)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--min-samples", c->min_samples, "Fewest samples per pixel (default 1)")->check(CLI::PositiveNumber);
  cmd->add_option("--max-samples", c->max_samples, "Most samples per pixel (default 256); doubling from --min-samples")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--samplers", c->samplers, "Samplers to compare (default: random,stratified,sobol)")
      ->delimiter(',')
      ->check(CLI::IsMember({"random", "stratified", "sobol"}));
  cmd->add_option("--clock", c->clock, "Time axis of plots, slopes and tables: wall (default) or cpu (all threads' "
                  "CPU time: steadier on a shared machine)")
      ->check(CLI::IsMember({"wall", "cpu"}));
  cmd->add_flag("--adaptive", c->adaptive, "Also run adaptive sampling (sobol) to each uniform sobol run's error");
  cmd->add_option("--threads", c->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", c->seed, "Random seed (overrides the scene's settings.seed)");
  cmd->add_option("--width", c->width, "Image width in pixels")->check(CLI::PositiveNumber);
  cmd->add_option("--height", c->height, "Image height in pixels")->check(CLI::PositiveNumber);
  cmd->add_option("--integrator", c->integrator, "whitted or path; overrides settings.integrator")
      ->check(CLI::IsMember({"whitted", "path"}));
  add_eval_options(*cmd, c->eval);
  cmd->callback([c, cmd, &ctx] { ctx.exit_code = run_converge(*c, *cmd, ctx); });
}

}  // namespace rts::cli
