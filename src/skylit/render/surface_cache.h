// A screen-space cache of smooth, costly quantities (the obstructed sky light on
// surfaces): computed exactly at the surface points seen through a sparse grid of pixel
// centres, then interpolated for the samples in between from the grid points that lie
// on the same surface. Where a pixel's surface has no such grid point around it (edges,
// small objects), a finer grid is computed there, and where that finds none either, the
// pixel's centre itself (so the antialiasing samples of a pixel share its centre's value
// instead of each computing its own: on a model of many small parts nearly every pixel is
// an edge); a sample that still finds none gets its own exact value from the caller. A
// cell serves only where its blend matched the value computed at its middle (the next
// level's point there); else the next level is computed. Sky light changes slowly along
// a surface, so this costs no visible accuracy, makes no noise, and is deterministic:
// every value computed is a function of its surface point alone, and every value found
// between computed ones (the per-pixel level's, between_neighbours) of theirs.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "skylit/core/huge_pages.h"
#include "skylit/media/fog_behind_surface.h"
#include "skylit/render/primary_hits.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

// The sky's light at a surface point: its irradiance (for the Lambertian part) and the
// radiance that the glossy part reflects toward the camera; and the sunlight that rough
// glossy facades reflect onto the point (render/reflected_sun.h), as smooth along a
// surface as the sky light, since their lobes spread it over tens of degrees.
struct CachedSkyLight {
  Irradiance diffuse_irradiance;
  Radiance specular_radiance;
  Irradiance rough_reflected_sun{};
  // The harmonic mean distance to the obstacles the point's sky-light integral met
  // (SkyLight::diffuse_irradiance): how far the value may stand for other points.
  double obstacle_distance_m = std::numeric_limits<double>::infinity();
  // In a multiply scattering fog: what the surface changes in the fog's light in front of
  // it, seen from the camera (media/fog_behind_surface.h); as smooth along a surface.
  FogHiddenBehind fog_hidden{};
  // What the point's pixel shows besides this sky light, as the sky illuminance (lx) on
  // the surface that would show as bright, or less (render/image_loop.cpp: the lamps'
  // glow in the fog in front of it; 0 without lamps in fog). The cache judges its
  // corners' spread against their sky light plus the least of this among them
  // (render/cache_corner_agreement.h).
  double other_lx = 0;
};

// Whether a cached point can stand in for `point`: the same material on the same plane
// (normals within ~18°, the point within 1 mm per metre of distance of the cached
// point's plane).
bool same_surface(const SurfacePoint& cached, const SurfacePoint& point);

class SurfaceCache {
 public:
  // The value at the surface point seen through pixel (x, y)'s centre.
  using Compute = std::function<CachedSkyLight(const SurfacePoint&, int x, int y)>;

  // Coarse and fine grid spacings in pixels; the last level is every pixel's centre.
  static constexpr int kCoarseSpacing = 16, kFineSpacing = 4, kPixelSpacing = 1;

  // From the surfaces seen at every pixel centre: computes the coarse grid, the fine
  // grid where the coarse one does not cover a pixel's surface, and the pixel's own
  // centre where neither does, the last with `compute_one_pixel` if given (a value that
  // stands for one pixel may be found more coarsely); in parallel. Of those pixels every
  // other one (by (x + y) % 2) is computed first, and each of the rest takes the mean
  // of its computed neighbours where they bracket it and agree (between_neighbours).
  SurfaceCache(const PrimaryHits& hits, const Compute& compute, const Compute& compute_one_pixel = {});

  // The value for a surface point seen at image position (x, y) in pixels: interpolated
  // from the coarse grid or else the fine one; else the nearest fine grid point within 8
  // pixels on the same surface; else interpolated from the pixel centres' values
  // (computed, or found between computed ones), or the nearest of them within 2 pixels on
  // the same surface; none if there is none.
  std::optional<CachedSkyLight> interpolate(double x, double y, const SurfacePoint& point) const;

  // Grid points computed, coarse, fine and per pixel (for the benchmark and tests).
  int coarse_points() const { return coarse_.computed(); }
  int fine_points() const { return fine_.computed(); }
  int pixel_points() const { return pixel_.computed() - pixels_between_; }
  // Pixels of the per-pixel level found between their neighbours (between_neighbours).
  int pixels_between() const { return pixels_between_; }
  // Of those, the points computed to check a coarser level's cells (check_cells).
  int cell_checks() const { return cell_checks_; }

 private:
  class Grid {
   public:
    // Computed points are stored densely, the grid holding their slots: the per-pixel
    // level has as many cells as the image but few computed points.
    struct Stored {
      SurfacePoint point;
      CachedSkyLight value;
      double diffuse_lx = 0;    // the value's diffuse illuminance, for corners_agree
      bool fog_hidden = false;  // whether value.fog_hidden holds anything (a multiply scattering fog)
      int x = 0, y = 0;         // the pixel
      // Holds `v`, with the illuminance and fog flag read from it.
      void set(const CachedSkyLight& v);
    };
    // A cell's corners on a point's surface and their bilinear weights (null where a
    // corner is not on it); `usable` if there are such corners and their sky light
    // agrees (render/cache_corner_agreement.h), `refused` if there are but they
    // disagree (the point then needs a finer level, not a neighbour's value).
    struct Corners {
      std::array<const Stored*, 4> stored{};
      std::array<double, 4> weight{};
      bool usable = false, refused = false;
      // The least of the corners' pixels' other light (CachedSkyLight::other_lx);
      // infinite without corners.
      double least_other_lx() const;
      // Whether the corners' sky light agrees within `spread`, against that other light
      // (corners_agree).
      bool agree(double spread) const;
    };

