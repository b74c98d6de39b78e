// Primary visibility, traced once per frame: what the ray through each pixel's centre
// meets (a G-buffer). The sky-light cache, the lamps' glow image, the first pass of
// the image loop and its edge detection all read it, so no centre ray is traced twice.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "skylit/core/huge_pages.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/render/camera.h"
#include "skylit/render/surface_point.h"

namespace skylit {

// What a camera ray meets: a surface of an object (the tracer's mesh id), or the sky.
struct PrimaryHit {
  static constexpr uint32_t kSky = std::numeric_limits<uint32_t>::max();
  uint32_t mesh = kSky;
  SurfacePoint point{{}, {}, std::numeric_limits<double>::infinity(), 0};  // valid unless sky

  bool is_sky() const { return mesh == kSky; }
  double distance() const { return point.distance; }  // infinite for the sky
};

class PrimaryHits {
 public:
  using Trace = std::function<PrimaryHit(const Ray& ray)>;
  // Traces the centre of every pixel of a width × height image, in parallel (in the
  // calling TBB arena).
  PrimaryHits(const ImageCamera& camera, int width, int height, const Trace& trace);

  int width() const { return width_; }
  int height() const { return height_; }
  const PrimaryHit& at(int x, int y) const { return hits_[static_cast<size_t>(y) * width_ + x]; }
  // The surface seen at a pixel's centre; null where it sees the sky.
  const SurfacePoint* surface(int x, int y) const {
    const PrimaryHit& hit = at(x, y);
    return hit.is_sky() ? nullptr : &hit.point;
  }

 private:
  int width_, height_;
  HugePageVector<PrimaryHit> hits_;  // row by row from the top
};

}  // namespace skylit
