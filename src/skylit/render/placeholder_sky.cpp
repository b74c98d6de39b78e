#include "skylit/render/placeholder_sky.h"

#include "skylit/spectrum/cie.h"
#include "skylit/spectrum/illuminants.h"

namespace skylit {

Spectrum placeholder_sky_radiance() {
  const Spectrum d65 = Spectrum::from_table(cie_d65_table());
  return d65 * static_cast<float>(kPlaceholderSkyLuminance / luminance(d65));
}

}  // namespace skylit
