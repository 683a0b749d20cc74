// PNG reading/writing: encodings, bit depths, non-finite values, atomic replacement, and
// graceful failure on missing directories, write errors and corrupt files.
#include <png.h>
#include <zlib.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include "render/image/image.hpp"
#include "tests/images/temp_dir.hpp"

using namespace rts::render;
using rts::images::TempDir;
namespace fs = std::filesystem;

namespace {

std::vector<char> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::vector<char>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The bit depth stored in the IHDR chunk (byte 24 of every PNG file).
int png_file_bit_depth(const std::string& path) {
  const auto bytes = file_bytes(path);
  REQUIRE(bytes.size() > 24);
  return static_cast<unsigned char>(bytes[24]);
}

// Names in `dir` other than `keep`: leftovers such as temp files.
std::vector<std::string> other_entries(const fs::path& dir, const std::string& keep) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().filename() != keep) names.push_back(entry.path().filename().string());
  }
  return names;
}

Image noise_image(int w, int h, unsigned seed) {
  Image image(w, h);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (float& v : image.rgb) v = unit(rng);
  return image;
}

// Writes an 8-bit PNG in any of libpng's simplified formats (gray, gray+alpha, RGBA,
// colormapped...) so that read_png meets layouts write_png never produces.
void write_simplified_png(const std::string& path, png_uint_32 format, int w, int h,
                          const std::vector<unsigned char>& pixels,
                          const std::vector<unsigned char>& colormap = {}) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(w);
  image.height = static_cast<png_uint_32>(h);
  image.format = format;
  if (!colormap.empty()) image.colormap_entries = static_cast<png_uint_32>(colormap.size() / 3);
  REQUIRE(png_image_write_to_file(&image, path.c_str(), 0, pixels.data(), 0,
                                  colormap.empty() ? nullptr : colormap.data()) != 0);
}

// Lowers the maximum file size this process may write, so a write fails part-way (EFBIG) just
// as it would on a full disk. SIGXFSZ is ignored meanwhile so the write returns an error.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    old_handler_ = signal(SIGXFSZ, SIG_IGN);
    rlimit lowered = saved_;
    lowered.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &lowered);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    signal(SIGXFSZ, old_handler_);
  }

 private:
  rlimit saved_{};
  void (*old_handler_)(int) = nullptr;
};

// Offset of the first chunk of `type` (its length field) in a PNG file, or npos.
std::size_t find_chunk(const std::vector<char>& png, const char* type) {
  std::size_t at = 8;   // after the signature
  while (at + 8 <= png.size()) {
    const auto* b = reinterpret_cast<const unsigned char*>(png.data() + at);
    const std::size_t length = (std::size_t{b[0]} << 24) | (b[1] << 16) | (b[2] << 8) | b[3];
    if (std::equal(type, type + 4, png.data() + at + 4)) return at;
    at += 12 + length;
  }
  return std::string::npos;
}

// Recomputes the CRC of the chunk at `at`, so libpng gets past the CRC check and meets the
// damage itself.
void fix_crc(std::vector<char>& png, std::size_t at) {
  const auto* b = reinterpret_cast<const unsigned char*>(png.data() + at);
  const std::size_t length = (std::size_t{b[0]} << 24) | (b[1] << 16) | (b[2] << 8) | b[3];
  const auto* typed = reinterpret_cast<const Bytef*>(png.data() + at + 4);
  const uLong crc = crc32(0L, typed, static_cast<uInt>(length + 4));
  for (int i = 0; i < 4; ++i) png[at + 8 + length + i] = static_cast<char>((crc >> (24 - 8 * i)) & 0xFF);
}

// A copy of `png` whose header (the IHDR chunk at `ihdr`) claims width x height, with its CRC
// fixed, so that libpng believes it.
std::vector<char> with_claimed_size(const std::vector<char>& png, std::size_t ihdr, uint32_t width, uint32_t height) {
  auto out = png;
  for (auto [field, value] : {std::pair{ihdr + 8, width}, std::pair{ihdr + 12, height}})
    for (int i = 0; i < 4; ++i) out[field + i] = static_cast<char>((value >> (24 - 8 * i)) & 0xFF);
  fix_crc(out, ihdr);
  return out;
}

}  // namespace

