#include "render/image/video_writer.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <fmt/format.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "render/image/temp_file_guard.hpp"
#include "render/scene/source_ref.hpp"

namespace rts::render {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw RenderError({}, fmt::format("cannot write video '{}': {}", path, why));
}

std::string av_message(int err) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(err, buf, sizeof buf);
  return buf;
}

std::string lower_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// The first encoder of `ids` this FFmpeg build has (Debian's has libx264 and libvpx).
const AVCodec* find_encoder(std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (const AVCodec* c = avcodec_find_encoder_by_name(n)) return c;
  return nullptr;
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
  AVFormatContext* fmt = nullptr;
  AVCodecContext* enc = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  std::vector<uint8_t> rgb;  // enc_width × enc_height × 3, sRGB
  int64_t next_pts = 0;
  bool finished = false;
  std::unique_ptr<TempFileGuard> guard;

  ~State() {
    sws_freeContext(sws);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&enc);
    if (fmt) {
      if (fmt->pb) avio_closep(&fmt->pb);
      avformat_free_context(fmt);
    }
    if (!finished && !temp.empty()) ::unlink(temp.c_str());
  }

  // Sends `f` (null: flush) and writes every packet the encoder has ready.
  void encode(AVFrame* f) {
    int err = avcodec_send_frame(enc, f);
    if (err < 0) fail(path, "encoding failed: " + av_message(err));
    for (;;) {
      err = avcodec_receive_packet(enc, packet);
      if (err == AVERROR(EAGAIN) || err == AVERROR_EOF) return;
      if (err < 0) fail(path, "encoding failed: " + av_message(err));
      av_packet_rescale_ts(packet, enc->time_base, stream->time_base);
      packet->stream_index = stream->index;
      err = av_interleaved_write_frame(fmt, packet);
      if (err < 0) fail(path, av_message(err));
    }
  }
};

