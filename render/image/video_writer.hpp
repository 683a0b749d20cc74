// Video output: an animation's frames encoded with FFmpeg's libraries into an MP4 (H.264) or
// WebM (VP9) file, so that `rts render anim.rts -o ball.mp4` needs no ffmpeg command. Frames
// arrive linear, are encoded to 8-bit sRGB exactly as a PNG frame would be, and converted to
// BT.709 4:2:0. The file is written under a temporary name and renamed into place at finish(),
// so a failed or interrupted encode never leaves a truncated video under the name.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "render/image/image.hpp"

namespace rts::render {

enum class VideoFormat { Mp4, Webm };

// The video format named by `path`'s extension (.mp4, .webm, any case), or nullopt.
std::optional<VideoFormat> video_format_for_path(const std::string& path);

struct VideoOptions {
  int fps = 24;
  // Constant quality: x264's CRF for MP4 (18 is visually lossless), libvpx's for WebM.
  int quality = -1;  // < 0: the format's default (18 for H.264, 30 for VP9)
};

class VideoWriter {
 public:
  // Opens the encoder for frames of width × height (odd sizes are padded by one pixel: 4:2:0
  // needs even sides). Throws RenderError naming `path` when the format's encoder is missing
  // or the file cannot be created.
  VideoWriter(const std::string& path, VideoFormat format, int width, int height, const VideoOptions& options);
  ~VideoWriter();  // without finish(): removes the temporary file
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // Appends one frame (linear RGB, the size given at construction). Throws RenderError.
  void add_frame(const Image& linear);
  // Flushes the encoder, writes the trailer and renames the file into place. Throws RenderError.
  void finish();
  int frames() const;
  std::string codec_name() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace rts::render
