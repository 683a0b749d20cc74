// ChunkedVector (render/scene/chunked_vector.hpp), the scene description's shape array: it
// behaves as a vector across chunk boundaries, and growing never moves a full chunk.
#include <catch2/catch.hpp>

#include <memory>
#include <stdexcept>
#include <string>

#include "render/scene/chunked_vector.hpp"
#include "render/scene/scene.hpp"

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

TEST_CASE("a chunk released ahead of the rest frees its elements and only those", "[chunked_vector]") {
  using V = ChunkedVector<std::shared_ptr<int>>;
  V v;
  for (std::size_t i = 0; i < 2 * V::kChunk + 5; ++i) v.push_back(std::make_shared<int>(static_cast<int>(i)));
  REQUIRE(v.chunk_count() == 3);
  CHECK(V::chunk_of(V::kChunk - 1) == 0);
  CHECK(V::chunk_of(V::kChunk) == 1);
  const std::weak_ptr<int> in_first = v[0], in_middle = v[V::kChunk + 7], in_last = v[2 * V::kChunk];
  CHECK(v.chunk_capacity_bytes(1) == V::kChunk * sizeof(std::shared_ptr<int>));
  v.release_chunk(1);
  CHECK(in_middle.expired());  // the chunk's elements are destroyed, its block freed
  CHECK(v.chunk_capacity_bytes(1) == 0);
  CHECK_FALSE(in_first.expired());
  CHECK_FALSE(in_last.expired());
  CHECK(*v[V::kChunk - 1] == static_cast<int>(V::kChunk - 1));
  CHECK(*v[2 * V::kChunk + 4] == static_cast<int>(2 * V::kChunk + 4));
  CHECK(v.size() == 2 * V::kChunk + 5);  // the indices of the others are unchanged
}

TEST_CASE("grow_to appends default elements and never shrinks", "[chunked_vector]") {
  ChunkedVector<int> v;
  v.grow_to(ChunkedVector<int>::kChunk + 2);
  REQUIRE(v.size() == ChunkedVector<int>::kChunk + 2);
  CHECK(v[0] == 0);
  CHECK(v.back() == 0);
  v.back() = 7;
  v.grow_to(3);
  CHECK(v.size() == ChunkedVector<int>::kChunk + 2);
  CHECK(v.back() == 7);
}

// SceneDesc::roots (render/scene/child_runs.hpp): placements kept as runs give back exactly
// the children placed, in order, whatever breaks a run.
TEST_CASE("the world's placements kept as runs read back as placed", "[chunked_vector][roots]") {
  using namespace rts::render;
  static const char* const kFile = "a.rts";
  static const char* const kOther = "b.rts";
  std::vector<Child> placed;
  auto add = [&](NodeId node, const ChildTransform& t, SourceRef loc) { placed.push_back(Child{node, t, loc}); };
  const SourceRef at{kFile, 3, 5};
  // A loop's spheres: consecutive nodes, no transform, one place in the file.
  for (NodeId n = 0; n < 10000; ++n) add(n, ChildTransform{}, at);
  add(10000, ChildTransform{}, SourceRef{kFile, 3, 6});   // another column
  add(10001, ChildTransform{}, SourceRef{kOther, 3, 5});  // another file, same position
  add(10001, ChildTransform{}, SourceRef{kOther, 3, 5});  // the same node again
  Mat4 moved(1.0);
  moved[3] = glm::dvec4(1, 2, 3, 1);
  const ChildTransform shared(moved);
  add(10002, shared, at);
  add(10003, shared, at);                  // the same block: one run
  add(10004, ChildTransform(moved), at);   // an equal matrix made apart: a run of its own
  add(20000, ChildTransform{}, at);        // a gap in the nodes
  add(20001, ChildTransform{}, at);

  ChildRuns<Child> runs;
  for (const Child& c : placed) runs.push_back(c);
  REQUIRE(runs.size() == placed.size());
  CHECK(runs.run_count() == 8);
  std::size_t i = 0;
  for (const Child& c : runs) {
    REQUIRE(i < placed.size());
    CHECK(c.node == placed[i].node);
    CHECK(c.transform.matrix() == placed[i].transform.matrix());
    CHECK(c.transform.same_block(placed[i].transform));
    CHECK(std::string(c.loc.file) == placed[i].loc.file);
    CHECK(c.loc.line == placed[i].loc.line);
    CHECK(c.loc.col == placed[i].loc.col);
    ++i;
  }
  CHECK(i == placed.size());
  ChildRuns<Child> empty;
  CHECK(empty.begin() == empty.end());
}
