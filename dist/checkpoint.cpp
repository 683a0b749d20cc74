#include "dist/checkpoint.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "render/scene/source_ref.hpp"

namespace rts::dist {
namespace {

constexpr char kMagic[8] = {'R', 'T', 'S', 'C', 'K', 'P', 'T', '1'};
constexpr uint32_t kRecordMagic = 0x54494C45;  // "TILE"
constexpr uint64_t kMaxRecord = uint64_t(1) << 32;

uint64_t fnv1a64(const unsigned char* p, std::size_t n, uint64_t h = 0xcbf29ce484222325ull) {
  for (std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 0x100000001b3ull;
  }
  return h;
}

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw render::RenderError({}, fmt::format("checkpoint '{}': {}", path, why));
}

template <typename T>
bool read_value(std::FILE* f, T& v) {
  return std::fread(&v, sizeof v, 1, f) == 1;
}

}  // namespace

Checkpoint::Checkpoint(const std::string& dir, const std::string& key) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) fail(dir, "cannot make the folder: " + ec.message());
  path_ = (std::filesystem::path(dir) / "rts-checkpoint.journal").string();
  std::FILE* f = std::fopen(path_.c_str(), "rb");
  long good_end = 0;
  if (f) {
    char magic[8];
    uint64_t key_size = 0;
    std::string stored;
    if (std::fread(magic, 1, 8, f) != 8 || std::memcmp(magic, kMagic, 8) != 0 || !read_value(f, key_size) ||
        key_size > (1u << 20)) {
      std::fclose(f);
      fail(path_, "not an rts checkpoint journal (delete it, or give another --checkpoint folder)");
    }
    stored.resize(key_size);
    if (std::fread(stored.data(), 1, key_size, f) != key_size) {
      std::fclose(f);
      fail(path_, "its header is cut short (delete it to start over)");
    }
    if (stored != key) {
      std::fclose(f);
      fail(path_, "it was made for another scene or other options, so its tiles do not belong to this image "
                  "(delete it, or give another --checkpoint folder)\n  journal: " + stored + "\n  this run: " + key);
    }
    good_end = std::ftell(f);
    for (;;) {
      uint32_t magic_r = 0;
      int32_t tile = 0;
      uint64_t size = 0, sum = 0;
      if (!read_value(f, magic_r) || magic_r != kRecordMagic || !read_value(f, tile) || !read_value(f, size) ||
          size > kMaxRecord || tile < 0)
        break;
      std::vector<unsigned char> payload(size);
      if (std::fread(payload.data(), 1, size, f) != size || !read_value(f, sum) ||
          sum != fnv1a64(payload.data(), payload.size()))
        break;
      finished_[tile] = std::move(payload);
      good_end = std::ftell(f);
    }
    std::fseek(f, 0, SEEK_END);
    torn_bytes_ = static_cast<std::size_t>(std::ftell(f) - good_end);
    std::fclose(f);
    if (torn_bytes_ > 0 && ::truncate(path_.c_str(), good_end) != 0) fail(path_, std::strerror(errno));
    file_ = std::fopen(path_.c_str(), "ab");
    if (!file_) fail(path_, std::strerror(errno));
  } else {
    file_ = std::fopen(path_.c_str(), "wb");
    if (!file_) fail(path_, std::strerror(errno));
    const uint64_t key_size = key.size();
    if (std::fwrite(kMagic, 1, 8, file_) != 8 || std::fwrite(&key_size, sizeof key_size, 1, file_) != 1 ||
        std::fwrite(key.data(), 1, key.size(), file_) != key.size())
      fail(path_, std::strerror(errno));
    sync();
  }
  last_sync_ = now_seconds();
}

Checkpoint::~Checkpoint() {
  if (file_) {
    std::fflush(file_);
    ::fsync(fileno(file_));
    std::fclose(file_);
  }
}

void Checkpoint::append(int tile, const std::vector<unsigned char>& payload) {
  const uint32_t magic = kRecordMagic;
  const int32_t t = tile;
  const uint64_t size = payload.size(), sum = fnv1a64(payload.data(), payload.size());
  if (std::fwrite(&magic, sizeof magic, 1, file_) != 1 || std::fwrite(&t, sizeof t, 1, file_) != 1 ||
      std::fwrite(&size, sizeof size, 1, file_) != 1 ||
      std::fwrite(payload.data(), 1, payload.size(), file_) != payload.size() ||
      std::fwrite(&sum, sizeof sum, 1, file_) != 1)
    fail(path_, std::strerror(errno));
  // Half a second of tiles at most is lost in a crash; a record cut short is dropped on resume.
  if (now_seconds() - last_sync_ >= 0.5) sync();
}

void Checkpoint::sync() {
  if (std::fflush(file_) != 0 || ::fsync(fileno(file_)) != 0) fail(path_, std::strerror(errno));
  last_sync_ = now_seconds();
}

}  // namespace rts::dist
