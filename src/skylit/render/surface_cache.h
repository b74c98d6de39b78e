// A screen-space cache of smooth, costly quantities (the obstructed sky light on
// surfaces): computed exactly at the surface points seen through a sparse grid of pixel
// centres, then interpolated for the samples in between from the grid points that lie
// on the same surface. Where a pixel's surface has no such grid point around it (edges,
// small objects), a finer grid is computed there; a sample that still finds none gets
// its own exact value from the caller. Sky light changes slowly along a surface, so this
// costs no visible accuracy, makes no noise, and is deterministic: every value is a
// function of its surface point alone.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "skylit/render/primary_hits.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

// The sky's light at a surface point: its irradiance (for the Lambertian part) and the
// radiance that the glossy part reflects toward the camera.
struct CachedSkyLight {
  Irradiance diffuse_irradiance;
  Radiance specular_radiance;
};

// Whether a cached point can stand in for `point`: the same material on the same plane
// (normals within ~18°, the point within 1 mm per metre of distance of the cached
// point's plane).
bool same_surface(const SurfacePoint& cached, const SurfacePoint& point);

class SurfaceCache {
 public:
  using Compute = std::function<CachedSkyLight(const SurfacePoint&)>;

  // Coarse and fine grid spacings in pixels.
  static constexpr int kCoarseSpacing = 16, kFineSpacing = 4;

  // From the surfaces seen at every pixel centre: computes the coarse grid, and the fine
  // grid where the coarse one does not cover a pixel's surface; in parallel.
  SurfaceCache(const PrimaryHits& hits, const Compute& compute);

  // The value for a surface point seen at image position (x, y) in pixels: interpolated
  // from the coarse grid or else the fine one; else the nearest fine grid point within 8
  // pixels on the same surface; none if there is none.
  std::optional<CachedSkyLight> interpolate(double x, double y, const SurfacePoint& point) const;

  // Grid points computed, coarse and fine (for the benchmark and tests).
  int coarse_points() const { return coarse_.computed(); }
  int fine_points() const { return fine_.computed(); }

 private:
  class Grid {
   public:
    Grid(int width, int height, int spacing);
    int grid_width() const { return grid_width_; }
    int grid_height() const { return grid_height_; }
    int pixel_x(int gx) const { return std::min(gx * spacing_, width_ - 1); }
    int pixel_y(int gy) const { return std::min(gy * spacing_, height_ - 1); }
    // The cell containing image position (x, y) and the position's place in it.
    void cell(double x, double y, int& gx, int& gy, double& tx, double& ty) const;
    std::optional<CachedSkyLight> interpolate(double x, double y, const SurfacePoint& point) const;
    // The value of the nearest grid point (on screen) within `cells` cells that lies on
    // the same surface: for slivers of a surface next to an edge, which no corner of
    // their own cell sees.
    std::optional<CachedSkyLight> nearest(double x, double y, const SurfacePoint& point, int cells) const;
    void set(int gx, int gy, const SurfacePoint& point, const CachedSkyLight& value);
    bool wanted(int gx, int gy) const { return entries_[index(gx, gy)].wanted; }
    void want(int gx, int gy) { entries_[index(gx, gy)].wanted = true; }
    int computed() const;

   private:
    struct Entry {
      bool wanted = false, valid = false;
      SurfacePoint point;
      CachedSkyLight value;
    };
    size_t index(int gx, int gy) const { return static_cast<size_t>(gy * grid_width_ + gx); }
    int width_, height_, spacing_, grid_width_, grid_height_;
    std::vector<Entry> entries_;
  };

  static void compute_wanted(Grid& grid, const PrimaryHits& hits, const Compute& compute);

  Grid coarse_, fine_;
};

}  // namespace skylit
