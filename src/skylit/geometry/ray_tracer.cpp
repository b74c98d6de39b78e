// RayTracer on Embree 3: one device and one scene per tracer, one Embree triangle
// geometry per mesh, single-ray queries (see ray_tracer.h).
#include "skylit/geometry/ray_tracer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

#include <tbb/task_arena.h>

namespace skylit {
namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool valid(const Ray& ray) {
  // Embree's behaviour for NaN/inf rays is undefined unless it was built to
  // ignore them, so they are turned away here.
  return finite(ray.origin) && finite(ray.direction) && !std::isnan(ray.t_min) && !std::isnan(ray.t_max) &&
         ray.t_min <= ray.t_max;
}

// Embree wants 0 <= tnear <= tfar.
void set_ray(RTCRay& r, const Ray& ray) {
  r.org_x = static_cast<float>(ray.origin.x);
  r.org_y = static_cast<float>(ray.origin.y);
  r.org_z = static_cast<float>(ray.origin.z);
  r.dir_x = static_cast<float>(ray.direction.x);
  r.dir_y = static_cast<float>(ray.direction.y);
  r.dir_z = static_cast<float>(ray.direction.z);
  r.tnear = static_cast<float>(std::max(ray.t_min, 0.0));
  r.tfar = static_cast<float>(ray.t_max);
  r.time = 0.0f;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
}

// Embree's filter callbacks: a hit the mesh's HitFilter refuses is marked invalid, and
// Embree goes on to the next one along the ray.
template <bool kShadow>
void filter_hits(const RTCFilterFunctionNArguments* args) {
  const auto* filter = static_cast<const HitFilter*>(args->geometryUserPtr);
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    RTCRayN* r = args->ray;
    RTCHitN* h = args->hit;
    const unsigned int n = args->N;
    const Vec3 direction{RTCRayN_dir_x(r, n, i), RTCRayN_dir_y(r, n, i), RTCRayN_dir_z(r, n, i)};
    const Vec3 normal{RTCHitN_Ng_x(h, n, i), RTCHitN_Ng_y(h, n, i), RTCHitN_Ng_z(h, n, i)};
    if (!filter->accepts(RTCHitN_primID(h, n, i), RTCHitN_u(h, n, i), RTCHitN_v(h, n, i), direction, normal, kShadow))
      args->valid[i] = 0;
  }
}

}  // namespace

struct RayTracer::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  uint32_t mesh_count = 0;
  size_t triangle_count = 0;
  bool committed = false;
  // Queries traced, counted where they are traced (no counter threaded through the
  // callers): one cache line per TBB worker slot, which only one thread uses at a time,
  // so a plain load and store suffice (no locked instruction per ray). Threads outside
  // TBB's workers share the last slot and may lose a count to each other: these are
  // statistics for the benchmark. (A thread-specific container's look-up cost 0.6 % of
  // a lamp-lit frame, an atomic increment about as much.)
  struct alignas(64) QueryCount {
    std::atomic<uint64_t> value{0};
  };
  static constexpr int kCountSlots = 64;
  mutable std::array<QueryCount, kCountSlots> queries{};
  void count_query() const {
    const int slot = tbb::this_task_arena::current_thread_index();  // -1 outside TBB's threads
    std::atomic<uint64_t>& count = queries[static_cast<size_t>(slot >= 0 ? slot % kCountSlots : kCountSlots - 1)].value;
    count.store(count.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  }

  // Embree reports errors through a callback, possibly from its build threads.
  // Throwing from inside Embree's C API is not safe, so the first error is kept
  // here and thrown by check() once control is back in our code.
  std::mutex error_mutex;
  RTCError error = RTC_ERROR_NONE;
  std::string error_message;

  static void on_error(void* user, RTCError code, const char* message) {
    auto* self = static_cast<Impl*>(user);
    std::lock_guard lock(self->error_mutex);
    if (self->error != RTC_ERROR_NONE) return;
    self->error = code;
    self->error_message = message ? message : "";
  }

  void check(const char* call) {
    std::lock_guard lock(error_mutex);
    if (error == RTC_ERROR_NONE) return;
    const std::string text =
        std::string("Embree error in ") + call + " (code " + std::to_string(error) + "): " + error_message;
    error = RTC_ERROR_NONE;
    error_message.clear();
    throw std::runtime_error(text);
  }

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

RayTracer::RayTracer() : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device)
    throw std::runtime_error("Embree: cannot create a device (error code " +
                             std::to_string(rtcGetDeviceError(nullptr)) + ")");
  rtcSetDeviceErrorFunction(impl_->device, &Impl::on_error, impl_.get());
  // A build with back-face culling would let shadow rays pass through walls seen
  // from behind; refuse it rather than render wrong shadows.
  if (rtcGetDeviceProperty(impl_->device, RTC_DEVICE_PROPERTY_BACKFACE_CULLING_ENABLED))
    throw std::runtime_error("Embree was built with back-face culling, which skylit cannot use");

  impl_->scene = rtcNewScene(impl_->device);
  impl_->check("rtcNewScene");
  if (!impl_->scene) throw std::runtime_error("Embree: cannot create a scene");
  // ROBUST makes the triangle test watertight: a ray through an edge or vertex
  // shared by two triangles hits one of them. Without it such rays can slip
  // through both, which shows as light leaking through box edges and building
  // corners into shadows. Static scene: spend build time for faster queries.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  impl_->check("rtcSetSceneFlags");
}

