#include "skylit/render/film.h"

#include "skylit/spectrum/cie.h"

namespace skylit {

void Film::set(int x, int y, const Spectrum& mean_radiance) { image_.set(x, y, xyz_from_spectrum(mean_radiance)); }

void Film::add_point_source(int x, int y, const Irradiance& irradiance, double pixel_solid_angle_sr) {
  const Xyz added = xyz_from_spectrum(irradiance.spectrum() * static_cast<float>(1.0 / pixel_solid_angle_sr));
  const Xyz old = image_.at(x, y);
  image_.set(x, y, {old.x + added.x, old.y + added.y, old.z + added.z});
}

}  // namespace skylit