TEST_CASE("sRGB transfer functions match the standard", "[png]") {
  CHECK(linear_to_srgb(0.0f) == 0.0f);
  CHECK(linear_to_srgb(1.0f) == Approx(1.0f));
  CHECK(linear_to_srgb(0.5f) == Approx(0.735356983).epsilon(1e-6));
  CHECK(srgb_to_linear(0.5f) == Approx(0.214041144).epsilon(1e-6));
  // The linear segment near black.
  CHECK(linear_to_srgb(0.002f) == Approx(0.002f * 12.92f));
  CHECK(srgb_to_linear(0.04f) == Approx(0.04f / 12.92f));
  for (int i = 0; i <= 100; ++i) {
    const float v = static_cast<float>(i) / 100.0f;
    CHECK(linear_to_srgb(srgb_to_linear(v)) == Approx(v).margin(1e-6));
  }
}

TEST_CASE("8-bit sRGB round trip reproduces every code", "[png]") {
  TempDir dir;
  Image image(256, 1);
  for (int i = 0; i < 256; ++i) {
    const float linear = srgb_to_linear(static_cast<float>(i) / 255.0f);
    image.at(i, 0)[0] = linear;
    image.at(i, 0)[1] = linear;
    image.at(i, 0)[2] = srgb_to_linear(static_cast<float>(255 - i) / 255.0f);
  }
  const std::string path = dir.file("codes.png");
  write_png(path, image, 8, Encoding::SRGB);
  CHECK(png_file_bit_depth(path) == 8);

  const Image raw = read_png(path, {}, Encoding::Linear);   // the stored codes / 255
  const Image back = read_png(path);                        // decoded to linear
  REQUIRE(raw.width == 256);
  REQUIRE(raw.height == 1);
  for (int i = 0; i < 256; ++i) {
    CHECK(raw.at(i, 0)[0] * 255.0f == Approx(i).margin(1e-3));
    CHECK(raw.at(i, 0)[2] * 255.0f == Approx(255 - i).margin(1e-3));
    CHECK(back.at(i, 0)[1] == Approx(image.at(i, 0)[1]).margin(1e-6));
  }
}

TEST_CASE("8-bit sRGB encoding rounds every value to the nearest code", "[png]") {
  TempDir dir;
  constexpr int kWidth = 1000, kHeight = 100;   // 100000 values sweeping [0, 1]
  Image image(kWidth, kHeight);
  const double last = kWidth * kHeight - 1;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    float* p = image.at(i % kWidth, i / kWidth);
    p[0] = p[1] = p[2] = static_cast<float>(i / last);
  }
  const std::string path = dir.file("sweep.png");
  write_png(path, image, 8, Encoding::SRGB);
  const Image codes = read_png(path, {}, Encoding::Linear);
  int mismatches = 0;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const float v = image.at(i % kWidth, i / kWidth)[0];
    const double exact = static_cast<double>(linear_to_srgb(v)) * 255.0;
    const long want = std::lround(exact);
    const long got = std::lround(codes.at(i % kWidth, i / kWidth)[0] * 255.0f);
    // Only a value within float noise of a half code may round either way.
    const bool on_boundary = std::abs(exact - std::floor(exact) - 0.5) < 1e-4;
    if (got != want && !on_boundary) ++mismatches;
  }
  CHECK(mismatches == 0);
}

TEST_CASE("8-bit linear encoding rounds to the nearest code", "[png]") {
  TempDir dir;
  Image image(4, 1);
  const float below_half = 0.49f / 255.0f, above_half = 0.51f / 255.0f;
  const float values[4] = {10.0f / 255 + below_half, 10.0f / 255 + above_half, 0.0f, 1.0f};
  for (int x = 0; x < 4; ++x) image.at(x, 0)[0] = image.at(x, 0)[1] = image.at(x, 0)[2] = values[x];
  const std::string path = dir.file("round.png");
  write_png(path, image, 8, Encoding::Linear);
  const Image back = read_png(path, {}, Encoding::Linear);
  CHECK(back.at(0, 0)[0] * 255.0f == Approx(10.0f));
  CHECK(back.at(1, 0)[0] * 255.0f == Approx(11.0f));
  CHECK(back.at(2, 0)[0] == 0.0f);
  CHECK(back.at(3, 0)[0] == 1.0f);
}

