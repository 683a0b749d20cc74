#include "dist/tile_exchange.hpp"

#include <atomic>
#include <chrono>
#include <cstring>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include <fmt/format.h>

#ifdef RTS_HAVE_MPI
#include <mpi.h>
#endif

#include "render/scene/source_ref.hpp"

namespace rts::dist {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Message tags: a worker asks for work, rank 0 assigns a tile (-1: no more), a worker returns
// a finished tile (its number, then its payload).
constexpr int kTagRequest = 1, kTagAssign = 2, kTagResult = 3;

}  // namespace

void TileQueueExchange::run(const Round& round, const RenderTile& render_tile, const StoreTile& store_tile) {
  stats_.tiles += round.tile_count;
  ++stats_.rounds;
  if (mpi_.rank() == 0)
    run_root(round, render_tile, store_tile);
  else
    run_worker(render_tile);
}

void TileQueueExchange::run_root(const Round& round, const RenderTile& render_tile, const StoreTile& store_tile) {
  const int tile_count = round.tile_count;
  std::vector<char> stored(static_cast<std::size_t>(tile_count), 0);
  if (checkpoint_) {
    // A one-pass render's journal holds units 0..tiles-1; a progressive one's, every round's
    // units (round × tiles + tile), read back round by round.
    const bool one_pass = round.prepare == nullptr;
    for (const auto& [unit, payload] : checkpoint_->finished()) {
      if (one_pass && (unit < 0 || unit >= tile_count))
        throw render::RenderError({}, fmt::format("checkpoint '{}' holds tile {} of an image of {} tiles",
                                                  checkpoint_->path(), unit, tile_count));
      if (unit < round.first_unit || unit >= round.first_unit + tile_count) continue;
      const int tile = unit - round.first_unit;
      store_tile(tile, payload);
      stored[static_cast<std::size_t>(tile)] = 1;
      ++stats_.from_checkpoint;
    }
  }
  std::vector<int> todo;
  for (int t = 0; t < tile_count; ++t)
    if (!stored[static_cast<std::size_t>(t)]) todo.push_back(t);

  std::mutex mutex;  // guards next, done_here, local_error and the prepare calls
  std::size_t next = 0;
  // Tiles not yet stored; a skipped tile is never stored, so it is counted off when skipped.
  std::atomic<std::size_t> remaining{todo.size()};
  // The next tile to render and its input, or -1 when none is left.
  auto take = [&](std::vector<unsigned char>& input) {
    std::lock_guard lock(mutex);
    while (next < todo.size()) {
      const int t = todo[next++];
      input.clear();
      if (!round.prepare || (*round.prepare)(t, input)) return t;
      ++stats_.skipped;
      --remaining;
    }
    return -1;
  };
  struct Done {
    int tile;
    double seconds;
    std::vector<unsigned char> payload;
  };
  std::deque<Done> done_here;
  std::exception_ptr local_error;
  // Rank 0 renders as well, on a thread of its own, while this thread serves the other ranks.
  std::thread local([&] {
    try {
      std::vector<unsigned char> input;
      for (int t = take(input); t >= 0; t = take(input)) {
        std::vector<unsigned char> payload;
        const auto start = std::chrono::steady_clock::now();
        render_tile(t, input, payload);
        const double seconds = seconds_since(start);
        std::lock_guard lock(mutex);
        stats_.render_seconds_here += seconds;
        done_here.push_back({t, seconds, std::move(payload)});
      }
    } catch (...) {
      std::lock_guard lock(mutex);
      local_error = std::current_exception();
      next = todo.size();  // no more work for anyone
    }
  });

  int workers = mpi_.active() ? mpi_.size() - 1 : 0;
  auto keep = [&](int tile, const std::vector<unsigned char>& payload, int rank, double seconds) {
    stats_.log.push_back({round.first_unit + tile, rank, seconds, payload.size()});
    store_tile(tile, payload);
    if (checkpoint_) checkpoint_->append(round.first_unit + tile, payload);
    --remaining;
  };
  try {
    while (remaining > 0 || workers > 0) {
      bool busy = false;
      std::deque<Done> mine;
      {
        std::lock_guard lock(mutex);
        mine.swap(done_here);
        if (local_error) break;
      }
      for (const Done& d : mine) {
        keep(d.tile, d.payload, 0, d.seconds);
        ++stats_.rendered_here;
        busy = true;
      }
#ifdef RTS_HAVE_MPI
      if (workers > 0) {
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
        const auto start = std::chrono::steady_clock::now();
        if (flag && st.MPI_TAG == kTagRequest) {
          int unused = 0;
          MPI_Recv(&unused, 1, MPI_INT, st.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          std::vector<unsigned char> input;
          int tile = take(input);
          std::vector<unsigned char> msg(sizeof tile + input.size());
          std::memcpy(msg.data(), &tile, sizeof tile);
          if (!input.empty()) std::memcpy(msg.data() + sizeof tile, input.data(), input.size());
          MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_BYTE, st.MPI_SOURCE, kTagAssign, MPI_COMM_WORLD);
          if (tile < 0) --workers;
          busy = true;
          stats_.serve_seconds += seconds_since(start);
        } else if (flag && st.MPI_TAG == kTagResult) {
          int bytes = 0;
          MPI_Get_count(&st, MPI_BYTE, &bytes);
          std::vector<unsigned char> msg(static_cast<std::size_t>(bytes));
          MPI_Recv(msg.data(), bytes, MPI_BYTE, st.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          // The tile's number, the seconds it took there, its payload.
          int tile = -1;
          double seconds = 0;
          constexpr std::size_t kHead = sizeof tile + sizeof seconds;
          if (msg.size() >= kHead) {
            std::memcpy(&tile, msg.data(), sizeof tile);
            std::memcpy(&seconds, msg.data() + sizeof tile, sizeof seconds);
          }
          if (tile < 0 || tile >= tile_count)
            throw render::RenderError({}, fmt::format("rank {} sent a tile that is not in the image", st.MPI_SOURCE));
          keep(tile, std::vector<unsigned char>(msg.begin() + kHead, msg.end()), st.MPI_SOURCE, seconds);
          ++stats_.rendered_remote;
          stats_.bytes_received += msg.size();
          busy = true;
          stats_.fold_seconds += seconds_since(start);
        }
      }
#endif
      if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  } catch (...) {
    {
      std::lock_guard lock(mutex);
      next = todo.size();
    }
    local.join();
    throw;
  }
  local.join();
  if (local_error) std::rethrow_exception(local_error);
  if (checkpoint_) checkpoint_->sync();
}

void TileQueueExchange::run_worker(const RenderTile& render_tile) {
#ifdef RTS_HAVE_MPI
  for (;;) {
    int ask = 0, tile = -1;
    MPI_Send(&ask, 1, MPI_INT, 0, kTagRequest, MPI_COMM_WORLD);
    // The assignment: the tile's number, then its input (empty for a one-pass render).
    MPI_Status st;
    MPI_Probe(0, kTagAssign, MPI_COMM_WORLD, &st);
    int bytes = 0;
    MPI_Get_count(&st, MPI_BYTE, &bytes);
    std::vector<unsigned char> assign(static_cast<std::size_t>(bytes));
    MPI_Recv(assign.data(), bytes, MPI_BYTE, 0, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (assign.size() < sizeof tile) throw render::RenderError({}, "rank 0 sent a malformed tile assignment");
    std::memcpy(&tile, assign.data(), sizeof tile);
    if (tile < 0) break;
    const std::vector<unsigned char> input(assign.begin() + sizeof tile, assign.end());
    std::vector<unsigned char> payload;
    const auto start = std::chrono::steady_clock::now();
    render_tile(tile, input, payload);
    const double seconds = seconds_since(start);
    stats_.render_seconds_here += seconds;
    std::vector<unsigned char> msg(sizeof tile + sizeof seconds + payload.size());
    std::memcpy(msg.data(), &tile, sizeof tile);
    std::memcpy(msg.data() + sizeof tile, &seconds, sizeof seconds);
    std::memcpy(msg.data() + sizeof tile + sizeof seconds, payload.data(), payload.size());
    MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_BYTE, 0, kTagResult, MPI_COMM_WORLD);
    ++stats_.rendered_here;
  }
#else
  (void)render_tile;
#endif
}

}  // namespace rts::dist
