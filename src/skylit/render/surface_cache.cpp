#include "skylit/render/surface_cache.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <span>

#include <tbb/parallel_for.h>

#include "skylit/render/cache_corner_agreement.h"
#include "skylit/spectrum/cie.h"

namespace skylit {

bool same_surface(const SurfacePoint& cached, const SurfacePoint& point) {
  if (cached.material != point.material || dot(cached.normal, point.normal) < 0.95) return false;
  // On the cached point's plane within 1 mm per metre of distance. Points of one plane
  // close together on the screen share their sky light closely enough however far apart
  // they are in depth (a street's far end near the horizon).
  const double plane_distance = std::abs(dot(cached.normal, point.position - cached.position));
  return plane_distance < 1e-3 * point.distance + 1e-3;
}

SurfaceCache::Grid::Grid(int width, int height, int spacing)
    : width_(width),
      height_(height),
      spacing_(spacing),
      grid_width_((width - 1 + spacing - 1) / spacing + 1),
      grid_height_((height - 1 + spacing - 1) / spacing + 1),
      slots_(static_cast<size_t>(grid_width_) * grid_height_, kNone),
      failed_(spacing > 1 ? static_cast<size_t>(grid_width_) * grid_height_ : 0, 0) {}

void SurfaceCache::Grid::cell(double x, double y, int& gx, int& gy, double& tx, double& ty) const {
  // Grid point g stands at the centre of pixel min(g·spacing, size − 1).
  auto locate = [this](double at, int grid, auto pixel_of, int& g, double& t) {
    g = std::clamp(static_cast<int>(std::floor((at - 0.5) / spacing_)), 0, std::max(0, grid - 2));
    const double p0 = pixel_of(g) + 0.5, p1 = pixel_of(std::min(g + 1, grid - 1)) + 0.5;
    t = p1 > p0 ? std::clamp((at - p0) / (p1 - p0), 0.0, 1.0) : 0.0;
  };
  locate(
      x, grid_width_, [this](int g) { return pixel_x(g); }, gx, tx);
  locate(
      y, grid_height_, [this](int g) { return pixel_y(g); }, gy, ty);
}

void SurfaceCache::Grid::Stored::set(const CachedSkyLight& v) {
  value = v;
  diffuse_lx = illuminance(v.diffuse_irradiance);
  fog_hidden = !v.fog_hidden.gain.is_black();
}

double SurfaceCache::Grid::Corners::least_other_lx() const {
  double least = std::numeric_limits<double>::infinity();
  for (const Stored* e : stored)
    if (e) least = std::min(least, e->value.other_lx);
  return least;
}

bool SurfaceCache::Grid::Corners::agree(double spread) const {
  std::array<double, 4> lx{};
  size_t count = 0;
  for (const Stored* e : stored)
    if (e) lx[count++] = e->diffuse_lx;
  return corners_agree(std::span<const double>(lx.data(), count), spread, least_other_lx());
}

SurfaceCache::Grid::Corners SurfaceCache::Grid::usable_corners(double x, double y, const SurfacePoint& point) const {
  int gx, gy;
  double tx, ty;
  cell(x, y, gx, gy, tx, ty);
  Corners out;
  size_t count = 0;
  bool all_within_reach = true, all_within_obstacle_reach = true;
  double depth_span = 0;
  for (int dy = 0; dy <= 1; ++dy)
    for (int dx = 0; dx <= 1; ++dx) {
      const Stored* e = stored(std::min(gx + dx, grid_width_ - 1), std::min(gy + dy, grid_height_ - 1));
      if (!e || !same_surface(e->point, point)) continue;
      out.stored[static_cast<size_t>(2 * dy + dx)] = e;
      // Bilinear weights, kept off zero so that a lone compatible corner still counts.
      out.weight[static_cast<size_t>(2 * dy + dx)] =
          std::max(dx ? tx : 1.0 - tx, 1e-3) * std::max(dy ? ty : 1.0 - ty, 1e-3);
      ++count;
      all_within_reach = all_within_reach && within_reach(e->point, point);
      all_within_obstacle_reach =
          all_within_obstacle_reach && within_obstacle_reach(e->point, e->value.obstacle_distance_m, point);
      depth_span = std::max(depth_span, std::abs(e->point.distance / point.distance - 1));
    }
  // Corners whose sky light disagrees lie across a change the cell cannot follow. Fewer
  // than four corners on the surface cannot show how it changes across the cell, so
  // they must also lie near the point. A lone corner shows nothing of it and stands in
  // for no point on the grids: its obstacles' reach (Ward's validity radius, which it
  // had to be within until 2026-12-06) is its own, and a point in its cell closer to a
  // small obstacle than it (a window's glass beside the frame, a wall under the eaves,
  // a recessed door's edge) sees less sky (measured in cache_corner_agreement.h).
  // In a cell that spans much depth, near obstacles, corners farther than their reach
  // must agree closely (cache_corner_agreement.h). The per-pixel level's corners are a
  // pixel apart: nothing finer to go to.
  if (!failed_.empty() && failed_[index(gx, gy)] && count > 0) {
    out.refused = true;
    return out;
  }
  const bool near_obstacles =
      spacing_ > 1 && depth_span > kDepthSpan && !all_within_obstacle_reach && !out.agree(kCloseSpread);
  const bool lone_on_a_grid = spacing_ > 1 && count == 1;
  const bool partial_usable = all_within_reach && !lone_on_a_grid;
  out.refused = count > 0 && (near_obstacles || !(count == 4 || partial_usable) || !out.agree(kCornerSpread));
  out.usable = count > 0 && !out.refused;
  return out;
}

std::optional<CachedSkyLight> SurfaceCache::Grid::interpolate(double x, double y, const SurfacePoint& point) const {
  const Corners corners = usable_corners(x, y, point);
  if (!corners.usable) return std::nullopt;
  return blend(corners);
}

CachedSkyLight SurfaceCache::Grid::blend(const Corners& corners) const {
  CachedSkyLight sum;
  double total = 0;
  for (size_t i = 0; i < 4; ++i) {
    const Stored* e = corners.stored[i];
    if (!e) continue;
    const double w = corners.weight[i];
    sum.diffuse_irradiance += e->value.diffuse_irradiance * static_cast<float>(w);
    sum.specular_radiance += e->value.specular_radiance * static_cast<float>(w);
    sum.rough_reflected_sun += e->value.rough_reflected_sun * static_cast<float>(w);
    if (e->fog_hidden) {  // only in a multiply scattering fog
      sum.fog_hidden.gain += e->value.fog_hidden.gain * static_cast<float>(w);
      sum.fog_hidden.field += e->value.fog_hidden.field * static_cast<float>(w);
      sum.fog_hidden.field_in_shadow += e->value.fog_hidden.field_in_shadow * static_cast<float>(w);
    }
    total += w;
  }
  const float scale = static_cast<float>(1.0 / total);
  CachedSkyLight out{sum.diffuse_irradiance * scale, sum.specular_radiance * scale, sum.rough_reflected_sun * scale};
  out.fog_hidden = {sum.fog_hidden.gain * scale, sum.fog_hidden.field * scale, sum.fog_hidden.field_in_shadow * scale};
  return out;
}

const SurfaceCache::Grid::Stored* SurfaceCache::Grid::nearest(double x, double y, const SurfacePoint& point,
                                                              int cells) const {
  int gx, gy;
  double tx, ty;
  cell(x, y, gx, gy, tx, ty);
  const Stored* best = nullptr;
  double best_distance = 0;
  for (int cy = std::max(0, gy - cells + 1); cy <= std::min(grid_height_ - 1, gy + cells); ++cy) {
    for (int cx = std::max(0, gx - cells + 1); cx <= std::min(grid_width_ - 1, gx + cells); ++cx) {
      const Stored* e = stored(cx, cy);
      if (!e || !same_surface(e->point, point) || !within_reach(e->point, point)) continue;
      // A single point shows nothing of how the light changes away from it: on the
      // grids it stands in only within its obstacles' reach (a roof's point beside a
      // standing seam, 7 cm from it, gave its sixth of the roof's sky light to the roof's
      // edge 0.6 m away). Unlike a lone corner, which stands in for nothing on the grids,
      // it is a sliver's only source short of an integral of its own. The per-pixel
      // level's points are a pixel or two apart: nothing finer to go to.
      if (spacing_ > 1 && !within_obstacle_reach(e->point, e->value.obstacle_distance_m, point)) continue;
      const double d = std::hypot(pixel_x(cx) + 0.5 - x, pixel_y(cy) + 0.5 - y);
      if (!best || d < best_distance) {  // ties keep the first in scan order: deterministic
        best = e;
        best_distance = d;
      }
    }
  }
  return best;
}

void SurfaceCache::Grid::keep(int gx, int gy, const SurfacePoint& point, const CachedSkyLight& value) {
  assert(slots_[index(gx, gy)] < 0);  // a computed value is never replaced
  slots_[index(gx, gy)] = static_cast<int32_t>(stored_.size());
  stored_.push_back({point, {}, 0, false, pixel_x(gx), pixel_y(gy)});
  stored_.back().set(value);
}

void SurfaceCache::Grid::compute_wanted(const PrimaryHits& hits, const Compute& compute,
                                        std::span<const Grid* const> coarser) {
  // Slots in scan order, then the values in parallel: deterministic. Room for every
  // wanted point first: growing the store copied it, into new pages each time.
  const size_t first_new = stored_.size();  // points computed before (a cell's checks) keep their values
  stored_.reserve(first_new + static_cast<size_t>(std::count(slots_.begin(), slots_.end(), kWanted)));
  for (int gy = 0; gy < grid_height_; ++gy)
    for (int gx = 0; gx < grid_width_; ++gx) {
      int32_t& slot = slots_[index(gx, gy)];
      if (slot != kWanted) continue;
      slot = kNone;
      if (const SurfacePoint* p = hits.surface(pixel_x(gx), pixel_y(gy))) {
        slot = static_cast<int32_t>(stored_.size());
        stored_.push_back({*p, {}, 0, false, pixel_x(gx), pixel_y(gy)});
      }
    }
  // A point at the pixel of a coarser grid's point is that point, and the same integral
  // (the caller's `coarser` are computed by `compute` too) gives it the same value.
  std::vector<const Stored*> same(stored_.size() - first_new, nullptr);
  for (size_t i = first_new; i < stored_.size(); ++i)
    for (const Grid* grid : coarser)
      if ((same[i - first_new] = grid->at_pixel(stored_[i].x, stored_[i].y))) {
        ++copied_;
        break;
      }
  tbb::parallel_for(first_new, stored_.size(), [&](size_t i) {
    const Stored* from = same[i - first_new];
    stored_[i].set(from ? from->value : compute(stored_[i].point, stored_[i].x, stored_[i].y));
  });
}

namespace {

// The pixels whose centre's surface `covered` has no value for, row by row (checked in
// parallel).
template <typename Covered>
std::vector<std::vector<int>> uncovered_pixels(const PrimaryHits& hits, const Covered& covered) {
  std::vector<std::vector<int>> rows(static_cast<size_t>(hits.height()));
  tbb::parallel_for(0, hits.height(), [&](int y) {
    for (int x = 0; x < hits.width(); ++x)
      if (const SurfacePoint* p = hits.surface(x, y); p && !covered(x + 0.5, y + 0.5, *p))
        rows[static_cast<size_t>(y)].push_back(x);
  });
  return rows;
}

}  // namespace

SurfaceCache::SurfaceCache(const PrimaryHits& hits, const Compute& compute, const Compute& compute_one_pixel)
    : coarse_(hits.width(), hits.height(), kCoarseSpacing),
      fine_(hits.width(), hits.height(), kFineSpacing),
      pixel_(hits.width(), hits.height(), kPixelSpacing) {
  for (int gy = 0; gy < coarse_.grid_height(); ++gy)
    for (int gx = 0; gx < coarse_.grid_width(); ++gx) coarse_.want(gx, gy);
  coarse_.compute_wanted(hits, compute);
  // Each coarse cell checked at its middle (a fine point), then the fine grid around
  // every pixel whose surface the coarse grid does not cover.
  cell_checks_ = check_cells(coarse_, fine_, hits, compute);
  const auto not_by_coarse =
      uncovered_pixels(hits, [&](double x, double y, const SurfacePoint& p) { return coarse_.covers(x, y, p); });
  for (size_t y = 0; y < not_by_coarse.size(); ++y)
    for (const int x : not_by_coarse[y]) {
      int gx, gy;
      double tx, ty;
      fine_.cell(x + 0.5, static_cast<double>(y) + 0.5, gx, gy, tx, ty);
      for (int dy = 0; dy <= 1; ++dy)
        for (int dx = 0; dx <= 1; ++dx)
          fine_.want(std::min(gx + dx, fine_.grid_width() - 1), std::min(gy + dy, fine_.grid_height() - 1));
    }
  fine_.compute_wanted(hits, compute, std::array<const Grid*, 1>{&coarse_});
  // The fine cells checked at their middle pixels, with the full integral: a coarser
  // value there would fail cells by its own quadrature's error.
  cell_checks_ += check_cells(fine_, pixel_, hits, compute);
  // The centres of the pixels that neither grid covers: every other one (a
  // checkerboard's black squares), then each of the others from the neighbours that
  // bracket it where they agree closely, else its own.
  const Compute& one_pixel = compute_one_pixel ? compute_one_pixel : compute;
  // The grids' values at their pixels only where they come from the same integral: a
  // value of more directions amid its neighbours' fewer stands out by the quadratures'
  // difference (0.6 % on the vanishing fog's ground, in a pattern of every fourth pixel
  // where the fine grid happened to be wanted).
  const std::vector<const Grid*> same_integral =
      compute_one_pixel ? std::vector<const Grid*>{} : std::vector<const Grid*>{&fine_, &coarse_};
  const auto not_by_grids = uncovered_pixels(
      hits, [&](double x, double y, const SurfacePoint& p) { return source_in_grids(x, y, p).found(); });
  for (size_t y = 0; y < not_by_grids.size(); ++y)
    for (const int x : not_by_grids[y])
      if ((x + y) % 2 == 0) pixel_.want(x, static_cast<int>(y));
  pixel_.compute_wanted(hits, one_pixel, same_integral);
  // A white square's neighbours are black, so a value kept for one never stands in for
  // another, and it is kept at once (room for all of them first: the store moves as it
  // grows).
  size_t white = 0;
  for (size_t y = 0; y < not_by_grids.size(); ++y)
    for (const int x : not_by_grids[y]) white += (x + y) % 2;
  pixel_.reserve_more(white);
  for (size_t y = 0; y < not_by_grids.size(); ++y)
    for (const int x : not_by_grids[y]) {
      const int yi = static_cast<int>(y);
      // (A white square may hold a fine cell's check already: kept as computed.)
      if ((x + y) % 2 == 0 || pixel_.at(x, yi)) continue;
      const SurfacePoint& point = *hits.surface(x, yi);
      if (const std::optional<CachedSkyLight> value = between_neighbours(x, yi, point)) {
        pixel_.keep(x, yi, point, *value);
        ++pixels_between_;
      } else {
        pixel_.want(x, yi);
      }
    }
  pixel_.compute_wanted(hits, one_pixel, same_integral);
}

std::optional<CachedSkyLight> SurfaceCache::between_neighbours(int x, int y, const SurfacePoint& point) const {
  Grid::Corners sides;
  const std::array<std::array<int, 2>, 4> offsets{{{-1, 0}, {1, 0}, {0, -1}, {0, 1}}};
  for (size_t i = 0; i < 4; ++i) {
    const int nx = x + offsets[i][0], ny = y + offsets[i][1];
    if (nx < 0 || ny < 0 || nx >= pixel_.grid_width() || ny >= pixel_.grid_height()) continue;
    const Grid::Stored* e = pixel_.at(nx, ny);
    // Only a neighbour within reach (kCornerReach of the distance) stands for the point
    // and must agree: one beyond it lies much deeper or nearer (a row above or below, seen
    // at a grazing angle), where the light may differ by its depth alone, which the
    // bracketing pair at the point's own depth shows. (Holding those to the 1 % as well
    // found 3,011 of Fig. 7's pixels between neighbours instead of 5,524, and moved no
    // 99th percentile.)
    if (!e || !same_surface(e->point, point) || !within_reach(e->point, point)) continue;
    sides.stored[i] = e;
    sides.weight[i] = 1;
  }
  const bool bracketed = (sides.stored[0] && sides.stored[1]) || (sides.stored[2] && sides.stored[3]);
  if (!bracketed || !sides.agree(kCloseSpread)) return std::nullopt;
  CachedSkyLight value = pixel_.blend(sides);
  value.other_lx = sides.least_other_lx();
  value.obstacle_distance_m = std::numeric_limits<double>::infinity();
  for (const Grid::Stored* e : sides.stored)
    if (e) value.obstacle_distance_m = std::min(value.obstacle_distance_m, e->value.obstacle_distance_m);
  return value;
}

int SurfaceCache::check_cells(Grid& grid, Grid& finer, const PrimaryHits& hits, const Compute& compute) {
  struct Check {
    int gx, gy, fx, fy;
    Grid::Corners corners;  // the cell's, for its middle (`grid` is not changed meanwhile)
  };
  std::vector<Check> checks;
  for (int gy = 0; gy + 1 < grid.grid_height(); ++gy)
    for (int gx = 0; gx + 1 < grid.grid_width(); ++gx) {
      // The point of the finer grid nearest the cell's middle (the spacings divide); a
      // cell too thin to hold one inside it (the last row or column of an image whose
      // size the spacing does not divide) is not checked: its corners are all it has.
      const auto middle = [&](int a, int b) { return ((a + b) / 2 + finer.spacing() / 2) / finer.spacing(); };
      const int fx = middle(grid.pixel_x(gx), grid.pixel_x(gx + 1));
      const int fy = middle(grid.pixel_y(gy), grid.pixel_y(gy + 1));
      const int px = finer.pixel_x(fx), py = finer.pixel_y(fy);
      if (px <= grid.pixel_x(gx) || px >= grid.pixel_x(gx + 1) || py <= grid.pixel_y(gy) || py >= grid.pixel_y(gy + 1))
        continue;
      const SurfacePoint* p = hits.surface(px, py);
      if (!p) continue;
      const Grid::Corners corners = grid.usable_corners(px + 0.5, py + 0.5, *p);
      if (!corners.usable) continue;  // the finer level is computed there anyway
      bool smooth = true;             // every corner within kSmoothReach of its obstacles' distance
      for (const Grid::Stored* s : corners.stored)
        smooth = smooth && (!s || within_obstacle_reach(s->point, s->value.obstacle_distance_m, *p, kSmoothReach));
      if (smooth || (grid.spacing() <= kUncheckedCellPixels && corners.agree(kUncheckedSpread))) continue;
      finer.want(fx, fy);
      checks.push_back({gx, gy, fx, fy, corners});
    }
  finer.compute_wanted(hits, compute);
  for (const Check& c : checks) {
    const Grid::Stored* exact = finer.at(c.fx, c.fy);
    if (!exact) continue;
    if (!corners_agree(std::array{illuminance(grid.blend(c.corners).diffuse_irradiance), exact->diffuse_lx}, kCellCheck,
                       exact->value.other_lx))
      grid.fail(c.gx, c.gy);
  }
  return static_cast<int>(checks.size());
}

SurfaceCache::GridSource SurfaceCache::source_in_grids(double x, double y, const SurfacePoint& point) const {
  if (Grid::Corners coarse = coarse_.usable_corners(x, y, point); coarse.usable) return {&coarse_, coarse, nullptr};
  const Grid::Corners fine = fine_.usable_corners(x, y, point);
  if (fine.usable) return {&fine_, fine, nullptr};
  // A sliver of a surface takes a neighbour's value; a point whose corners disagree
  // lies where the sky light changes fast, and gets its pixel's own.
  if (fine.refused) return {};
  return {nullptr, {}, fine_.nearest(x, y, point, 2)};
}

std::optional<CachedSkyLight> SurfaceCache::from_grids(double x, double y, const SurfacePoint& point) const {
  const GridSource source = source_in_grids(x, y, point);
  if (source.grid) return source.grid->blend(source.corners);
  if (source.nearest) return source.nearest->value;
  return std::nullopt;
}

std::optional<CachedSkyLight> SurfaceCache::interpolate(double x, double y, const SurfacePoint& point) const {
  if (auto value = from_grids(x, y, point)) return value;
  if (auto value = pixel_.interpolate(x, y, point)) return value;
  if (const Grid::Stored* near = pixel_.nearest(x, y, point, 2)) return near->value;
  return std::nullopt;
}

}  // namespace skylit