TEST_CASE("16-bit round trip keeps 16-bit precision", "[png]") {
  TempDir dir;
  const Image image = noise_image(17, 9, 42);
  SECTION("linear") {
    const std::string path = dir.file("wide.png");
    write_png(path, image, 16, Encoding::Linear);
    CHECK(png_file_bit_depth(path) == 16);
    const Image back = read_png(path, {}, Encoding::Linear);
    REQUIRE(back.width == 17);
    REQUIRE(back.height == 9);
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
      CHECK(back.rgb[i] == Approx(image.rgb[i]).margin(0.5 / 65535.0 + 1e-7));
    }
  }
  SECTION("sRGB") {
    const std::string path = dir.file("wide-srgb.png");
    write_png(path, image, 16, Encoding::SRGB);
    const Image back = read_png(path);
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
      CHECK(back.rgb[i] == Approx(image.rgb[i]).margin(1e-4));
    }
  }
}

TEST_CASE("pixel rows are stored top row first", "[png]") {
  TempDir dir;
  Image image(2, 3);
  image.at(0, 0)[0] = 1.0f;   // top-left red
  image.at(1, 2)[2] = 1.0f;   // bottom-right blue
  const std::string path = dir.file("orientation.png");
  write_png(path, image);
  const Image back = read_png(path);
  CHECK(back.at(0, 0)[0] == 1.0f);
  CHECK(back.at(1, 2)[2] == 1.0f);
  CHECK(back.at(1, 0)[2] == 0.0f);
}

TEST_CASE("PNGs are written for speed: libdeflate level 1, SUB filter on every row", "[png]") {
  // Level 6 with adaptive filtering (libpng's default) was ~15% of a 1280x960 render; zlib
  // level 3 still 0.19 s at 1920x1080. The zlib stream header records the level class:
  // FLEVEL 0 is the fastest levels (libdeflate 0-1), 1 is 2-5, 2 is 6.
  TempDir dir;
  const int w = 64, h = 16;
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.at(x, y)[0] = image.at(x, y)[1] = static_cast<float>(x + y) / (w + h);
  const std::string path = dir.file("speed.png");
  write_png(path, image);
  const auto bytes = file_bytes(path);
  auto be32 = [&](std::size_t i) {
    return (static_cast<uint32_t>(static_cast<unsigned char>(bytes[i])) << 24) |
           (static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 16) |
           (static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 2])) << 8) |
           static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 3]));
  };
  std::vector<unsigned char> zdata;
  for (std::size_t i = 8; i + 8 <= bytes.size();) {  // chunks after the signature
    const uint32_t len = be32(i);
    const std::string type(bytes.begin() + static_cast<std::ptrdiff_t>(i + 4),
                           bytes.begin() + static_cast<std::ptrdiff_t>(i + 8));
    REQUIRE(i + 12 + len <= bytes.size());
    if (type == "IDAT") zdata.insert(zdata.end(), bytes.begin() + static_cast<std::ptrdiff_t>(i + 8),
                                     bytes.begin() + static_cast<std::ptrdiff_t>(i + 8 + len));
    i += 12 + len;
  }
  REQUIRE(zdata.size() > 2);
  CHECK((zdata[1] >> 6) == 0);  // FLEVEL: compressed with the fastest level
  std::vector<unsigned char> raw(static_cast<std::size_t>(h) * (1 + 3 * w));
  uLongf raw_len = static_cast<uLongf>(raw.size());
  REQUIRE(uncompress(raw.data(), &raw_len, zdata.data(), static_cast<uLong>(zdata.size())) == Z_OK);
  REQUIRE(raw_len == raw.size());
  for (int y = 0; y < h; ++y) CHECK(static_cast<int>(raw[static_cast<std::size_t>(y) * (1 + 3 * w)]) == 1);  // SUB
  const Image back = read_png(path);
  CHECK(back.at(w - 1, h - 1)[0] == Approx(image.at(w - 1, h - 1)[0]).margin(1.0 / 255));
}

