// PNG reading with libpng; PNG writing with libdeflate (see encode_png), to a file through
// write_file_atomically.
//
// libpng reports errors by longjmp-ing out of its own (C) frames. We never let that jump cross
// a C++ frame that owns objects with destructors: every setjmp lives in a small function whose
// locals are trivially destructible, state is kept in caller-owned structs, and the C++
// exception (RenderError) is thrown only after the libpng call chain has been left.
#include <png.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <libdeflate.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/image/image.hpp"
#include "render/scene/resource_limits.hpp"
#include "render/image/atomic_file.hpp"

namespace rts::render {

namespace {

// sRGB transfer function constants (IEC 61966-2-1).
constexpr double kSrgbLinearThreshold = 0.0031308;   // linear value where the curve changes
constexpr double kSrgbEncodedThreshold = 0.04045;    // the same point, encoded
constexpr double kSrgbLinearSlope = 12.92;
constexpr double kSrgbGamma = 2.4;
constexpr double kSrgbOffset = 0.055;

// Images larger than this many pixels are refused when reading (a corrupt or hostile header
// must not make us allocate gigabytes).
constexpr std::size_t kMaxReadPixels = 100'000'000;

// Deflate expands at most 1032:1 (its best case, long runs of one byte), so a file of N bytes holds
// at most ~1032 N bytes of raw pixel rows; a header that claims more describes data the file
// cannot contain, and is refused before any row buffer is allocated (a 100-byte file must not
// make us allocate gigabytes only to fail on its missing data). 1100 leaves room above the bound.
constexpr std::size_t kMaxDeflateExpansion = 1100;

// The largest buffer libpng may allocate for one chunk other than the pixels (text, ICC
// profiles, unknown chunks): far above any real image's metadata; a larger ancillary chunk is
// skipped with a warning, a larger critical one is an error.
constexpr png_alloc_size_t kMaxChunkBytes = png_alloc_size_t(8) << 20;

constexpr int kPngSignatureBytes = 8;
// libdeflate level for writing (1 fastest .. 12 smallest). See encode_png.
constexpr int kPngCompressionLevel = 1;

constexpr int kCodes8 = 256;

// ---- value encoding -----------------------------------------------------------------------

double decode_srgb(double e) {
  if (e <= kSrgbEncodedThreshold) return e / kSrgbLinearSlope;
  return std::pow((e + kSrgbOffset) / (1.0 + kSrgbOffset), kSrgbGamma);
}

double encode_srgb(double l) {
  if (l <= kSrgbLinearThreshold) return l * kSrgbLinearSlope;
  return (1.0 + kSrgbOffset) * std::pow(l, 1.0 / kSrgbGamma) - kSrgbOffset;
}

// Linear (possibly NaN/inf/out of range) → [0,1]: NaN is black, infinities clamp.
double clamp_linear(float linear) {
  return std::isnan(linear) ? 0.0 : std::clamp(static_cast<double>(linear), 0.0, 1.0);
}

// 8-bit sRGB without a pow() per sample: code k+1 starts at the linear value whose encoding is
// (k + 0.5)/255, so counting the thresholds at or below a value rounds it to the nearest code
// exactly as round(encode_srgb(v) * 255) does.
class Srgb8Encoder {
 public:
  Srgb8Encoder() {
    for (int k = 0; k < kCodes8 - 1; ++k) starts_[k] = decode_srgb((k + 0.5) / (kCodes8 - 1));
  }
  unsigned encode(double linear) const {
    // Iterators, not `starts_ + kCodes8 - 1`: that parses as (starts_ + 256) - 1 and forms a
    // pointer two past the end of the array first, which is undefined (clang's UBSan says so).
    return static_cast<unsigned>(std::upper_bound(starts_.begin(), starts_.end(), linear) -
                                 starts_.begin());
  }
  // The linear value where code k + 1 starts (k < 255): encode(v) counts these at or below v.
  double start(int k) const { return starts_[static_cast<std::size_t>(k)]; }

