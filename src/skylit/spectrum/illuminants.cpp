#include "skylit/spectrum/illuminants.h"

namespace skylit {

const Tabulated& solar_extraterrestrial_table() {
  static const Tabulated table = embedded_table("solar_extraterrestrial.csv", 1);
  return table;
}

Spectrum solar_extraterrestrial_irradiance() { return Spectrum::from_table(solar_extraterrestrial_table()); }

const Tabulated& cie_d65_table() {
  static const Tabulated table = embedded_table("cie_d65.csv", 1);
  return table;
}

}  // namespace skylit
