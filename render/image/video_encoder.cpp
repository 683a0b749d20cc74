// The video module (librts_video.so): FFmpeg's encoders behind the C interface of
// video_module_api.h. Frames arrive as 8-bit sRGB and are converted to BT.709 4:2:0.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "render/image/video_module_api.h"

namespace {

struct Failure {
  std::string message;
};

[[noreturn]] void fail(const std::string& why) { throw Failure{why}; }

std::string av_message(int err) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(err, buf, sizeof buf);
  return buf;
}

void set_error(char* err, std::size_t len, const std::string& message) {
  if (err && len) std::snprintf(err, len, "%s", message.c_str());
}

// The first encoder of `names` this FFmpeg build has (Debian's has libx264 and libvpx).
const AVCodec* find_encoder(std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (const AVCodec* c = avcodec_find_encoder_by_name(n)) return c;
  return nullptr;
}

struct Encoder {
  int width = 0, height = 0;
  AVFormatContext* fmt = nullptr;
  AVCodecContext* enc = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  int64_t next_pts = 0;

  ~Encoder() {
    sws_freeContext(sws);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&enc);
    if (fmt) {
      if (fmt->pb) avio_closep(&fmt->pb);
      avformat_free_context(fmt);
    }
  }

  // Sends `f` (null: flush) and writes every packet the encoder has ready.
  void encode(AVFrame* f) {
    int err = avcodec_send_frame(enc, f);
    if (err < 0) fail("encoding failed: " + av_message(err));
    for (;;) {
      err = avcodec_receive_packet(enc, packet);
      if (err == AVERROR(EAGAIN) || err == AVERROR_EOF) return;
      if (err < 0) fail("encoding failed: " + av_message(err));
      av_packet_rescale_ts(packet, enc->time_base, stream->time_base);
      packet->stream_index = stream->index;
      err = av_interleaved_write_frame(fmt, packet);
      if (err < 0) fail(av_message(err));
    }
  }

  void open(const char* path, bool mp4, int w, int h, int fps, int quality) {
    width = w;
    height = h;
    av_log_set_level(AV_LOG_ERROR);  // the encoders' statistics are not the user's business
    const AVCodec* codec = mp4 ? find_encoder({"libx264", "libopenh264", "mpeg4"}) : find_encoder({"libvpx-vp9", "libvpx"});
    if (!codec) fail(mp4 ? "this FFmpeg has no H.264 or MPEG-4 encoder" : "this FFmpeg has no VP9 or VP8 encoder");
    int err = avformat_alloc_output_context2(&fmt, nullptr, mp4 ? "mp4" : "webm", path);
    if (err < 0 || !fmt) fail("no muxer: " + av_message(err));
    fmt->flags |= AVFMT_FLAG_BITEXACT;  // no encoder version strings: the same frames give the same file

    enc = avcodec_alloc_context3(codec);
    enc->width = w;
    enc->height = h;
    enc->time_base = AVRational{1, fps};
    enc->framerate = AVRational{fps, 1};
    enc->pix_fmt = AV_PIX_FMT_YUV420P;
    enc->gop_size = fps;  // a key frame a second: seeking stays quick
    enc->flags |= AV_CODEC_FLAG_BITEXACT;
    enc->color_primaries = AVCOL_PRI_BT709;
    enc->color_trc = AVCOL_TRC_IEC61966_2_1;  // the frames are sRGB-encoded
    enc->colorspace = AVCOL_SPC_BT709;
    enc->color_range = AVCOL_RANGE_MPEG;
    if (fmt->oformat->flags & AVFMT_GLOBALHEADER) enc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    const std::string name = codec->name;
    if (name == "libx264") {
      av_opt_set(enc->priv_data, "crf", std::to_string(quality < 0 ? 18 : quality).c_str(), 0);
      av_opt_set(enc->priv_data, "preset", "medium", 0);
      // No B-frames: timestamps then start at 0 with no reordering, and the MP4 needs no edit
      // list (see use_editlist below).
      enc->max_b_frames = 0;
    } else if (name == "libvpx-vp9" || name == "libvpx") {
      av_opt_set(enc->priv_data, "crf", std::to_string(quality < 0 ? 30 : quality).c_str(), 0);
      enc->bit_rate = 0;  // constant quality
    } else {
      enc->bit_rate = int64_t(w) * h * fps / 4;  // mpeg4: a quarter bit a pixel
    }
    err = avcodec_open2(enc, codec, nullptr);
    if (err < 0) fail("cannot open the " + name + " encoder: " + av_message(err));
    stream = avformat_new_stream(fmt, nullptr);
    if (!stream) fail("cannot add a stream");
    avcodec_parameters_from_context(stream->codecpar, enc);
    stream->time_base = enc->time_base;
    err = avio_open(&fmt->pb, path, AVIO_FLAG_WRITE);
    if (err < 0) fail(av_message(err));
    AVDictionary* mux_options = nullptr;
    // FFmpeg 5.1's MP4 edit list ends at the last frame's start, so players that honour it drop
    // the last frame (7 encoded, 6 played); without B-frames the video needs no edit list.
    if (mp4) av_dict_set(&mux_options, "use_editlist", "0", 0);
    err = avformat_write_header(fmt, &mux_options);
    av_dict_free(&mux_options);
    if (err < 0) fail(av_message(err));

    frame = av_frame_alloc();
    frame->format = AV_PIX_FMT_YUV420P;
    frame->width = w;
    frame->height = h;
    if (av_frame_get_buffer(frame, 0) < 0) fail("out of memory");
    packet = av_packet_alloc();
    sws = sws_getContext(w, h, AV_PIX_FMT_RGB24, w, h, AV_PIX_FMT_YUV420P,
                         SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr, nullptr);
    if (!sws) fail("cannot convert RGB to YUV");
    // BT.709 coefficients, full-range RGB in, limited-range YUV out.
    const int* coeffs = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(sws, coeffs, 1, coeffs, 0, 0, 1 << 16, 1 << 16);
  }

  void add(const uint8_t* rgb) {
    if (av_frame_make_writable(frame) < 0) fail("out of memory");
    const uint8_t* src[1] = {rgb};
    const int stride[1] = {width * 3};
    sws_scale(sws, src, stride, 0, height, frame->data, frame->linesize);
    frame->pts = next_pts++;
    encode(frame);
  }

  void finish() {
    if (next_pts == 0) fail("no frames");
    encode(nullptr);
    int err = av_write_trailer(fmt);
    if (err < 0) fail(av_message(err));
    err = avio_closep(&fmt->pb);
    if (err < 0) fail(av_message(err));
  }
};

