// Rendering a SceneDesc to images. The CLI calls render() then write_png().
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/image/render_result.hpp"
#include "render/progress.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

// Distribution (dist/): which tiles this process renders, and the gathering of the others'.
// A tile's pixels travel whole (their values, variances, sample counts, AOVs and ray counts),
// so the image does not depend on which process rendered which tile.
class TileExchange {
 public:
  // Root only: what rendering `tile` needs in this round (empty for a one-pass render, the
  // tile's sample sums and the samples to add for a progressive one); false skips the tile
  // this round (nothing to add, or out of time).
  using PrepareTile = std::function<bool(int tile, std::vector<unsigned char>& input)>;
  using RenderTile =
      std::function<void(int tile, const std::vector<unsigned char>& input, std::vector<unsigned char>& payload)>;
  using StoreTile = std::function<void(int tile, const std::vector<unsigned char>& payload)>;
  // One round of work: `tile_count` tiles, known to checkpoints as units first_unit + tile (a
  // progressive render's rounds number their units apart, so a resume finds each round's).
  struct Round {
    int first_unit = 0;
    int tile_count = 0;
    const PrepareTile* prepare = nullptr;  // null: every tile, with an empty input
  };
  virtual ~TileExchange() = default;
  // Renders a round's tiles among the processes: `render_tile` renders a tile here and packs
  // it; `store_tile` unpacks a tile (from here, another process or a checkpoint) into this
  // process's image and statistics. Returns when the root has stored every tile, or when a
  // worker has no more work.
  virtual void run(const Round& round, const RenderTile& render_tile, const StoreTile& store_tile) = 0;
  // Between the rounds of a progressive render: the root passes whether another round follows
  // and every process gets the root's answer back (a collective: every process calls it).
  virtual bool another_round(bool more) = 0;
  // True on the process that gathers the image (the only one whose result is complete).
  virtual bool root() const = 0;
};

struct RenderOptions {
  int threads = 0;                        // 0: all hardware threads
  std::optional<uint64_t> seed;           // overrides settings.seed
  std::optional<int> width, height, samples, max_depth;  // override settings
  std::vector<std::string> aovs;          // any of "normal", "depth", "albedo", "error", "error_map"
  std::optional<SamplerKind> sampler;     // overrides settings.sampler
  std::optional<IntegratorKind> integrator;  // overrides settings.integrator
  // Adaptive sampling: add samples where the estimated error is highest until the image's
  // estimated RMSE is at most this (0: off); `samples` is then the per-pixel maximum.
  double target_error = 0;
  // Stop adding passes after this many seconds of rendering (0: no limit); the image then
  // holds what was rendered (every pixel has at least its first pass) and stats say so.
  double time_limit = 0;
  // The depth AOV maps [near, far] linearly to [0, 1] (clamped) when given, as the courses do;
  // otherwise it scales by the farthest visible depth (see finish_depth).
  std::optional<std::pair<double, double>> depth_range;
  float depth_miss = 0.0f;                // depth AOV value where the camera ray hits nothing
  float normal_miss = 0.0f;               // normal AOV value (every channel) where nothing is hit
  ProgressMode progress = ProgressMode::None;  // feedback on stderr: a bar or plain lines
  bool specialize = true;                 // false: the generic path (--no-specialize)
  std::size_t max_pixels = 100'000'000;   // larger images are a RenderError
  std::size_t max_memory = 0;             // bytes (--max-memory): the image and AOVs must fit; 0: no limit
  // Non-null: the tiles are shared with other processes (mpirun); fixed sample counts only.
  TileExchange* exchange = nullptr;
};

// Throws RenderError (located where possible) for unreadable textures, oversize images...
RenderResult render(const SceneDesc& scene, const RenderOptions& options);
// The same for a scene rendered once: it is taken, and its shapes and graph are released once
// the world holds them, before the top-level BVH is built (PreparedScene's taking constructor):
// a large scene's peak memory without its description. `scene` is left empty.
RenderResult render(SceneDesc&& scene, const RenderOptions& options);
// The same for a scene prepared beforehand (render/prepared_scene.hpp: built once for many
// renders); it was prepared with its own --no-specialize and --max-memory, which win over
// `options`' ones.
class PreparedScene;
RenderResult render(const PreparedScene& prepared, const RenderOptions& options);

}  // namespace rts::render
