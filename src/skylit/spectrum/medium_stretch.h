// What a stretch of a medium along a ray (air, fog, a cloud) does to the light that
// crosses it toward the ray's origin: it lets a share through and adds its own
// in-scattered light, L_near = T · L_far + L_in. Every medium reports a stretch in this
// one form, and stretches one after another compose into one.
#pragma once

#include "skylit/spectrum/radiometry.h"

namespace skylit {

struct MediumStretch {
  Transmittance transmittance{1.0f};
  Radiance in_scattered{0.0f};  // absolute, toward the ray's origin

  // The light arriving at the near end when `far_end` leaves the far end toward it.
  Radiance seen_through(const Radiance& far_end) const { return far_end * transmittance + in_scattered; }
};

// Two stretches one after the other along a ray, `near` closer to the ray's origin: the
// far one's light is seen through the near one.
inline MediumStretch followed_by(const MediumStretch& near, const MediumStretch& far) {
  return {near.transmittance * far.transmittance, near.seen_through(far.in_scattered)};
}

}  // namespace skylit