RayTracer::~RayTracer() = default;
RayTracer::RayTracer(RayTracer&&) noexcept = default;
RayTracer& RayTracer::operator=(RayTracer&&) noexcept = default;

uint32_t RayTracer::add_mesh(const TriangleMesh& mesh, const HitFilter* filter) {
  Impl& im = *impl_;
  const uint32_t id = im.mesh_count;
  for (const Vec3& v : mesh.vertices)
    if (!std::isfinite(static_cast<float>(v.x)) || !std::isfinite(static_cast<float>(v.y)) ||
        !std::isfinite(static_cast<float>(v.z)))
      throw std::invalid_argument("RayTracer::add_mesh: mesh " + std::to_string(id) +
                                  " has a coordinate that is not a finite single-precision number");
  for (const auto& t : mesh.triangles)
    for (uint32_t index : t)
      if (index >= mesh.vertices.size())
        throw std::invalid_argument("RayTracer::add_mesh: mesh " + std::to_string(id) + " refers to vertex " +
                                    std::to_string(index) + " of " + std::to_string(mesh.vertices.size()));

  ++im.mesh_count;
  if (mesh.triangles.empty()) return id;  // nothing to trace; the id is still taken

  RTCGeometry geometry = rtcNewGeometry(im.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  im.check("rtcNewGeometry");
  if (!geometry) throw std::runtime_error("Embree: cannot create a triangle geometry");
  // Release the geometry on every path; the scene keeps its own reference.
  struct Release {
    RTCGeometry g;
    ~Release() { rtcReleaseGeometry(g); }
  } release{geometry};

  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), mesh.vertices.size()));
  im.check("rtcSetNewGeometryBuffer(vertex)");
  if (!vertices) throw std::runtime_error("Embree: cannot allocate a vertex buffer");
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    vertices[3 * i + 0] = static_cast<float>(mesh.vertices[i].x);
    vertices[3 * i + 1] = static_cast<float>(mesh.vertices[i].y);
    vertices[3 * i + 2] = static_cast<float>(mesh.vertices[i].z);
  }
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(uint32_t), mesh.triangles.size()));
  im.check("rtcSetNewGeometryBuffer(index)");
  if (!indices) throw std::runtime_error("Embree: cannot allocate an index buffer");
  for (size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) indices[3 * i + k] = mesh.triangles[i][k];

  if (filter != nullptr) {
    if (!rtcGetDeviceProperty(im.device, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED))
      throw std::runtime_error("Embree was built without filter functions, which masked and one-sided surfaces need");
    rtcSetGeometryUserData(geometry, const_cast<HitFilter*>(filter));  // only read, by filter_hits
    rtcSetGeometryIntersectFilterFunction(geometry, &filter_hits<false>);
    rtcSetGeometryOccludedFilterFunction(geometry, &filter_hits<true>);
  }
  rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
  rtcCommitGeometry(geometry);
  im.check("rtcCommitGeometry");
  // By id so that ids stay equal to call order even though empty meshes are
  // never attached.
  rtcAttachGeometryByID(im.scene, geometry, id);
  im.check("rtcAttachGeometryByID");

  im.triangle_count += mesh.triangles.size();
  im.committed = false;
  return id;
}

