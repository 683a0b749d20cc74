// Video output (render/image/video_writer.*): frames encoded to MP4 (H.264) and WebM (VP9) are
// decoded back with FFmpeg's libraries: the frame count, the size (odd sides padded by one
// pixel) and each frame's colour (within the 4:2:0 round trip's few codes), the same bytes
// from the same frames, and no file at all when the writer never finishes.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <catch2/catch.hpp>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include "render/image/video_writer.hpp"
#include "render/scene/source_ref.hpp"

using namespace rts::render;
namespace fs = std::filesystem;

namespace {

struct Decoded {
  int width = 0, height = 0;
  int frame_height = 0;  // of the last frame decoded
  std::vector<std::array<double, 3>> mean_rgb;  // per frame, 0..255 codes
};

// Decodes every frame of `path` and averages its RGB codes.
Decoded decode(const std::string& path) {
  Decoded out;
  AVFormatContext* fmt = nullptr;
  REQUIRE(avformat_open_input(&fmt, path.c_str(), nullptr, nullptr) == 0);
  REQUIRE(avformat_find_stream_info(fmt, nullptr) >= 0);
  const AVCodec* codec = nullptr;
  const int stream = av_find_best_stream(fmt, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
  REQUIRE(stream >= 0);
  AVCodecContext* dec = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(dec, fmt->streams[stream]->codecpar);
  REQUIRE(avcodec_open2(dec, codec, nullptr) == 0);
  out.width = dec->width;
  out.height = dec->height;
  AVPacket* pkt = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* sws = nullptr;
  std::vector<uint8_t> rgb(static_cast<std::size_t>(dec->width) * dec->height * 3);
  auto drain = [&] {
    while (avcodec_receive_frame(dec, frame) == 0) {
      sws = sws_getCachedContext(sws, frame->width, frame->height, static_cast<AVPixelFormat>(frame->format),
                                 frame->width, frame->height, AV_PIX_FMT_RGB24, SWS_BICUBIC, nullptr, nullptr, nullptr);
      const int* coeffs = sws_getCoefficients(SWS_CS_ITU709);
      sws_setColorspaceDetails(sws, coeffs, frame->color_range == AVCOL_RANGE_JPEG, coeffs, 1, 0, 1 << 16, 1 << 16);
      uint8_t* dst[1] = {rgb.data()};
      int stride[1] = {frame->width * 3};
      sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, stride);
      std::array<double, 3> sum{0, 0, 0};
      const std::size_t n_bytes = static_cast<std::size_t>(frame->width) * frame->height * 3;
      REQUIRE(n_bytes <= rgb.size());
      for (std::size_t i = 0; i < n_bytes; ++i) sum[i % 3] += rgb[i];
      out.frame_height = frame->height;
      const double n = double(frame->width) * frame->height;
      out.mean_rgb.push_back({sum[0] / n, sum[1] / n, sum[2] / n});
    }
  };
  while (av_read_frame(fmt, pkt) >= 0) {
    if (pkt->stream_index == stream) {
      while (avcodec_send_packet(dec, pkt) == AVERROR(EAGAIN)) drain();  // full: take frames out first
      drain();
    }
    av_packet_unref(pkt);
  }
  avcodec_send_packet(dec, nullptr);
  drain();
  sws_freeContext(sws);
  av_frame_free(&frame);
  av_packet_free(&pkt);
  avcodec_free_context(&dec);
  avformat_close_input(&fmt);
  return out;
}

// A flat frame of one linear colour.
Image flat(int w, int h, float r, float g, float b) {
  Image im(w, h);
  for (std::size_t i = 0; i < im.rgb.size(); i += 3) {
    im.rgb[i] = r;
    im.rgb[i + 1] = g;
    im.rgb[i + 2] = b;
  }
  return im;
}

std::string temp_dir() {
  std::string t = (fs::temp_directory_path() / "rts-video-XXXXXX").string();
  REQUIRE(mkdtemp(t.data()) != nullptr);
  return t;
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Frame k is a grey ramp in linear light whose sRGB code is 20 + 30k.
double code_of(int k) { return 20.0 + 30.0 * k; }
float linear_of(double code) {
  const double e = code / 255.0;
  return static_cast<float>(e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4));
}

}  // namespace