 private:
  std::array<double, kCodes8 - 1> starts_{};
};

// Srgb8Encoder's answer in a table lookup for most values. Profile finding (perf, writing a
// 1920x1080 frame): the binary search per sample was 64% of write_png's CPU time. A clamped
// sample is a non-negative float, whose bit pattern orders like its value: the top 16 bits
// (sign, exponent, 11 mantissa bits) select a range of floats, and where the encoder gives the same code at both ends of the
// range (monotonic: so for every value inside) the table answers; otherwise (near a code
// boundary, about 3% of samples) the search runs as before. Same codes, exactly.
class FastSrgb8 {
 public:
  explicit FastSrgb8(const Srgb8Encoder& exact) : exact_(exact) {
    // A non-negative float x is at or above threshold k (exact.start(k)) exactly when its bits
    // are at or above those of the smallest float at or above it, `first` below: so each
    // threshold falls in one key's range, the keys between two thresholds take one code, and
    // only the keys holding a threshold past their first float need the search. The table is
    // filled in runs, one step per threshold. Profile finding (callgrind of the pattern race
    // scene): the previous construction, two cursors compared with every key's two ends, was
    // 9.4M instructions (36 per key) on every PNG written, whatever the image's size; this
    // one is a fill of 0.5 MB. The same table (compared entry by entry with the old
    // construction when it was written).
    uint32_t key = 0;
    int k = 0;
    while (k < kCodes8 - 1) {
      const uint32_t held = first(exact.start(k)) >> kShift;   // the key holding threshold k
      std::fill(table_ + key, table_ + std::min(held, kKeys), static_cast<uint16_t>(k));
      if (held >= kKeys) return;   // (thresholds are below 1: not reached)
      // Thresholds k .. k_end - 1 fall in key `held`; those at its first float count for it.
      int k_end = k, at_start = 0;
      while (k_end < kCodes8 - 1 && first(exact.start(k_end)) >> kShift == held) {
        if (first(exact.start(k_end)) == held << kShift) ++at_start;
        ++k_end;
      }
      table_[held] = at_start == k_end - k ? static_cast<uint16_t>(k_end) : kSearch;
      key = held + 1;
      k = k_end;
    }
    std::fill(table_ + key, table_ + kKeys, static_cast<uint16_t>(kCodes8 - 1));
  }
  unsigned encode(float clamped) const {  // clamped to [0, 1]
    const uint32_t key = std::bit_cast<uint32_t>(clamped) >> kShift;
    const uint16_t code = table_[key];
    return code != kSearch ? code : exact_.encode(clamped);
  }

