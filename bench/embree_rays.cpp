// Embree 3 against rts's own mesh BVH on the same rays (issue 12: "within reach of Embree on
// meshes"), for bench/race.sh and docs/performance.md:
//
//   rts-bench-embree MESH.obj [W H [THREADS]]
//
// Loads the mesh once (rts's OBJ loader), then for each kernel: builds its acceleration
// structure (timed), traces one camera ray per pixel centre with race scene "terrain"'s camera
// (position <0, 6, -14>, look_at <0, 0, 0>, 60 degree horizontal field of view) and, from each
// hit, one shadow ray to its point light <-10, 20, -10>: the rays rts's render phase traces for
// that scene, without the shading. Rows are spread over THREADS threads (oneTBB). Prints build
// time and traversal throughput in Mrays/s per kernel, and checks that both kernels agree on
// which rays hit (a disagreement beyond a handful of grazing rays would be a bug).
// Embree runs in robust mode (RTC_SCENE_FLAG_ROBUST: watertight, as rts's triangle test must be).
#include <embree3/rtcore.h>
#include <sys/resource.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "render/sample/camera.hpp"
#include "render/accel/mesh_accel.hpp"
#include "render/builder/obj_loader.hpp"

using namespace rts::render;

namespace {

const Vec3 kLight(-10, 20, -10);

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

long peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024;
}

struct Counts {
  long camera = 0, hits = 0, shadow = 0, blocked = 0;
};

// Traces every pixel's camera ray and a shadow ray from each hit; `trace` answers the closest
// hit distance (or a negative value) and the geometric normal; `occluded` a shadow ray.
template <class Closest, class Occluded>
Counts trace_all(const Camera& camera, int w, int h, Closest&& closest, Occluded&& occluded) {
  tbb::enumerable_thread_specific<Counts> local;
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 4), [&](const tbb::blocked_range<int>& rows) {
    Counts& c = local.local();
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < w; ++x) {
        Ray ray = camera.generate(x + 0.5, y + 0.5, glm::dvec2(0.5));
        ++c.camera;
        Vec3 normal;
        double t = closest(ray, normal);
        if (t < 0) continue;
        ++c.hits;
        Vec3 p = ray.at(t);
        Vec3 n = glm::normalize(normal);
        Vec3 to_light = kLight - p;
        double dist = glm::length(to_light);
        Vec3 dir = to_light / dist;
        Ray shadow{offset_ray_origin(p, n, dir, t), dir};
        ++c.shadow;
        if (occluded(shadow, dist * (1 - 1e-9))) ++c.blocked;
      }
  });
  Counts total;
  for (const Counts& c : local) {
    total.camera += c.camera;
    total.hits += c.hits;
    total.shadow += c.shadow;
    total.blocked += c.blocked;
  }
  return total;
}

