// The film: where the spectral light of each pixel becomes CIE XYZ, the only place in
// the renderer where light leaves its spectral bins, and where point sources seen by
// the camera (lamps) land in the pixel they fall in.
#pragma once

#include "skylit/spectrum/radiometry.h"
#include "skylit/spectrum/xyz_image.h"

namespace skylit {

class Film {
 public:
  Film(int width, int height) : image_(width, height) {}

  int width() const { return image_.width; }
  int height() const { return image_.height; }
  // A pixel's value: the mean radiance of its samples (W m⁻² sr⁻¹ nm⁻¹).
  void set(int x, int y, const Spectrum& mean_radiance);
  // A point source whose spectral irradiance at the camera is `irradiance`, spread over
  // the pixel it falls in, which covers `pixel_solid_angle_sr`.
  void add_point_source(int x, int y, const Irradiance& irradiance, double pixel_solid_angle_sr);

  const XyzImage& image() const { return image_; }
  // The pixels themselves, for a split render's exchange of tiles (ImageShare).
  XyzImage& pixels() { return image_; }
  XyzImage take() { return std::move(image_); }

 private:
  XyzImage image_;
};

}  // namespace skylit
