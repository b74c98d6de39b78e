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

// The inverse of followed_by: the far stretch that `whole` adds beyond `near`, both
// measured from the same origin (the air from the camera to two distances). Clamped to
// a transmittance in [0, 1] and a non-negative in-scatter, since tables interpolated at
// two distances need not nest exactly; where `near` lets nothing through, nothing of
// the far stretch would be seen anyway and it is returned empty.
MediumStretch remainder_after(const MediumStretch& near, const MediumStretch& whole);

// A ray whose radiance `whole` holds the air along all of it (the sky's radiance S),
// when a medium (a cloud) fills it from where the air stretch `air_before` ends: S = A +
// T·S_beyond, with A and T the air's in-scatter and transmittance up to the medium,
// and the medium replaces what lies beyond, seen through that air:
// T·(medium's light + t·S_beyond) + A = t·S + (1 − t)·A + T·medium's light.
inline Radiance seen_past(const Radiance& whole, const MediumStretch& air_before, const MediumStretch& medium) {
  return whole * medium.transmittance + air_before.in_scattered * (Transmittance(1.0f) - medium.transmittance) +
         medium.in_scattered * air_before.transmittance;
}

// Two media that fill the same stretch of a ray (the air inside a fog layer), each
// reported as if it were alone there. Each one's in-scattered light is then also dimmed
// by the other, by as much as it is on average where that light comes from. Exact when
// both media are uniform along the stretch (a level ray, Koschmieder's setting): with
// optical depths τa, τb over a length L and sources Sa, Sb per unit length, a alone
// gives Sa·L·g(τa) and both together Sa·L·g(τa + τb), g(τ) = (1 − e^−τ)/τ.
MediumStretch mixed(const MediumStretch& a, const MediumStretch& b);

}  // namespace skylit