TEST_CASE("NaN and infinite pixels never reach the file", "[png]") {
  TempDir dir;
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // -0 is 0 (its sign bit must not index the 8-bit encoder's table as a huge value).
  Image image(7, 1);
  const float values[7] = {nan, inf, -inf, 7.5f, -3.0f, -0.0f, -nan};
  const float expected[7] = {0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f};
  for (int x = 0; x < 7; ++x) image.at(x, 0)[0] = image.at(x, 0)[1] = image.at(x, 0)[2] = values[x];
  for (int bits : {8, 16}) {
    const std::string path = dir.file("nonfinite" + std::to_string(bits) + ".png");
    write_png(path, image, bits);
    const Image back = read_png(path);
    for (int x = 0; x < 7; ++x) {
      INFO("bits " << bits << " pixel " << x);
      CHECK(back.at(x, 0)[0] == expected[x]);
    }
  }
}

TEST_CASE("read_png expands gray, gray+alpha, RGBA and palette images to RGB", "[png]") {
  TempDir dir;
  SECTION("gray") {
    const std::string path = dir.file("gray.png");
    write_simplified_png(path, PNG_FORMAT_GRAY, 2, 1, {0, 255});
    const Image back = read_png(path, {}, Encoding::Linear);
    CHECK(back.at(0, 0)[0] == 0.0f);
    CHECK(back.at(1, 0)[0] == 1.0f);
    CHECK(back.at(1, 0)[1] == 1.0f);
    CHECK(back.at(1, 0)[2] == 1.0f);
  }
  SECTION("gray + alpha: alpha is dropped") {
    const std::string path = dir.file("ga.png");
    write_simplified_png(path, PNG_FORMAT_GA, 1, 1, {51, 0});
    const Image back = read_png(path, {}, Encoding::Linear);
    CHECK(back.at(0, 0)[0] * 255.0f == Approx(51.0f));
    CHECK(back.at(0, 0)[2] * 255.0f == Approx(51.0f));
  }
  SECTION("RGBA: alpha is dropped") {
    const std::string path = dir.file("rgba.png");
    write_simplified_png(path, PNG_FORMAT_RGBA, 1, 1, {255, 128, 0, 10});
    const Image back = read_png(path, {}, Encoding::Linear);
    CHECK(back.at(0, 0)[0] == 1.0f);
    CHECK(back.at(0, 0)[1] * 255.0f == Approx(128.0f));
    CHECK(back.at(0, 0)[2] == 0.0f);
  }
  SECTION("palette") {
    const std::string path = dir.file("palette.png");
    write_simplified_png(path, PNG_FORMAT_RGB_COLORMAP, 3, 1, {2, 0, 1},
                         {255, 0, 0, 0, 255, 0, 0, 0, 255});
    const Image back = read_png(path, {}, Encoding::Linear);
    CHECK(back.at(0, 0)[2] == 1.0f);   // index 2: blue
    CHECK(back.at(1, 0)[0] == 1.0f);   // index 0: red
    CHECK(back.at(2, 0)[1] == 1.0f);   // index 1: green
    CHECK(back.at(2, 0)[0] == 0.0f);
  }
}

TEST_CASE("write_png replaces an existing file atomically", "[png][atomic]") {
  TempDir dir;
  const std::string path = dir.file("out.png");
  write_png(path, noise_image(8, 8, 1));
  const auto old_bytes = file_bytes(path);

  SECTION("a successful write replaces the content and leaves no temp file") {
    write_png(path, noise_image(8, 8, 2));
    CHECK(file_bytes(path) != old_bytes);
    CHECK(other_entries(dir.path(), "out.png").empty());
  }
  SECTION("a write that fails part-way (file too large, as on a full disk) keeps the old file") {
    const Image big = noise_image(256, 256, 3);   // noise does not compress: ~200 KB
    try {
      FileSizeLimit limit(4096);
      write_png(path, big);
      FAIL("write_png should have failed");
    } catch (const RenderError& e) {
      const std::string message = e.what();
      CHECK_THAT(message, Catch::Contains("cannot write") && Catch::Contains(path));
    }
    CHECK(file_bytes(path) == old_bytes);
    CHECK(other_entries(dir.path(), "out.png").empty());
  }
  SECTION("a directory in the way is refused and left alone") {
    const std::string target = dir.file("taken");
    fs::create_directory(target);
    CHECK_THROWS_WITH(write_png(target, noise_image(4, 4, 4)), Catch::Contains("directory"));
    CHECK(fs::is_directory(target));
    CHECK(fs::is_empty(target));
    const auto left = other_entries(dir.path(), "out.png");
    CHECK(left == std::vector<std::string>{"taken"});
    CHECK(file_bytes(path) == old_bytes);
  }
}