TEST_CASE("video: extensions pick the format", "[video]") {
  CHECK(video_format_for_path("a/b.mp4") == VideoFormat::Mp4);
  CHECK(video_format_for_path("B.WEBM") == VideoFormat::Webm);
  CHECK_FALSE(video_format_for_path("x.png").has_value());
  CHECK_FALSE(video_format_for_path("dir.mp4/x").has_value());
}

TEST_CASE("video: frames decode back with their count, size and colours", "[video]") {
  const std::string dir = temp_dir();
  for (const char* ext : {".mp4", ".webm"}) {
    SECTION(ext) {
      const std::string path = dir + "/v" + ext;
      const int w = 47, h = 31;  // odd: padded to 48 × 32
      {
        VideoWriter v(path, *video_format_for_path(path), w, h, VideoOptions{});
        for (int k = 0; k < 7; ++k) {
          const float l = linear_of(code_of(k));
          v.add_frame(flat(w, h, l, l, l));
        }
        v.finish();
        CHECK(v.frames() == 7);
      }
      Decoded d = decode(path);
      CHECK(d.width == 48);
      CHECK(d.height == 32);
      REQUIRE(d.mean_rgb.size() == 7);
      for (int k = 0; k < 7; ++k)
        for (int c = 0; c < 3; ++c) CHECK(std::abs(d.mean_rgb[k][c] - code_of(k)) < 4.0);
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("video: a coloured frame keeps its hue through BT.709 4:2:0", "[video]") {
  const std::string dir = temp_dir();
  const std::string path = dir + "/c.mp4";
  {
    VideoWriter v(path, VideoFormat::Mp4, 32, 32, VideoOptions{});
    v.add_frame(flat(32, 32, linear_of(200), linear_of(60), linear_of(30)));
    v.finish();
  }
  Decoded d = decode(path);
  REQUIRE(d.mean_rgb.size() == 1);
  CHECK(std::abs(d.mean_rgb[0][0] - 200) < 5.0);
  CHECK(std::abs(d.mean_rgb[0][1] - 60) < 5.0);
  CHECK(std::abs(d.mean_rgb[0][2] - 30) < 5.0);
  fs::remove_all(dir);
}

TEST_CASE("video: the same frames give the same bytes", "[video]") {
  const std::string dir = temp_dir();
  for (const char* name : {"/a.mp4", "/b.mp4"}) {
    VideoWriter v(dir + name, VideoFormat::Mp4, 16, 16, VideoOptions{});
    for (int k = 0; k < 3; ++k) v.add_frame(flat(16, 16, 0.1f * k, 0.2f, 0.3f));
    v.finish();
  }
  CHECK(bytes_of(dir + "/a.mp4") == bytes_of(dir + "/b.mp4"));
  fs::remove_all(dir);
}

TEST_CASE("video: nothing is left under the name unless the writer finishes", "[video]") {
  const std::string dir = temp_dir();
  {
    VideoWriter v(dir + "/unfinished.mp4", VideoFormat::Mp4, 16, 16, VideoOptions{});
    v.add_frame(flat(16, 16, 0.5f, 0.5f, 0.5f));
  }  // destroyed without finish(): an error path
  CHECK(fs::is_empty(dir));
  {
    VideoWriter v(dir + "/empty.mp4", VideoFormat::Mp4, 16, 16, VideoOptions{});
    CHECK_THROWS_AS(v.finish(), RenderError);  // no frames
  }
  CHECK(fs::is_empty(dir));
  {
    VideoWriter v(dir + "/size.mp4", VideoFormat::Mp4, 16, 16, VideoOptions{});
    CHECK_THROWS_AS(v.add_frame(flat(8, 8, 0, 0, 0)), RenderError);  // another size
  }
  CHECK(fs::is_empty(dir));
  CHECK_THROWS_AS(VideoWriter(dir + "/no/such/dir.mp4", VideoFormat::Mp4, 16, 16, VideoOptions{}), RenderError);
  fs::remove_all(dir);
}