void RayTracer::commit() {
  rtcCommitScene(impl_->scene);
  impl_->check("rtcCommitScene");
  impl_->committed = true;
}

std::optional<Hit> RayTracer::intersect(const Ray& ray) const {
  if (!impl_->committed) throw std::logic_error("RayTracer::intersect before commit()");
  impl_->count_query();
  if (!valid(ray)) return std::nullopt;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  set_ray(rh.ray, ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  // Embree's Ng is cross(v1 - v0, v2 - v0) (for its default right-handed
  // convention), unnormalised.
  Vec3 n{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
  const double len = length(n);
  n = len > 0 ? n / len : Vec3{0, 0, 0};
  return Hit{static_cast<double>(rh.ray.tfar), n, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v};
}

void RayTracer::intersect(std::span<const Ray> rays, std::vector<std::optional<Hit>>& hits) const {
  if (!impl_->committed) throw std::logic_error("RayTracer::intersect before commit()");
  hits.assign(rays.size(), std::nullopt);
  constexpr size_t kPacket = 16;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(64) RTCRayHit16 packet;
  alignas(64) std::array<int, kPacket> active;
  for (size_t first = 0; first < rays.size(); first += kPacket) {
    const size_t count = std::min(kPacket, rays.size() - first);
    for (size_t i = 0; i < kPacket; ++i) {
      const bool use = i < count && valid(rays[first + i]);
      if (i < count) impl_->count_query();
      active[i] = use ? -1 : 0;
      if (!use) continue;
      const Ray& ray = rays[first + i];
      RTCRay16& r = packet.ray;
      r.org_x[i] = static_cast<float>(ray.origin.x);
      r.org_y[i] = static_cast<float>(ray.origin.y);
      r.org_z[i] = static_cast<float>(ray.origin.z);
      r.dir_x[i] = static_cast<float>(ray.direction.x);
      r.dir_y[i] = static_cast<float>(ray.direction.y);
      r.dir_z[i] = static_cast<float>(ray.direction.z);
      r.tnear[i] = static_cast<float>(std::max(ray.t_min, 0.0));
      r.tfar[i] = static_cast<float>(ray.t_max);
      r.time[i] = 0.0f;
      r.mask[i] = 0xFFFFFFFFu;
      r.id[i] = 0;
      r.flags[i] = 0;
      packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.primID[i] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(active.data(), impl_->scene, &context, &packet);
    for (size_t i = 0; i < count; ++i) {
      if (!active[i] || packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
      Vec3 n{packet.hit.Ng_x[i], packet.hit.Ng_y[i], packet.hit.Ng_z[i]};
      const double len = length(n);
      n = len > 0 ? n / len : Vec3{0, 0, 0};
      hits[first + i] = Hit{static_cast<double>(packet.ray.tfar[i]),
                            n,
                            packet.hit.geomID[i],
                            packet.hit.primID[i],
                            packet.hit.u[i],
                            packet.hit.v[i]};
    }
  }
}

bool RayTracer::occluded(const Ray& ray) const {
  if (!impl_->committed) throw std::logic_error("RayTracer::occluded before commit()");
  impl_->count_query();
  if (!valid(ray)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r;
  set_ray(r, ray);
  rtcOccluded1(impl_->scene, &context, &r);
  // Embree marks a blocked ray by setting tfar to -inf.
  return r.tfar < 0.0f;
}

uint64_t RayTracer::rays_traced() const {
  uint64_t total = 0;
  for (const Impl::QueryCount& count : impl_->queries) total += count.value.load(std::memory_order_relaxed);
  return total;
}

size_t RayTracer::triangle_count() const { return impl_->triangle_count; }
size_t RayTracer::mesh_count() const { return impl_->mesh_count; }

}  // namespace skylit
