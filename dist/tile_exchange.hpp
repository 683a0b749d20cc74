// The dynamic work queue of a distributed still: rank 0 hands out tiles one at a time to
// whichever rank asks (and renders too, on a thread of its own), so fast machines take more
// tiles and nobody idles while work remains; finished tiles travel back whole and are stored in
// rank 0's image (and journal, with --checkpoint) as they arrive. A tile's identity and content
// never depend on the rank count, so the image is the same bytes for any N (docs/scale-out.md).
// Without MPI (one process with --checkpoint) the same queue runs with rank 0 alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dist/checkpoint.hpp"
#include "dist/mpi_session.hpp"
#include "render/renderer.hpp"

namespace rts::dist {

// One tile as rank 0 received it: for --tile-log and bench/simulate_ranks.py.
struct TileRecord {
  int unit;            // round × tiles + tile
  int rank;            // that rendered it
  double seconds;      // rendering it there (wall time of its threads)
  std::size_t bytes;   // its payload
};

struct ExchangeStats {
  int tiles = 0;                   // in the image (summed over the rounds of a progressive render)
  int rounds = 0;                  // 1, or a progressive render's passes and adaptive rounds
  int skipped = 0;                 // tiles a round left alone (nothing to add, or out of time)
  int from_checkpoint = 0;         // read back from the journal instead of rendered
  int rendered_here = 0;           // by this process
  int rendered_remote = 0;         // gathered from other ranks (root only)
  uint64_t bytes_received = 0;     // tile payloads gathered (root only)
  // Rank 0's main thread: time receiving, storing and journaling other ranks' tiles, and
  // answering requests — the serial part that bounds how many ranks one root can feed.
  double fold_seconds = 0, serve_seconds = 0;
  double render_seconds_here = 0;  // rendering tiles on this process (its rendering thread)
  std::vector<TileRecord> log;     // every tile stored, in arrival order (root only; not the checkpoint's)
};

class TileQueueExchange final : public render::TileExchange {
 public:
  // `checkpoint`: rank 0's journal, or null. Both must outlive run().
  TileQueueExchange(const MpiSession& mpi, Checkpoint* checkpoint) : mpi_(mpi), checkpoint_(checkpoint) {}
  void run(const Round& round, const RenderTile& render_tile, const StoreTile& store_tile) override;
  bool another_round(bool more) override { return mpi_.from_root(more ? 1 : 0) != 0; }
  bool root() const override { return mpi_.rank() == 0; }
  const ExchangeStats& stats() const { return stats_; }

 private:
  void run_root(const Round& round, const RenderTile& render_tile, const StoreTile& store_tile);
  void run_worker(const RenderTile& render_tile);

  const MpiSession& mpi_;
  Checkpoint* checkpoint_;
  ExchangeStats stats_;
};

}  // namespace rts::dist
