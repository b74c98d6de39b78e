// The tables of an atmosphere that do not depend on the sun: optical properties,
// transmittance, multiple scattering and the ground's sky irradiance, with the
// integrators that read them.
//
// They take a few hundred milliseconds to build and depend only on the air (not on the
// sun, the moon, a CIE sky or the night sky's emission), so a process keeps the last
// few it built and hands the same tables to every Atmosphere of the same air: a sun
// study, a sweep or a test suite builds them once.
#pragma once

#include <memory>

#include "skylit/atmosphere/atmosphere_settings.h"
#include "skylit/atmosphere/multiple_scattering_table.h"
#include "skylit/atmosphere/optical_properties.h"
#include "skylit/atmosphere/scattering_integrator.h"
#include "skylit/atmosphere/scattering_orders_table.h"
#include "skylit/atmosphere/transmittance_table.h"

namespace skylit {

struct AtmosphereTables {
  AtmosphereTables(const AtmosphereSettings& settings, const SpectralBands& bands);
  AtmosphereTables(const AtmosphereTables&) = delete;
  AtmosphereTables& operator=(const AtmosphereTables&) = delete;

  AtmosphereMedium medium;
  TransmittanceTable transmittance;
  std::unique_ptr<MultipleScatteringTable> hillaire;  // Hillaire's approximation, when chosen
  std::unique_ptr<ScatteringOrdersTable> orders;      // iterated scattering orders, when chosen
  std::unique_ptr<ScatteringIntegrator> sky_only;     // without the ground's sky irradiance
  std::unique_ptr<GroundIrradianceTable> ground_sky;
  std::unique_ptr<ScatteringIntegrator> integrator;
};

// The tables for this air: the ones built before for the same air if the process still
// keeps them, else new ones (kept, the oldest dropped). Safe from any thread.
std::shared_ptr<const AtmosphereTables> shared_atmosphere_tables(const AtmosphereSettings& settings,
                                                                 const SpectralBands& bands);

// Forgets the kept tables (for benchmarks that time a cold build).
void forget_shared_atmosphere_tables();

}  // namespace skylit
