// The lamps' glow in fog over the whole image, found without evaluating it at every
// sample. The glow (render/scene_lamps.h) costs a shadow-volume query and an integral
// per lamp and view ray. It depends only on a view ray's direction and length, so it
// varies smoothly across the image except where the length jumps (an object in front
// of another) and at the edges of beams and shadows. So it is computed at pixel
// centres by a quadtree: the centres of 32-pixel blocks first; a block whose centres'
// distances its corners interpolate (within 2 %), and whose middle's glow (and on
// blocks of 4 pixels or more its sides' middles') its corners predict within
// kGlowTolerance, is filled by bilinear interpolation; any other block is split in
// four, down to single pixels, where every centre is evaluated exactly. A sample then
// takes the glow interpolated from the pixel centres around it whose view rays are as
// long as its own, so edges stay antialiased; with none, it evaluates the glow itself.
//
// Measured against the exact glow at every centre of the Fig. 9 frame: within 0.8 %
// for 99 % of pixels, 1.5 % at worst, from a tenth as many evaluations as pixels
// (tests/render/lamp_glow_image_test.cpp). Limits (docs/lights.md): a shadow or beam
// narrower than the checked points' spacing can slip between them; the glow is added
// after the air's extinction on the way, which over a street's length is under 1 %.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "skylit/geometry/ray_tracer.h"
#include "skylit/render/camera.h"
#include "skylit/render/primary_hits.h"
#include "skylit/render/scene_lamps.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

// What a view ray meets: an object (the tracer's mesh id) at a distance, or the sky.
struct ViewHit {
  static constexpr uint32_t kSky = std::numeric_limits<uint32_t>::max();
  uint32_t mesh = kSky;
  double distance = std::numeric_limits<double>::infinity();
};

// A block is interpolated when the glow at its middle differs from what its corners
// predict by at most this fraction (per channel).
inline constexpr double kGlowTolerance = 0.01;

class LampGlowImage {
 public:
  // Runs the quadtree over the image (in the calling TBB arena, in parallel), given what
  // the ray through each pixel's centre meets.
  LampGlowImage(const ImageCamera& camera, const PrimaryHits& centre_hits, const SceneLamps& lamps);

  // The glow's radiance (W m⁻² sr⁻¹ nm⁻¹) at a pixel's centre.
  const Spectrum& centre_glow(int x, int y) const { return centre(x, y).glow; }

  // The glow's radiance for a sample at image position (x, y) whose ray met `hit`.
  Spectrum at(double x, double y, const Ray& ray, const ViewHit& hit) const;

  // How many glow evaluations the quadtree made (for the benchmark and tests).
  uint64_t evaluations() const { return evaluations_; }

 private:
  struct Centre {
    Spectrum glow;
    ViewHit hit;
  };
  Spectrum evaluate(const Ray& ray, const ViewHit& hit) const;
  void fill_block(int bx, int by, uint64_t& evaluations);
  const Centre& centre(int x, int y) const { return centres_[static_cast<size_t>(y) * width_ + x]; }
  Centre& centre(int x, int y) { return centres_[static_cast<size_t>(y) * width_ + x]; }

  const ImageCamera& camera_;
  const SceneLamps& lamps_;
  int width_, height_;
  std::vector<Centre> centres_;
  uint64_t evaluations_ = 0;
};

}  // namespace skylit
