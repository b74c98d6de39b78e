#include "skylit/render/lamp_glow_image.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "skylit/spectrum/cie.h"

namespace skylit {

namespace {

// The coarsest blocks: 32 pixels on a side (33 × 33 centres).
constexpr int kBlock = 32;
constexpr int kSideCheck = 4;
// The glow depends only on a view ray's direction and length: two view hits count as
// alike when both are sky or their distances differ by at most this fraction, on one
// object or on two that meet (a wall and the road).
constexpr double kDistanceTolerance = 0.02;

bool alike(const ViewHit& a, double distance) {
  const bool sky = a.mesh == ViewHit::kSky, other_sky = !std::isfinite(distance);
  if (sky || other_sky) return sky && other_sky;
  return std::abs(a.distance - distance) <= kDistanceTolerance * distance;
}

// Whether the glow at a block's middle is what bilinear interpolation of its corners
// predicts, within kGlowTolerance in every channel.
bool interpolates(const std::array<Xyz, 4>& c, const Xyz& middle, double u, double v) {
  auto close = [&](double a, double b, double p, double q, double actual) {
    const double predicted = (1 - v) * ((1 - u) * a + u * b) + v * ((1 - u) * p + u * q);
    return std::abs(predicted - actual) <= kGlowTolerance * std::max(predicted, actual);
  };
  return close(c[0].x, c[1].x, c[2].x, c[3].x, middle.x) && close(c[0].y, c[1].y, c[2].y, c[3].y, middle.y) &&
         close(c[0].z, c[1].z, c[2].z, c[3].z, middle.z);
}

}  // namespace

LampGlowImage::LampGlowImage(const ImageCamera& camera, const PrimaryHits& centre_hits, const SceneLamps& lamps)
    : camera_(camera),
      lamps_(lamps),
      width_(centre_hits.width()),
      height_(centre_hits.height()),
      centres_(static_cast<size_t>(width_) * height_) {
  const int width = width_, height = height_;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const PrimaryHit& hit = centre_hits.at(x, y);
      centre(x, y).hit = {hit.mesh, hit.distance()};
    }
  const int blocks_x = (width + kBlock - 1) / kBlock, blocks_y = (height + kBlock - 1) / kBlock;
  std::atomic<uint64_t> evaluations{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, blocks_x * blocks_y), [&](const tbb::blocked_range<int>& range) {
    uint64_t count = 0;
    for (int b = range.begin(); b != range.end(); ++b)
      fill_block((b % blocks_x) * kBlock, (b / blocks_x) * kBlock, count);
    evaluations.fetch_add(count, std::memory_order_relaxed);
  });
  evaluations_ = evaluations.load();
}

Spectrum LampGlowImage::evaluate(const Ray& ray, const ViewHit& hit) const {
  return lamps_.in_scattered(ray, hit.distance).spectrum();
}

