#include "render/geometry/shapes/mesh_closure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace rts::render {

namespace {

struct PositionKey {
  uint32_t bits[3];
  bool operator==(const PositionKey& o) const {
    return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
  }
};
struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    uint64_t h = 1469598103934665603ull;
    for (uint32_t b : k.bits) h = (h ^ b) * 1099511628211ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

struct EdgeUse {
  int32_t net = 0;     // walks from the lower vertex id to the higher, minus the other way
  uint32_t total = 0;  // every walk
  uint32_t a = 0, b = 0;  // as first walked (vertex ids), for the message
};

}  // namespace

MeshClosure mesh_closure(const MeshData& mesh) {
  MeshClosure out;
  const std::size_t n = mesh.positions.size();
  // One id per distinct position (+0 and -0 are one: both are zero).
  std::unordered_map<PositionKey, uint32_t, PositionHash> ids;
  std::vector<uint32_t> id_of(n, UINT32_MAX);
  std::vector<uint32_t> first_index;  // id -> a position index with it
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3& p = mesh.positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    PositionKey k;
    for (int a = 0; a < 3; ++a) {
      float v = p[a] == 0.0f ? 0.0f : p[a];
      std::memcpy(&k.bits[a], &v, sizeof v);
    }
    auto [it, fresh] = ids.emplace(k, static_cast<uint32_t>(first_index.size()));
    if (fresh) first_index.push_back(static_cast<uint32_t>(i));
    id_of[i] = it->second;
  }
  std::unordered_map<uint64_t, EdgeUse> edges;
  edges.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t v[3];
    bool valid = true;
    for (int k = 0; k < 3; ++k) {
      const uint32_t idx = mesh.indices[t + k];
      valid = valid && idx < n && id_of[idx] != UINT32_MAX;
      v[k] = valid ? id_of[idx] : 0;
    }
    if (!valid) continue;  // never hit (MeshAccel leaves it out), so it bounds nothing
    ++out.triangles;
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = v[k], b = v[(k + 1) % 3];
      if (a == b) continue;  // a collapsed edge walks nowhere
      const uint64_t key = (static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      EdgeUse& e = edges[key];
      if (e.total == 0) {
        e.a = a;
        e.b = b;
      }
      e.net += a < b ? 1 : -1;
      ++e.total;
    }
  }
  // Count the unbalanced edges; report the one with the smallest key (the same on every run).
  uint64_t reported = UINT64_MAX;
  for (const auto& [key, e] : edges) {
    if (e.net == 0) continue;
    ++out.open_edges;
    if (e.total >= 2 && static_cast<uint32_t>(std::abs(e.net)) == e.total) out.inconsistent = true;
    if (key < reported) {
      reported = key;
      out.edge_from = Vec3(mesh.positions[first_index[e.a]]) + mesh.origin;
      out.edge_to = Vec3(mesh.positions[first_index[e.b]]) + mesh.origin;
    }
  }
  out.closed = out.triangles > 0 && out.open_edges == 0;
  return out;
}

}  // namespace rts::render
