// ChunkedVector (render/scene/chunked_vector.hpp), the scene description's shape array: it
// behaves as a vector across chunk boundaries, and growing never moves a full chunk.
#include <catch2/catch.hpp>

#include <memory>
#include <stdexcept>
#include <string>

#include "render/scene/chunked_vector.hpp"

using rts::render::ChunkedVector;

TEST_CASE("a chunked vector indexes, iterates and copies like a vector across its chunks", "[chunked_vector]") {
  constexpr std::size_t n = 2 * ChunkedVector<int>::kChunk + 3;  // two full chunks and a part
  ChunkedVector<std::string> v;
  CHECK(v.empty());
  const std::string* first = nullptr;
  for (std::size_t i = 0; i < n; ++i) {
    v.push_back(std::to_string(i));
    if (i + 1 == ChunkedVector<int>::kChunk) first = &v[0];  // the first chunk is full
  }
  CHECK(&v[0] == first);  // a full chunk is never moved by growing past it
  REQUIRE(v.size() == n);
  CHECK(v.back() == std::to_string(n - 1));
  std::size_t i = 0;
  for (const std::string& s : v) CHECK(s == std::to_string(i++));
  CHECK(i == n);
  for (std::size_t k : {std::size_t{0}, ChunkedVector<int>::kChunk - 1, ChunkedVector<int>::kChunk, n - 1})
    CHECK(v.at(k) == std::to_string(k));
  CHECK_THROWS_AS(v.at(n), std::out_of_range);

  ChunkedVector<std::string> copy = v;
  copy[ChunkedVector<int>::kChunk] = "changed";
  copy.push_back("one more");
  CHECK(v[ChunkedVector<int>::kChunk] == std::to_string(ChunkedVector<int>::kChunk));  // a deep copy
  CHECK(copy.size() == n + 1);
  CHECK(copy.back() == "one more");

  ChunkedVector<std::string> empty;
  empty.swap(copy);
  CHECK(copy.empty());
  CHECK(empty.size() == n + 1);
  empty.clear();
  CHECK(empty.empty());
  CHECK(empty.begin() == empty.end());
}

TEST_CASE("a chunked vector holds move-only elements", "[chunked_vector]") {
  ChunkedVector<std::unique_ptr<int>> v;
  for (int i = 0; i < 5000; ++i) v.emplace_back(std::make_unique<int>(i));
  CHECK(*v[4999] == 4999);
  CHECK(*v.at(4096) == 4096);
}