TEST_CASE("write_png writes pipes and devices in place, never renaming over them", "[png]") {
  // (Not tested on /dev/full: a regression would replace the device node when run as root.
  // Write failures part-way are covered by the file-size-limit test above.)
  TempDir dir;
  const std::string fifo = dir.file("pipe");
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  std::vector<char> received;
  std::thread reader([&] { received = file_bytes(fifo); });   // blocks until a writer opens
  bool wrote = true;
  try {
    write_png(fifo, noise_image(3, 3, 8));
  } catch (const RenderError&) {
    wrote = false;
    std::ofstream unblock(fifo);   // let the reader's open() return before joining
  }
  reader.join();
  REQUIRE(wrote);
  CHECK(fs::is_fifo(fifo));
  REQUIRE(received.size() > 8);
  CHECK(received[1] == 'P');
  CHECK(received[2] == 'N');
  CHECK(received[3] == 'G');
  CHECK(other_entries(dir.path(), "pipe").empty());
}

TEST_CASE("write_png explains a missing directory and creates nothing", "[png][atomic]") {
  TempDir dir;
  const std::string path = dir.file("no/such/dir/out.png");
  try {
    write_png(path, noise_image(2, 2, 5));
    FAIL("write_png should have failed");
  } catch (const RenderError& e) {
    const std::string message = e.what();
    CHECK_THAT(message, Catch::Contains("does not exist") && Catch::Contains("no/such/dir"));
  }
  CHECK(fs::is_empty(dir.path()));
}

TEST_CASE("write_png refuses invalid arguments", "[png]") {
  TempDir dir;
  CHECK_THROWS_AS(write_png(dir.file("a.png"), noise_image(2, 2, 6), 12), RenderError);
  CHECK_THROWS_AS(write_png(dir.file("b.png"), Image{}), RenderError);
  Image inconsistent(2, 2);
  inconsistent.rgb.pop_back();
  CHECK_THROWS_AS(write_png(dir.file("c.png"), inconsistent), RenderError);
  CHECK(fs::is_empty(dir.path()));
}

TEST_CASE("read_png reports missing, foreign, truncated and corrupt files", "[png][corrupt]") {
  TempDir dir;
  const SourceRef where{"scene.rts", 12, 5};

  SECTION("missing file: located error") {
    try {
      read_png(dir.file("missing.png"), where);
      FAIL("read_png should have failed");
    } catch (const RenderError& e) {
      CHECK(std::string(e.where.file) == "scene.rts");
      CHECK(e.where.line == 12u);
      CHECK(e.where.col == 5u);
      CHECK_THAT(std::string(e.what()), Catch::Contains("missing.png"));
    }
  }
  SECTION("not a PNG") {
    const std::string path = dir.file("text.png");
    write_bytes(path, {'h', 'e', 'l', 'l', 'o', ' ', 'w', 'o', 'r', 'l', 'd'});
    CHECK_THROWS_WITH(read_png(path), Catch::Contains("not a PNG"));
  }
  SECTION("empty file") {
    const std::string path = dir.file("empty.png");
    write_bytes(path, {});
    CHECK_THROWS_AS(read_png(path), RenderError);
  }

  const std::string good = dir.file("good.png");
  write_png(good, noise_image(32, 32, 7));
  const auto bytes = file_bytes(good);
  REQUIRE(bytes.size() > 100);

  SECTION("truncated at every kind of place") {
    for (std::size_t keep : {std::size_t{8}, std::size_t{20}, std::size_t{33}, std::size_t{60},
                             bytes.size() / 2, bytes.size() - 13, bytes.size() - 1}) {
      INFO("kept " << keep << " of " << bytes.size() << " bytes");
      const std::string path = dir.file("truncated.png");
      write_bytes(path, std::vector<char>(bytes.begin(), bytes.begin() + keep));
      CHECK_THROWS_AS(read_png(path), RenderError);
    }
  }
  SECTION("corrupted bytes (CRC and zlib errors)") {
    for (std::size_t offset : {std::size_t{16}, std::size_t{29}, bytes.size() / 2}) {
      INFO("byte " << offset << " flipped");
      auto damaged = bytes;
      damaged[offset] = static_cast<char>(damaged[offset] ^ 0x5A);
      const std::string path = dir.file("corrupt.png");
      write_bytes(path, damaged);
      CHECK_THROWS_AS(read_png(path), RenderError);
    }
  }
}