VideoWriter::VideoWriter(const std::string& path, VideoFormat format, int width, int height,
                         const VideoOptions& options)
    : s_(std::make_unique<State>()) {
  State& s = *s_;
  s.path = path;
  s.width = width;
  s.height = height;
  s.enc_width = width + (width & 1);
  s.enc_height = height + (height & 1);
  if (options.fps < 1 || options.fps > 1000) fail(path, fmt::format("fps must be from 1 to 1000, got {}", options.fps));

  av_log_set_level(AV_LOG_ERROR);  // the encoders' statistics are not the user's business
  const bool mp4 = format == VideoFormat::Mp4;
  const AVCodec* codec = mp4 ? find_encoder({"libx264", "libopenh264", "mpeg4"}) : find_encoder({"libvpx-vp9", "libvpx"});
  if (!codec) fail(path, mp4 ? "this FFmpeg has no H.264 or MPEG-4 encoder" : "this FFmpeg has no VP9 or VP8 encoder");

  static thread_local std::mt19937_64 rng{std::random_device{}()};
  s.temp = fmt::format("{}.tmp-{}-{:016x}", path, static_cast<long>(getpid()), rng());
  s.guard = std::make_unique<TempFileGuard>(s.temp);
  int err = avformat_alloc_output_context2(&s.fmt, nullptr, mp4 ? "mp4" : "webm", s.temp.c_str());
  if (err < 0 || !s.fmt) fail(path, "no muxer: " + av_message(err));
  s.fmt->flags |= AVFMT_FLAG_BITEXACT;  // no encoder version strings: the same frames give the same file

  s.enc = avcodec_alloc_context3(codec);
  s.enc->width = s.enc_width;
  s.enc->height = s.enc_height;
  s.enc->time_base = AVRational{1, options.fps};
  s.enc->framerate = AVRational{options.fps, 1};
  s.enc->pix_fmt = AV_PIX_FMT_YUV420P;
  s.enc->gop_size = options.fps;  // a key frame a second: seeking stays quick
  s.enc->flags |= AV_CODEC_FLAG_BITEXACT;
  s.enc->color_primaries = AVCOL_PRI_BT709;
  s.enc->color_trc = AVCOL_TRC_IEC61966_2_1;  // the frames are sRGB-encoded
  s.enc->colorspace = AVCOL_SPC_BT709;
  s.enc->color_range = AVCOL_RANGE_MPEG;
  if (s.fmt->oformat->flags & AVFMT_GLOBALHEADER) s.enc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  const std::string name = codec->name;
  if (name == "libx264") {
    av_opt_set(s.enc->priv_data, "crf", std::to_string(options.quality < 0 ? 18 : options.quality).c_str(), 0);
    av_opt_set(s.enc->priv_data, "preset", "medium", 0);
    // No B-frames: timestamps then start at 0 with no reordering, and the MP4 needs no edit
    // list (see use_editlist below).
    s.enc->max_b_frames = 0;
  } else if (name == "libvpx-vp9" || name == "libvpx") {
    av_opt_set(s.enc->priv_data, "crf", std::to_string(options.quality < 0 ? 30 : options.quality).c_str(), 0);
    s.enc->bit_rate = 0;  // constant quality
  } else {
    s.enc->bit_rate = int64_t(s.enc_width) * s.enc_height * options.fps / 4;  // mpeg4: a quarter bit a pixel
  }
  err = avcodec_open2(s.enc, codec, nullptr);
  if (err < 0) fail(path, fmt::format("cannot open the {} encoder: {}", name, av_message(err)));
  s.stream = avformat_new_stream(s.fmt, nullptr);
  if (!s.stream) fail(path, "cannot add a stream");
  avcodec_parameters_from_context(s.stream->codecpar, s.enc);
  s.stream->time_base = s.enc->time_base;
  err = avio_open(&s.fmt->pb, s.temp.c_str(), AVIO_FLAG_WRITE);
  if (err < 0) fail(path, av_message(err));
  AVDictionary* mux_options = nullptr;
  // FFmpeg 5.1's MP4 edit list ends at the last frame's start, so players that honour it drop
  // the last frame (7 encoded, 6 played); without B-frames the video needs no edit list.
  if (mp4) av_dict_set(&mux_options, "use_editlist", "0", 0);
  err = avformat_write_header(s.fmt, &mux_options);
  av_dict_free(&mux_options);
  if (err < 0) fail(path, av_message(err));

  s.frame = av_frame_alloc();
  s.frame->format = AV_PIX_FMT_YUV420P;
  s.frame->width = s.enc_width;
  s.frame->height = s.enc_height;
  if (av_frame_get_buffer(s.frame, 0) < 0) fail(path, "out of memory");
  s.packet = av_packet_alloc();
  s.sws = sws_getContext(s.enc_width, s.enc_height, AV_PIX_FMT_RGB24, s.enc_width, s.enc_height, AV_PIX_FMT_YUV420P,
                         SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr, nullptr);
  if (!s.sws) fail(path, "cannot convert RGB to YUV");
  // BT.709 coefficients, full-range RGB in, limited-range YUV out.
  const int* coeffs = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(s.sws, coeffs, 1, coeffs, 0, 0, 1 << 16, 1 << 16);
  s.rgb.assign(static_cast<std::size_t>(s.enc_width) * s.enc_height * 3, 0);
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::add_frame(const Image& linear) {
  State& s = *s_;
  if (linear.width != s.width || linear.height != s.height)
    fail(s.path, fmt::format("frame {} is {}x{}, the video is {}x{}", s.next_pts, linear.width, linear.height,
                             s.width, s.height));
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
  if (av_frame_make_writable(s.frame) < 0) fail(s.path, "out of memory");
  const uint8_t* src[1] = {s.rgb.data()};
  const int stride[1] = {s.enc_width * 3};
  sws_scale(s.sws, src, stride, 0, s.enc_height, s.frame->data, s.frame->linesize);
  s.frame->pts = s.next_pts++;
  s.encode(s.frame);
}

void VideoWriter::finish() {
  State& s = *s_;
  if (s.finished) return;
  if (s.next_pts == 0) fail(s.path, "no frames");
  s.encode(nullptr);
  int err = av_write_trailer(s.fmt);
  if (err < 0) fail(s.path, av_message(err));
  err = avio_closep(&s.fmt->pb);
  if (err < 0) fail(s.path, av_message(err));
  if (std::rename(s.temp.c_str(), s.path.c_str()) != 0) {
    ::unlink(s.temp.c_str());
    fail(s.path, "cannot rename the finished file into place");
  }
  s.finished = true;
  s.guard.reset();
}

int VideoWriter::frames() const { return static_cast<int>(s_->next_pts); }
std::string VideoWriter::codec_name() const { return s_->enc ? s_->enc->codec->name : ""; }

}  // namespace rts::render
