// Unbiased tracking through the clouds, for the path-traced reference: where light
// travelling back along a ray last scattered in a cloud (delta tracking, Woodcock et al.
// 1965), and the clouds' transmittance along a shadow ray (ratio tracking, Novák et al.
// 2014, "Residual ratio tracking for estimating attenuation in participating media").
// Both test the cloud's exact solid (CloudGeometry::contains) at tentative collisions
// drawn with a majorant, the summed extinction of the clouds whose bounding volumes
// overlap there, so no step size or grid stands between them and the true optical
// depth. Clouds are grey (§6): one distance serves every bin.
#pragma once

#include "skylit/clouds/cloud_layer.h"
#include "skylit/core/counter_random.h"

namespace skylit {

struct CloudCollision {
  bool collided = false;
  double distance = 0;  // where (when it did)
  double albedo = 1;    // of the cloud it met
};

// Along o + t·d (d unit), t in [0, t_end] (t_end finite).
CloudCollision sample_cloud_collision(const CloudLayer& clouds, const Vec3& o, const Vec3& d, double t_end,
                                      CounterRandom& random);

// An unbiased estimate of e^{−τ} through the clouds along o + t·d, t in [0, t_end].
double estimate_cloud_transmittance(const CloudLayer& clouds, const Vec3& o, const Vec3& d, double t_end,
                                    CounterRandom& random);

}  // namespace skylit