    Grid(int width, int height, int spacing);
    int grid_width() const { return grid_width_; }
    int grid_height() const { return grid_height_; }
    int spacing() const { return spacing_; }
    int pixel_x(int gx) const { return std::min(gx * spacing_, width_ - 1); }
    int pixel_y(int gy) const { return std::min(gy * spacing_, height_ - 1); }
    // The cell containing image position (x, y) and the position's place in it.
    void cell(double x, double y, int& gx, int& gy, double& tx, double& ty) const;
    Corners usable_corners(double x, double y, const SurfacePoint& point) const;
    // Whether interpolate would give a value, without blending one (the constructor's
    // test of every pixel).
    bool covers(double x, double y, const SurfacePoint& point) const { return usable_corners(x, y, point).usable; }
    // Bilinear from the usable corners, if there are any.
    std::optional<CachedSkyLight> interpolate(double x, double y, const SurfacePoint& point) const;
    // The bilinear blend of usable corners (`corners.usable`).
    CachedSkyLight blend(const Corners& corners) const;
    // The nearest grid point (on screen) within `cells` cells that lies on the same
    // surface (and, on the coarse and fine grids, within its obstacles' reach): for
    // slivers of a surface next to an edge, which no corner of their own cell sees; null
    // if none.
    const Stored* nearest(double x, double y, const SurfacePoint& point, int cells) const;
    // Asks for grid point (gx, gy), unless it is computed already (a cell's check).
    void want(int gx, int gy) {
      if (int32_t& slot = slots_[index(gx, gy)]; slot < 0) slot = kWanted;
    }
    // The stored point at grid point (gx, gy), null if none (not wanted, or it sees no surface).
    const Stored* at(int gx, int gy) const { return stored(gx, gy); }
    // Marks the cell whose top-left corner is (gx, gy) as failing its check: no point in
    // it is interpolated from this grid.
    void fail(int gx, int gy) { failed_[index(gx, gy)] = 1; }
    // Stores `value` for grid point (gx, gy), whose surface is `point`, found without an
    // integral of its own (a pixel between neighbours that agree).
    void keep(int gx, int gy, const SurfacePoint& point, const CachedSkyLight& value);
    // Room for `n` more points (keep's), so that the store is not copied as it grows.
    void reserve_more(size_t n) { stored_.reserve(stored_.size() + n); }
    // Computes the wanted points that see a surface, in parallel; those at the pixel of a
    // point of a `coarser` grid computed by the same `compute` take its value.
    void compute_wanted(const PrimaryHits& hits, const Compute& compute, std::span<const Grid* const> coarser = {});
    // Points stored, less those taken from a coarser grid.
    int computed() const { return static_cast<int>(stored_.size()) - copied_; }
    // The stored point at pixel (x, y), null if no grid point stands there or none is stored.
    const Stored* at_pixel(int x, int y) const {
      // Grid point g stands at pixel min(g·spacing, size − 1).
      const int gx = std::min(grid_width_ - 1, (x + spacing_ - 1) / spacing_);
      const int gy = std::min(grid_height_ - 1, (y + spacing_ - 1) / spacing_);
      return pixel_x(gx) == x && pixel_y(gy) == y ? stored(gx, gy) : nullptr;
    }

   private:
    static constexpr int32_t kNone = -1, kWanted = -2;
    size_t index(int gx, int gy) const { return static_cast<size_t>(gy) * grid_width_ + gx; }
    const Stored* stored(int gx, int gy) const {
      const int32_t slot = slots_[index(gx, gy)];
      return slot >= 0 ? &stored_[static_cast<size_t>(slot)] : nullptr;
    }
    int width_, height_, spacing_, grid_width_, grid_height_;
    int copied_ = 0;                 // stored points taken from a coarser grid
    HugePageVector<int32_t> slots_;  // per cell: as many as the image's pixels at the pixel level
    std::vector<uint8_t> failed_;    // per cell (by its top-left corner), on the grids only
    HugePageVector<Stored> stored_;  // up to tens of MB (a Stored is about 1.1 KB)
  };

  // Where the coarse grid or else the fine one has a value for a point (interpolate's
  // first levels): a grid's usable corners, or the nearest fine point for a sliver of a
  // surface; neither if none. The constructor asks only whether there is one (and
  // computes the pixel centres where there is not); from_grids takes the value.
  struct GridSource {
    const Grid* grid = nullptr;  // with `corners`
    Grid::Corners corners;
    const Grid::Stored* nearest = nullptr;
    bool found() const { return grid != nullptr || nearest != nullptr; }
  };
  GridSource source_in_grids(double x, double y, const SurfacePoint& point) const;
  // Checks the cells of `grid` at their middles, points of `finer` (where the grid would
  // interpolate; fine cells only where their corners differ by kUncheckedSpread or more):
  // computes the value there and fails the cell where its blend departs from it by more
  // than kCellCheck (render/cache_corner_agreement.h). The points stay in `finer`.
  // Returns how many were checked.
  static int check_cells(Grid& grid, Grid& finer, const PrimaryHits& hits, const Compute& compute);
  std::optional<CachedSkyLight> from_grids(double x, double y, const SurfacePoint& point) const;
  // The value at pixel (x, y), on `point`'s surface, from its four neighbours computed at
  // the per-pixel level: the mean of those on its surface within reach (within_reach)
  // where two of them lie on opposite sides of it and all of them agree within
  // kCloseSpread; none otherwise.
  std::optional<CachedSkyLight> between_neighbours(int x, int y, const SurfacePoint& point) const;

  Grid coarse_, fine_, pixel_;
  int cell_checks_ = 0;
  int pixels_between_ = 0;
};

}  // namespace skylit