 private:
  // The bits of the smallest float at or above v (0 < v < 1).
  static uint32_t first(double v) {
    float f = static_cast<float>(v);
    if (static_cast<double>(f) < v) f = std::nextafter(f, 2.0f);
    return std::bit_cast<uint32_t>(f);
  }
  static constexpr int kShift = 12;  // 11 mantissa bits: ranges of 1/2048 of their value, ~0.5 MB
  static constexpr uint32_t kKeys = (std::bit_cast<uint32_t>(1.0f) >> kShift) + 1;
  static constexpr uint16_t kSearch = 0xFFFF;
  const Srgb8Encoder& exact_;
  uint16_t table_[kKeys];
};

// Linear float -> [0, 1] for the 8-bit sRGB table: NaN is black, infinities clamp, and -0 is
// +0 (its sign bit would index FastSrgb8's table far past its end: a -0 pixel crashed the
// writer). Otherwise the float clamp_linear gives.
float clamp_unit(float linear) { return linear > 0.0f ? (linear < 1.0f ? linear : 1.0f) : 0.0f; }

// Packs the image into PNG rows (big-endian samples for 16-bit), top row first; rows in
// parallel (each output byte depends on its own sample only, so the result never depends on
// scheduling).
std::vector<unsigned char> pack_rows(const Image& image, int bits, Encoding encoding) {
  const int bytes_per_sample = bits / 8;
  const double max_value = bits == 16 ? 65535.0 : 255.0;
  std::vector<unsigned char> out(image.rgb.size() * bytes_per_sample);
  const std::size_t row_samples = static_cast<std::size_t>(image.width) * 3;
  const tbb::blocked_range<std::size_t> all_rows(0, static_cast<std::size_t>(image.height), 16);
  if (encoding == Encoding::SRGB && bits == 8) {
    // Every rendered PNG: a clamp and a table lookup per sample, the format test outside the
    // loop. Profile finding (callgrind, the pattern race scene at 800x600): this loop was 41
    // instructions a sample with the format tested inside it and the clamp in double.
    static const Srgb8Encoder srgb8;
    static const FastSrgb8 fast_srgb8(srgb8);
    tbb::parallel_for(all_rows, [&](const tbb::blocked_range<std::size_t>& rows) {
      for (std::size_t i = rows.begin() * row_samples; i < rows.end() * row_samples; ++i)
        out[i] = static_cast<unsigned char>(fast_srgb8.encode(clamp_unit(image.rgb[i])));
    });
    return out;
  }
  tbb::parallel_for(all_rows, [&](const tbb::blocked_range<std::size_t>& rows) {
    for (std::size_t i = rows.begin() * row_samples; i < rows.end() * row_samples; ++i) {
      const double linear = clamp_linear(image.rgb[i]);
      const double e = encoding == Encoding::SRGB ? encode_srgb(linear) : linear;
      const unsigned q = static_cast<unsigned>(std::lround(std::clamp(e, 0.0, 1.0) * max_value));
      std::size_t o = i * bytes_per_sample;
      if (bits == 16) out[o++] = static_cast<unsigned char>(q >> 8);
      out[o] = static_cast<unsigned char>(q & 0xFF);
    }
  });
  return out;
}

// ---- libpng glue shared by reading and writing -----------------------------------------------

// Caller-owned state that libpng callbacks fill in; survives the longjmp.
struct PngIo {
  std::FILE* file = nullptr;             // reading
  std::vector<unsigned char>* out = nullptr;  // writing: the encoded file, appended to
  char message[256] = {};
  int saved_errno = 0;      // errno of the failing read/write, 0 if none
  bool truncated = false;   // reading: the file ended early
};

void png_error_handler(png_structp png, png_const_charp msg) {
  auto* io = static_cast<PngIo*>(png_get_error_ptr(png));
  if (io->message[0] == '\0') std::snprintf(io->message, sizeof io->message, "%s", msg);
  png_longjmp(png, 1);
}

void png_warning_handler(png_structp, png_const_charp) {
  // Warnings (unknown chunks, odd gamma) do not stop reading or writing; stay quiet.
}

void read_callback(png_structp png, png_bytep data, png_size_t length) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (std::fread(data, 1, length, io->file) != length) {
    if (std::ferror(io->file)) {
      io->saved_errno = errno != 0 ? errno : EIO;
    } else {
      io->truncated = true;
    }
    png_error(png, "read failed");
  }
}

std::string io_failure(const PngIo& io) {
  if (io.saved_errno != 0) return std::strerror(io.saved_errno);
  if (io.truncated) return "file is truncated";
  return io.message[0] != '\0' ? io.message : "libpng error";
}

// ---- writing ------------------------------------------------------------------------------

// Encodes `rows` into *io.out as a PNG written chunk by chunk here, compressed with libdeflate.
// Profile finding (callgrind, 1920x1080): zlib's deflate inside libpng was ~80% of writing
// (0.19 s at level 3); libdeflate compresses the same filtered rows several times faster in
// one whole-buffer call. SUB filter on every row (rendered images are smooth, so it loses
// little to adaptive filtering). Returns false (with io filled in) on failure.
bool write_bytes(PngIo& io, const void* data, std::size_t length) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  if (length > 0) io.out->insert(io.out->end(), bytes, bytes + length);
  return true;
}

