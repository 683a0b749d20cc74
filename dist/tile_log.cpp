#include "dist/tile_log.hpp"

#include <iterator>
#include <vector>

#include <fmt/format.h>

#include "render/image/atomic_file.hpp"

namespace rts::dist {

void write_tile_log(const std::string& path, const ExchangeStats& x, int ranks, int tiles_per_round,
                    const render::RenderStats& stats) {
  fmt::memory_buffer out;
  for (const TileRecord& r : x.log)
    fmt::format_to(std::back_inserter(out),
                   "{{\"unit\": {}, \"round\": {}, \"tile\": {}, \"rank\": {}, \"seconds\": {:.9g}, \"bytes\": {}}}\n",
                   r.unit, r.unit / tiles_per_round, r.unit % tiles_per_round, r.rank, r.seconds, r.bytes);
  // Start-up is every rank's own (each evaluates the scene and builds its BVH): rank 0's
  // figures stand for all.
  fmt::format_to(std::back_inserter(out),
                 "{{\"summary\": {{\"ranks\": {}, \"threads\": {}, \"tiles_per_round\": {}, \"rounds\": {}, "
                 "\"tiles\": {}, \"from_checkpoint\": {}, \"rendered_remote\": {}, \"serve_seconds\": {:.9g}, "
                 "\"fold_seconds\": {:.9g}, \"bytes_received\": {}, \"eval_seconds\": {:.9g}, "
                 "\"build_seconds\": {:.9g}, \"render_seconds\": {:.9g}}}}}\n",
                 ranks, stats.threads, tiles_per_round, x.rounds, x.tiles, x.from_checkpoint, x.rendered_remote,
                 x.serve_seconds, x.fold_seconds, x.bytes_received, stats.eval_seconds, stats.build_seconds,
                 stats.render_seconds);
  render::write_file_atomically(path, std::vector<unsigned char>(out.data(), out.data() + out.size()));
}

}  // namespace rts::dist
