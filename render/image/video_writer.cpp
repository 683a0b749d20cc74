#include "render/image/video_writer.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <random>
#include <vector>

#include <fmt/format.h>

#include "render/image/temp_file_guard.hpp"
#include "render/image/video_module_api.h"
#include "render/scene/source_ref.hpp"

namespace rts::render {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw RenderError({}, fmt::format("cannot write video '{}': {}", path, why));
}

std::string lower_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// The video module, loaded once, on first use: $RTS_VIDEO_MODULE, else librts_video.so beside
// the running program, else in ../lib/rts from it (an installed rts).
const rts_video_api* video_api(std::string& why) {
  static std::once_flag once;
  static const rts_video_api* api = nullptr;
  static std::string error;
  std::call_once(once, [] {
    std::vector<std::string> candidates;
    if (const char* env = std::getenv("RTS_VIDEO_MODULE")) candidates.emplace_back(env);
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
      candidates.push_back((exe.parent_path() / "librts_video.so").string());
      candidates.push_back((exe.parent_path().parent_path() / "lib" / "rts" / "librts_video.so").string());
    }
    std::string tried;
    for (const std::string& c : candidates) {
      void* handle = dlopen(c.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        tried += fmt::format("\n  {}: {}", c, dlerror());
        continue;
      }
      using Entry = const rts_video_api* (*)();
      auto entry = reinterpret_cast<Entry>(dlsym(handle, "rts_video_api_v1"));
      if (entry && entry()->version == RTS_VIDEO_API_VERSION) {
        api = entry();
        return;
      }
      tried += fmt::format("\n  {}: not an rts video module of this version", c);
    }
    error = "video output needs rts's video module (librts_video.so, built when FFmpeg's libraries are found)"
            " and it could not be loaded:" + tried;
  });
  why = error;
  return api;
}

}  // namespace

std::optional<VideoFormat> video_format_for_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".mp4") return VideoFormat::Mp4;
  if (ext == ".webm") return VideoFormat::Webm;
  return std::nullopt;
}

struct VideoWriter::State {
  std::string path, temp;
  int width = 0, height = 0;          // of the frames given
  int enc_width = 0, enc_height = 0;  // even
  const rts_video_api* api = nullptr;
  void* encoder = nullptr;
  std::vector<uint8_t> rgb;  // enc_width × enc_height × 3, sRGB
  int frames = 0;
  std::string codec;
  bool finished = false;
  std::unique_ptr<TempFileGuard> guard;

  ~State() {
    if (encoder) api->close(encoder);
    if (!finished && !temp.empty()) ::unlink(temp.c_str());
  }
};

VideoWriter::VideoWriter(const std::string& path, VideoFormat format, int width, int height,
                         const VideoOptions& options)
    : s_(std::make_unique<State>()) {
  State& s = *s_;
  s.path = path;
  s.width = width;
  s.height = height;
  s.enc_width = width + (width & 1);  // 4:2:0 needs even sides
  s.enc_height = height + (height & 1);
  if (options.fps < 1 || options.fps > 1000) fail(path, fmt::format("fps must be from 1 to 1000, got {}", options.fps));
  std::string why;
  s.api = video_api(why);
  if (!s.api) fail(path, why);
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  s.temp = fmt::format("{}.tmp-{}-{:016x}", path, static_cast<long>(getpid()), rng());
  s.guard = std::make_unique<TempFileGuard>(s.temp);
  char err[512] = {};
  s.encoder = s.api->open(s.temp.c_str(), format == VideoFormat::Mp4 ? 0 : 1, s.enc_width, s.enc_height, options.fps,
                          options.quality, err, sizeof err);
  if (!s.encoder) fail(path, err);
  s.codec = s.api->codec_name(s.encoder);
  s.rgb.assign(static_cast<std::size_t>(s.enc_width) * s.enc_height * 3, 0);
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::add_frame(const Image& linear) {
  State& s = *s_;
  if (linear.width != s.width || linear.height != s.height)
    fail(s.path, fmt::format("frame {} is {}x{}, the video is {}x{}", s.frames, linear.width, linear.height, s.width,
                             s.height));
  // Each code as the PNG writer makes it (round(encode_srgb(v) * 255)); odd sides repeat the
  // last column or row.
  for (int y = 0; y < s.enc_height; ++y) {
    const int sy = std::min(y, s.height - 1);
    for (int x = 0; x < s.enc_width; ++x) {
      const float* p = linear.at(std::min(x, s.width - 1), sy);
      uint8_t* q = &s.rgb[(static_cast<std::size_t>(y) * s.enc_width + x) * 3];
      for (int c = 0; c < 3; ++c) {
        float v = p[c];
        v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
        q[c] = static_cast<uint8_t>(std::lround(linear_to_srgb(v) * 255.0f));
      }
    }
  }
  char err[512] = {};
  if (s.api->add_frame(s.encoder, s.rgb.data(), err, sizeof err) != 0) fail(s.path, err);
  ++s.frames;
}

void VideoWriter::finish() {
  State& s = *s_;
  if (s.finished) return;
  if (s.frames == 0) fail(s.path, "no frames");
  char err[512] = {};
  if (s.api->finish(s.encoder, err, sizeof err) != 0) fail(s.path, err);
  if (std::rename(s.temp.c_str(), s.path.c_str()) != 0) {
    ::unlink(s.temp.c_str());
    fail(s.path, "cannot rename the finished file into place");
  }
  s.finished = true;
  s.guard.reset();
}

int VideoWriter::frames() const { return s_->frames; }
std::string VideoWriter::codec_name() const { return s_->codec; }

}  // namespace rts::render