void put_u32(unsigned char* p, uint32_t v) {
  p[0] = static_cast<unsigned char>(v >> 24);
  p[1] = static_cast<unsigned char>(v >> 16);
  p[2] = static_cast<unsigned char>(v >> 8);
  p[3] = static_cast<unsigned char>(v);
}

// One PNG chunk: length, type, data, CRC-32 of type and data.
bool write_chunk(PngIo& io, const char type[4], const unsigned char* data, std::size_t length) {
  unsigned char head[8];
  put_u32(head, static_cast<uint32_t>(length));
  std::memcpy(head + 4, type, 4);
  uint32_t crc = libdeflate_crc32(0, head + 4, 4);
  if (length > 0) crc = libdeflate_crc32(crc, data, length);  // a NULL buffer would reset it
  unsigned char tail[4];
  put_u32(tail, crc);
  return write_bytes(io, head, 8) && write_bytes(io, data, length) && write_bytes(io, tail, 4);
}

bool encode_png(PngIo& io, const unsigned char* rows, int width, int height, int bits,
                Encoding encoding) {
  const std::size_t bpp = 3 * static_cast<std::size_t>(bits / 8);  // bytes per pixel
  const std::size_t stride = static_cast<std::size_t>(width) * bpp;
  const std::size_t h = static_cast<std::size_t>(height);
  // Filter byte + SUB-filtered row, rows in parallel (each row depends only on itself).
  std::vector<unsigned char> filtered((stride + 1) * h);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, h, 64), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t y = r.begin(); y < r.end(); ++y) {
      const unsigned char* in = rows + stride * y;
      unsigned char* out = filtered.data() + (stride + 1) * y;
      out[0] = 1;  // SUB
      for (std::size_t i = 0; i < bpp; ++i) out[1 + i] = in[i];
      for (std::size_t i = bpp; i < stride; ++i) out[1 + i] = static_cast<unsigned char>(in[i] - in[i - bpp]);
    }
  });
  libdeflate_compressor* compressor = libdeflate_alloc_compressor(kPngCompressionLevel);
  if (compressor == nullptr) {
    std::snprintf(io.message, sizeof io.message, "out of memory");
    return false;
  }
  std::vector<unsigned char> compressed(libdeflate_zlib_compress_bound(compressor, filtered.size()));
  const std::size_t size =
      libdeflate_zlib_compress(compressor, filtered.data(), filtered.size(), compressed.data(), compressed.size());
  libdeflate_free_compressor(compressor);
  if (size == 0) {
    std::snprintf(io.message, sizeof io.message, "compression failed");
    return false;
  }

  static const unsigned char kSignature[kPngSignatureBytes] = {137, 80, 78, 71, 13, 10, 26, 10};
  unsigned char ihdr[13];
  put_u32(ihdr, static_cast<uint32_t>(width));
  put_u32(ihdr + 4, static_cast<uint32_t>(height));
  ihdr[8] = static_cast<unsigned char>(bits);
  ihdr[9] = 2;  // RGB
  ihdr[10] = ihdr[11] = ihdr[12] = 0;  // deflate, adaptive filtering, no interlace
  if (!write_bytes(io, kSignature, sizeof kSignature) || !write_chunk(io, "IHDR", ihdr, sizeof ihdr)) return false;
  if (encoding == Encoding::SRGB) {
    const unsigned char intent = 0;  // perceptual
    if (!write_chunk(io, "sRGB", &intent, 1)) return false;
  } else {
    unsigned char gamma[4];
    put_u32(gamma, 100000);  // gAMA 1.0: linear samples
    if (!write_chunk(io, "gAMA", gamma, 4)) return false;
  }
  constexpr std::size_t kMaxIdat = std::size_t(1) << 30;  // chunk lengths are limited to 2^31-1
  for (std::size_t at = 0; at < size; at += kMaxIdat) {
    if (!write_chunk(io, "IDAT", compressed.data() + at, std::min(kMaxIdat, size - at))) return false;
  }
  return write_chunk(io, "IEND", nullptr, 0);
}