TEST_CASE("read_png survives damaged data behind valid CRCs", "[png][corrupt]") {
  TempDir dir;
  const std::string good = dir.file("good.png");
  write_png(good, noise_image(40, 30, 11));
  const auto bytes = file_bytes(good);
  const std::size_t idat = find_chunk(bytes, "IDAT");
  const std::size_t ihdr = find_chunk(bytes, "IHDR");
  REQUIRE(idat != std::string::npos);
  REQUIRE(ihdr != std::string::npos);
  const std::string path = dir.file("damaged.png");

  SECTION("a header claiming a gigantic image is refused before allocating it") {
    const auto huge = with_claimed_size(bytes, ihdr, 60000, 60000);
    write_bytes(path, huge);
    CHECK_THROWS_AS(read_png(path), RenderError);
  }
  SECTION("a header claiming more rows than the file's data can hold is refused by name") {
    // 5000x5000 RGB is 75 MB of rows: past what deflate can pack into this ~4 kB file (at most
    // 1032:1), though under the 100-megapixel cap. Refused before the rows are allocated.
    const auto claims = with_claimed_size(bytes, ihdr, 5000, 5000);
    write_bytes(path, claims);
    CHECK_THROWS_WITH(read_png(path), Catch::Contains("claims 5000x5000 pixels, more than its") &&
                                          Catch::Contains("damaged or truncated"));
  }
  SECTION("a highly compressible image near deflate's best ratio still reads") {
    // 3000x1000 gray zeros through libpng's zlib: ~3 MB of rows in a few kB of file, close to
    // deflate's 1032:1, must not be taken for a lying header.
    write_simplified_png(path, PNG_FORMAT_GRAY, 3000, 1000, std::vector<unsigned char>(3000 * 1000, 0));
    REQUIRE(3000.0 * 1000.0 / static_cast<double>(file_bytes(path).size()) > 500.0);
    const Image back = read_png(path);
    CHECK(back.width == 3000);
    CHECK(back.height == 1000);
    CHECK(*std::max_element(back.rgb.begin(), back.rgb.end()) == 0.0f);
  }
  SECTION("random damage to the compressed pixels: an error or an image, never a crash") {
    std::mt19937 rng(1234);
    const std::size_t data_begin = idat + 8;
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + idat);
    const std::size_t data_length = (std::size_t{b[0]} << 24) | (b[1] << 16) | (b[2] << 8) | b[3];
    std::uniform_int_distribution<std::size_t> where(data_begin, data_begin + data_length - 1);
    std::uniform_int_distribution<int> value(0, 255);
    int refused = 0, decoded = 0;
    for (int trial = 0; trial < 200; ++trial) {
      auto damaged = bytes;
      for (int k = 0; k <= trial % 4; ++k) damaged[where(rng)] = static_cast<char>(value(rng));
      fix_crc(damaged, idat);
      write_bytes(path, damaged);
      try {
        const Image image = read_png(path);
        CHECK(image.width == 40);
        CHECK(image.height == 30);
        ++decoded;
      } catch (const RenderError&) {
        ++refused;
      }
    }
    CHECK(refused + decoded == 200);
    CHECK(refused > 0);   // most damage to a deflate stream is detected
  }
}