void report(const char* name, double build, double trace, const Counts& c, std::size_t tris) {
  long rays = c.camera + c.shadow;
  std::printf("%s: build %.3f s (%.1f M triangles/s), trace %.3f s for %.2fM rays (%ld camera, %ld shadow, "
              "%ld hits, %ld blocked) = %.2f Mrays/s\n",
              name, build, tris / build / 1e6, trace, rays / 1e6, c.camera, c.shadow, c.hits, c.blocked,
              rays / trace / 1e6);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: rts-bench-embree MESH.obj [W H [THREADS]]\n");
    return 2;
  }
  std::string path = argv[1];
  int w = argc > 3 ? std::atoi(argv[2]) : 800, h = argc > 3 ? std::atoi(argv[3]) : 600;
  int threads = argc > 4 ? std::atoi(argv[4]) : 2;
  if (w <= 0 || h <= 0 || threads <= 0) return 2;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  std::shared_ptr<MeshData> mesh = load_obj(path, path, false, SourceRef{});
  std::size_t tris = mesh->indices.size() / 3;
  CameraDesc desc;
  desc.position = Vec3(0, 6, -14);
  desc.look_at = Vec3(0, 0, 0);
  desc.fov = 60;
  Camera camera(desc, w, h);
  long rss_loaded = peak_rss_mb();

  // ---- rts: MeshAccel (the bottom level of rts's two-level BVH) ----
  double t0 = now();
  MeshAccel accel(mesh);
  double rts_build = now() - t0;
  t0 = now();
  Counts rc = trace_all(
      camera, w, h,
      [&](const Ray& ray, Vec3& normal) {
        SurfaceHit hit;
        if (!accel.intersect(ray, Interval(0.0, Interval::kInfinity), hit, false)) return -1.0;
        normal = hit.normal;
        return hit.t;
      },
      [&](const Ray& ray, double tmax) { return accel.occluded(ray, Interval(0.0, tmax)); });
  double rts_trace = now() - t0;
  report("rts MeshAccel", rts_build, rts_trace, rc, tris);

  // ---- Embree 3, robust, same triangles (float vertices, as rts stores them) ----
  RTCDevice device = rtcNewDevice(("threads=" + std::to_string(threads)).c_str());
  if (device == nullptr) {
    std::fprintf(stderr, "rtcNewDevice failed\n");
    return 3;
  }
  t0 = now();
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                         3 * sizeof(float), mesh->positions.size()));
  for (std::size_t i = 0; i < mesh->positions.size(); ++i) {
    vb[3 * i] = mesh->positions[i].x;
    vb[3 * i + 1] = mesh->positions[i].y;
    vb[3 * i + 2] = mesh->positions[i].z;
  }
  auto* ib = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris));
  for (std::size_t i = 0; i < mesh->indices.size(); ++i) ib[i] = mesh->indices[i];
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene);
  double embree_build = now() - t0;
  t0 = now();
  Counts ec = trace_all(
      camera, w, h,
      [&](const Ray& ray, Vec3& normal) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRayHit rh{};
        rh.ray.org_x = static_cast<float>(ray.origin.x);
        rh.ray.org_y = static_cast<float>(ray.origin.y);
        rh.ray.org_z = static_cast<float>(ray.origin.z);
        rh.ray.dir_x = static_cast<float>(ray.direction.x);
        rh.ray.dir_y = static_cast<float>(ray.direction.y);
        rh.ray.dir_z = static_cast<float>(ray.direction.z);
        rh.ray.tnear = 0.0f;
        rh.ray.tfar = INFINITY;
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1.0;
        normal = Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
        if (glm::dot(normal, ray.direction) > 0) normal = -normal;
        return static_cast<double>(rh.ray.tfar);
      },
      [&](const Ray& ray, double tmax) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRay r{};
        r.org_x = static_cast<float>(ray.origin.x);
        r.org_y = static_cast<float>(ray.origin.y);
        r.org_z = static_cast<float>(ray.origin.z);
        r.dir_x = static_cast<float>(ray.direction.x);
        r.dir_y = static_cast<float>(ray.direction.y);
        r.dir_z = static_cast<float>(ray.direction.z);
        // Embree works in float: start the shadow ray past the float rounding of its origin
        // (rts's offset is sized for its double-precision hit points), or it hits its own triangle.
        r.tnear = static_cast<float>(1e-5 * std::max(1.0, max_abs_component(ray.origin)));
        r.tfar = static_cast<float>(tmax);
        r.mask = ~0u;
        rtcOccluded1(scene, &ctx, &r);
        return r.tfar < 0.0f;  // Embree sets tfar to -inf when occluded
      });
  double embree_trace = now() - t0;
  report("Embree 3 (robust)", embree_build, embree_trace, ec, tris);
  std::printf("rts / Embree: traversal throughput %.2f, build rate %.2f; hits agree on %ld of %ld camera rays; "
              "peak RSS %ld MB (%ld MB after loading)\n",
              (rc.camera + rc.shadow) / rts_trace / ((ec.camera + ec.shadow) / embree_trace), embree_build / rts_build,
              rc.hits == ec.hits ? rc.camera : rc.camera - std::labs(rc.hits - ec.hits), rc.camera, peak_rss_mb(),
              rss_loaded);
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
  return 0;
}