[[noreturn]] void fail_write(const std::string& path, const std::string& why) {
  throw RenderError({}, fmt::format("cannot write '{}': {}", path, why));
}

// ---- reading ------------------------------------------------------------------------------

struct DecodedPng {
  png_uint_32 width = 0, height = 0;
  int bits = 8;                           // 8 or 16 after transformations
  std::vector<unsigned char> pixels;      // RGB rows, big-endian samples when 16-bit
  std::vector<png_bytep> row_pointers;
  bool too_large = false;
  std::size_t file_bytes = 0;             // in: the file's size, for the deflate bound
  bool more_than_data = false;            // out: the header claims more rows than the file holds
  std::size_t max_memory = 0;             // in: --max-memory (0: no limit)
  std::size_t needed = 0;                 // out, when over_memory: bytes decoding would take
  bool over_memory = false;
};

// Decodes io.file into out. Returns false on any libpng error. Only trivially destructible
// locals; `out`'s vectors are resized here but owned (and destroyed) by the caller.
bool decode_png(PngIo& io, DecodedPng& out) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &io, png_error_handler,
                                           png_warning_handler);
  if (png == nullptr) {
    std::snprintf(io.message, sizeof io.message, "out of memory");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_set_read_fn(png, &io, read_callback);
  png_set_sig_bytes(png, kPngSignatureBytes);
  // Debian's libpng sets no limit on one chunk's buffer: an ancillary chunk whose length field
  // says 600 MB made png_read_info allocate it before finding the file ends (fuzz_png, seed 1).
  png_set_chunk_malloc_max(png, kMaxChunkBytes);
  png_read_info(png, info);

  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  if (static_cast<std::size_t>(width) * height > kMaxReadPixels) {
    out.too_large = true;
    out.width = width;
    out.height = height;
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  // Before any transformation rowbytes is one stored row's size once inflated; the filter bytes
  // and interlacing only add to what the data must hold, so this is a lower bound.
  if (static_cast<std::size_t>(png_get_rowbytes(png, info)) * height > kMaxDeflateExpansion * out.file_bytes) {
    out.more_than_data = true;
    out.width = width;
    out.height = height;
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  const int color_type = png_get_color_type(png, info);
  // Everything becomes 8- or 16-bit RGB without alpha.
  png_set_expand(png);                                   // palette → RGB, gray < 8 → 8, tRNS → alpha
  if (color_type == PNG_COLOR_TYPE_GRAY || color_type == PNG_COLOR_TYPE_GRAY_ALPHA) {
    png_set_gray_to_rgb(png);
  }
  png_set_strip_alpha(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);

  out.width = width;
  out.height = height;
  out.bits = png_get_bit_depth(png, info) == 16 ? 16 : 8;
  const std::size_t stride = png_get_rowbytes(png, info);
  // The decoded rows, their pointers and the float image made from them, before any is made.
  const std::size_t needed = (stride + sizeof(png_bytep)) * height + std::size_t(width) * height * 3 * sizeof(float);
  if (!memory_fits(out.max_memory, needed)) {
    out.over_memory = true;
    out.needed = needed;
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  out.pixels.resize(stride * height);
  out.row_pointers.resize(height);
  for (png_uint_32 y = 0; y < height; ++y) out.row_pointers[y] = out.pixels.data() + stride * y;
  png_read_image(png, out.row_pointers.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

// Closes the FILE on scope exit (reading only: failures on close do not matter there).
struct FileCloser {
  std::FILE* file;
  ~FileCloser() {
    if (file != nullptr) std::fclose(file);
  }
};

}  // namespace

float srgb_to_linear(float v) { return static_cast<float>(decode_srgb(v)); }

float linear_to_srgb(float v) { return static_cast<float>(encode_srgb(v)); }

void write_png(const std::string& path, const Image& image, int bits, Encoding encoding) {
  if (bits != 8 && bits != 16) fail_write(path, fmt::format("unsupported bit depth {}", bits));
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    fail_write(path, fmt::format("invalid image ({}x{} with {} values)", image.width,
                                 image.height, image.rgb.size()));
  }
  const std::vector<unsigned char> rows = pack_rows(image, bits, encoding);
  // Encoded in memory (compressed, smaller than the rows), then written like every other file
  // rts writes: atomically, with the temp file removed on Ctrl-C (write_file_atomically).
  std::vector<unsigned char> file;
  PngIo io;
  io.out = &file;
  if (!encode_png(io, rows.data(), image.width, image.height, bits, encoding)) fail_write(path, io_failure(io));
  write_file_atomically(path, file);
}

RenderError image_over_memory(const std::string& path, SourceRef where, long long width, long long height,
                              std::size_t bytes, std::size_t max_memory) {
  return RenderError(where, fmt::format("cannot read image '{}': its {}x{} pixels need {} more memory, past the memory "
                                        "limit of {} (raise it with --max-memory)",
                                        path, width, height, size_in_words(bytes), size_in_words(max_memory)));
}

Image read_png(const std::string& path, SourceRef where, Encoding encoding, std::size_t max_memory) {
  auto fail = [&](const std::string& why) -> RenderError {
    return RenderError(where, fmt::format("cannot read image '{}': {}", path, why));
  };
  // A FIFO or device would block or never end: only regular files are read.
  if (std::string kind = non_regular_kind(path); !kind.empty()) throw fail(fmt::format("it is {}, not a file", kind));
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw fail(std::strerror(errno));
  FileCloser closer{file};

  unsigned char signature[kPngSignatureBytes];
  if (std::fread(signature, 1, sizeof signature, file) != sizeof signature ||
      png_sig_cmp(signature, 0, sizeof signature) != 0) {
    throw fail("not a PNG file");
  }
  PngIo io;
  io.file = file;
  DecodedPng decoded;
  decoded.max_memory = max_memory;
  struct stat st {};
  decoded.file_bytes = fstat(fileno(file), &st) == 0 ? static_cast<std::size_t>(st.st_size)
                                                   : SIZE_MAX / kMaxDeflateExpansion;  // unknown: no bound
  if (!decode_png(io, decoded)) {
    if (decoded.too_large) {
      throw fail(fmt::format("image too large ({}x{})", decoded.width, decoded.height));
    }
    if (decoded.more_than_data) {
      throw fail(fmt::format("its header claims {}x{} pixels, more than its {} of data can hold "
                             "(a damaged or truncated file)",
                             decoded.width, decoded.height, size_in_words(decoded.file_bytes)));
    }
    if (decoded.over_memory)
      throw image_over_memory(path, where, decoded.width, decoded.height, decoded.needed, max_memory);
    throw fail(io_failure(io));
  }

  Image image(static_cast<int>(decoded.width), static_cast<int>(decoded.height));
  const bool wide = decoded.bits == 16;
  const float max_value = wide ? 65535.0f : 255.0f;
  // Decoding table for 8-bit data: 256 pow() calls instead of one per sample.
  float lut8[kCodes8];
  for (int i = 0; i < kCodes8; ++i) {
    const float v = static_cast<float>(i) / static_cast<float>(kCodes8 - 1);
    lut8[i] = encoding == Encoding::SRGB ? srgb_to_linear(v) : v;
  }
  const std::size_t samples = image.rgb.size();
  for (std::size_t i = 0; i < samples; ++i) {
    if (wide) {
      const unsigned q = (decoded.pixels[2 * i] << 8) | decoded.pixels[2 * i + 1];
      const float v = static_cast<float>(q) / max_value;
      image.rgb[i] = encoding == Encoding::SRGB ? srgb_to_linear(v) : v;
    } else {
      image.rgb[i] = lut8[decoded.pixels[i]];
    }
  }
  return image;
}

}  // namespace rts::render
