/* The C interface between rts and its video module (librts_video.so, built from
   video_encoder.cpp with FFmpeg's libraries). rts loads the module with dlopen only when a
   render writes a video, so every other run starts without FFmpeg's ~150 shared libraries.
   Errors come back as text in `err` (never as C++ exceptions across the boundary). */
#ifndef RTS_VIDEO_MODULE_API_H
#define RTS_VIDEO_MODULE_API_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RTS_VIDEO_API_VERSION 1

struct rts_video_api {
  int version; /* RTS_VIDEO_API_VERSION */
  /* Opens an encoder writing `path` (format 0: MP4/H.264, 1: WebM/VP9) for width × height
     frames (even sides), fps frames a second, quality < 0 for the default. Null on failure. */
  void* (*open)(const char* path, int format, int width, int height, int fps, int quality, char* err, size_t errlen);
  /* Appends one frame of width × height × 3 sRGB bytes, rows top first. 0 on success. */
  int (*add_frame)(void* enc, const uint8_t* rgb, char* err, size_t errlen);
  /* Flushes the encoder and closes the file. 0 on success. */
  int (*finish)(void* enc, char* err, size_t errlen);
  /* Frees the encoder (after finish, or instead of it on an error path). */
  void (*close)(void* enc);
  const char* (*codec_name)(void* enc);
};

/* The module's one exported symbol. */
const struct rts_video_api* rts_video_api_v1(void);

#ifdef __cplusplus
}
#endif

#endif
