// libFuzzer harness: a whole tiny render. Parse + evaluate with the default limits, then render
// at 4x3 pixels on one thread. Every input renders an image with finite pixels or fails with a
// LanguageError / SceneError / RenderError, as `rts render` reports them.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "render/renderer.hpp"
#include "runtime/evaluator.hpp"

namespace {
constexpr int kWidth = 4, kHeight = 3;
// Samples and depth are capped so one input stays a few milliseconds: the scene's settings are
// still parsed and checked, only the work per pixel is bounded (caps on both are budget items
// of their own, tested in the normal suite).
constexpr int kMaxSamples = 4;
constexpr int kMaxDepth = 8;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::string text;
  if (!rts::fuzz::scene_text(data, size, text)) return -1;
  const std::string path = (rts::fuzz::work_dir() / "fuzz.rts").string();
  rts::SourceManager sources;
  const rts::SourceFile* file = sources.add(path, std::move(text));
  rts::DiagnosticSink warnings(rts::fuzz::null_stream());
  rts::render::SceneDesc scene;
  try {
    scene = rts::evaluate_source(sources, *file, rts::fuzz::eval_options(), warnings).scene;
  } catch (const rts::LanguageError& e) {
    rts::fuzz::check_error(e);
    return 0;
  } catch (const rts::SourceError&) {
    return 0;
  } catch (const rts::render::SceneError&) {
    return 0;
  }
  rts::render::RenderOptions options;
  options.threads = 1;
  options.width = kWidth;
  options.height = kHeight;
  options.samples = std::clamp(scene.settings.samples, 1, kMaxSamples);
  options.max_depth = std::clamp(scene.settings.max_depth, 0, kMaxDepth);
  try {
    rts::render::RenderResult result = rts::render::render(scene, options);
    if (result.color.width != kWidth || result.color.height != kHeight) std::abort();
    for (float v : result.color.rgb)
      if (std::isnan(v)) std::abort();  // "never NaN"
  } catch (const rts::render::RenderError& e) {
    if (std::string(e.what()).empty()) std::abort();
  }
  return 0;
}