void LampGlowImage::fill_block(int bx, int by, uint64_t& evaluations) {
  // The block's centres run from (bx, by) to (x_end, y_end), corners included; it
  // writes those it owns (up to the next block's first row and column, exclusive).
  const int x_end = std::min(bx + kBlock, width_ - 1), y_end = std::min(by + kBlock, height_ - 1);
  const int x_own = bx + kBlock >= width_ ? width_ - 1 : bx + kBlock - 1;
  const int y_own = by + kBlock >= height_ ? height_ - 1 : by + kBlock - 1;
  // The glow at each evaluated centre, spectral, with its XYZ for the decisions (which
  // compare colours as the eye would, not bin by bin).
  struct Evaluated {
    Spectrum glow;
    Xyz xyz;
  };
  std::vector<std::optional<Evaluated>> memo(static_cast<size_t>(kBlock + 1) * (kBlock + 1));
  auto evaluated = [&](int x, int y) -> const Evaluated& {
    std::optional<Evaluated>& v = memo[static_cast<size_t>(y - by) * (kBlock + 1) + (x - bx)];
    if (!v) {
      const Spectrum glow = evaluate(camera_.ray_through(x + 0.5, y + 0.5), centre(x, y).hit);
      v = Evaluated{glow, xyz_from_spectrum(glow)};
      ++evaluations;
    }
    return *v;
  };
  auto value = [&](int x, int y) -> const Xyz& { return evaluated(x, y).xyz; };
  auto set = [&](int x, int y, const Spectrum& glow) {
    if (x > x_own || y > y_own) return;
    centre(x, y).glow = glow;
  };
  auto refine = [&](auto&& self, int x0, int y0, int x1, int y1) -> void {
    if (x1 - x0 <= 1 && y1 - y0 <= 1) {
      for (int y : {y0, y1})
        for (int x : {x0, x1}) set(x, y, evaluated(x, y).glow);
      return;
    }
    const std::array<Xyz, 4> c{value(x0, y0), value(x1, y0), value(x0, y1), value(x1, y1)};
    const ViewHit& h00 = centre(x0, y0).hit;
    const int mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
    // The corners must predict the middle, and on blocks of kSideCheck pixels or more
    // also the middles of the four sides (which a split would need anyway), so that a
    // feature between the middle and a corner is not missed.
    const double um = x1 > x0 ? double(mx - x0) / (x1 - x0) : 0, vm = y1 > y0 ? double(my - y0) / (y1 - y0) : 0;
    bool accept = interpolates(c, value(mx, my), um, vm);
    if (accept && std::max(x1 - x0, y1 - y0) >= kSideCheck)
      accept = interpolates(c, value(mx, y0), um, 0) && interpolates(c, value(mx, y1), um, 1) &&
               interpolates(c, value(x0, my), 0, vm) && interpolates(c, value(x1, my), 1, vm);
    // Every centre in the block at the distance the corners' distances interpolate to
    // (or all of them sky).
    const bool sky = h00.mesh == ViewHit::kSky;
    for (int y = y0; accept && y <= y1; ++y)
      for (int x = x0; accept && x <= x1; ++x) {
        const ViewHit& h = centre(x, y).hit;
        if (sky || h.mesh == ViewHit::kSky) {
          accept = sky && h.mesh == ViewHit::kSky;
          continue;
        }
        const double u = x1 > x0 ? double(x - x0) / (x1 - x0) : 0, v = y1 > y0 ? double(y - y0) / (y1 - y0) : 0;
        const double d = (1 - v) * ((1 - u) * h00.distance + u * centre(x1, y0).hit.distance) +
                         v * ((1 - u) * centre(x0, y1).hit.distance + u * centre(x1, y1).hit.distance);
        accept = std::isfinite(d) && std::abs(h.distance - d) <= kDistanceTolerance * h.distance;
      }
    if (accept) {
      const std::array<const Spectrum*, 4> g{&evaluated(x0, y0).glow, &evaluated(x1, y0).glow, &evaluated(x0, y1).glow,
                                             &evaluated(x1, y1).glow};
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const double u = x1 > x0 ? double(x - x0) / (x1 - x0) : 0, v = y1 > y0 ? double(y - y0) / (y1 - y0) : 0;
          // Bilinear, in single precision over the bins (vectorised: 40 bins cost about
          // what the 3 channels of XYZ did in double).
          const auto w00 = static_cast<float>((1 - v) * (1 - u)), w10 = static_cast<float>((1 - v) * u);
          const auto w01 = static_cast<float>(v * (1 - u)), w11 = static_cast<float>(v * u);
          set(x, y, *g[0] * w00 + *g[1] * w10 + *g[2] * w01 + *g[3] * w11);
        }
      return;
    }
    if (x1 - x0 >= 2 && y1 - y0 >= 2) {
      self(self, x0, y0, mx, my);
      self(self, mx, y0, x1, my);
      self(self, x0, my, mx, y1);
      self(self, mx, my, x1, y1);
    } else if (x1 - x0 >= 2) {
      self(self, x0, y0, mx, y1);
      self(self, mx, y0, x1, y1);
    } else {
      self(self, x0, y0, x1, my);
      self(self, x0, my, x1, y1);
    }
  };
  refine(refine, bx, by, x_end, y_end);
}

Spectrum LampGlowImage::at(double x, double y, const Ray& ray, const ViewHit& hit) const {
  // The four pixel centres around the sample, bilinear weights, only those whose view
  // ray is as long as the sample's.
  const double cx = std::clamp(x - 0.5, 0.0, width_ - 1.0), cy = std::clamp(y - 0.5, 0.0, height_ - 1.0);
  const int x0 = std::min(static_cast<int>(cx), width_ - 1), y0 = std::min(static_cast<int>(cy), height_ - 1);
  const int x1 = std::min(x0 + 1, width_ - 1), y1 = std::min(y0 + 1, height_ - 1);
  const double fx = cx - x0, fy = cy - y0;
  // A sample at a pixel's centre on the centre's own surface (every sample of the first
  // pass) takes the centre's value as it is.
  if (fx == 0 && fy == 0 && alike(centre(x0, y0).hit, hit.distance)) return centre(x0, y0).glow;
  double weight = 0;
  Spectrum sum(0.0f);
  auto take = [&](int px, int py, double w) {
    const Centre& c = centre(px, py);
    if (!alike(c.hit, hit.distance)) return;
    w += 1e-6;  // a sample exactly on a centre still counts its neighbours' side
    weight += w;
    sum += c.glow * static_cast<float>(w);
  };
  take(x0, y0, (1 - fx) * (1 - fy));
  take(x1, y0, fx * (1 - fy));
  take(x0, y1, (1 - fx) * fy);
  take(x1, y1, fx * fy);
  if (weight > 0) return sum * static_cast<float>(1.0 / weight);
  return evaluate(ray, hit);
}

}  // namespace skylit