void* api_open(const char* path, int format, int width, int height, int fps, int quality, char* err, size_t len) {
  auto* e = new Encoder;
  try {
    e->open(path, format == 0, width, height, fps, quality);
    return e;
  } catch (const Failure& f) {
    set_error(err, len, f.message);
  } catch (const std::exception& x) {
    set_error(err, len, x.what());
  }
  delete e;
  return nullptr;
}

int api_add_frame(void* enc, const uint8_t* rgb, char* err, size_t len) {
  try {
    static_cast<Encoder*>(enc)->add(rgb);
    return 0;
  } catch (const Failure& f) {
    set_error(err, len, f.message);
  } catch (const std::exception& x) {
    set_error(err, len, x.what());
  }
  return -1;
}

int api_finish(void* enc, char* err, size_t len) {
  try {
    static_cast<Encoder*>(enc)->finish();
    return 0;
  } catch (const Failure& f) {
    set_error(err, len, f.message);
  } catch (const std::exception& x) {
    set_error(err, len, x.what());
  }
  return -1;
}

void api_close(void* enc) { delete static_cast<Encoder*>(enc); }

const char* api_codec_name(void* enc) {
  auto* e = static_cast<Encoder*>(enc);
  return e && e->enc ? e->enc->codec->name : "";
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const struct rts_video_api* rts_video_api_v1(void) {
  static const rts_video_api api{RTS_VIDEO_API_VERSION, api_open, api_add_frame, api_finish, api_close,
                                 api_codec_name};
  return &api;
}
