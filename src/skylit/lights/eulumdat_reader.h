// Reading EULUMDAT (.ldt) photometric files: the line-based format of A. Stockmar,
// "EULUMDAT — ein Leuchtendaten-Format für den europäischen Beleuchtungsplaner"
// (Light Consult Inc., Berlin, 1990). One value per line; intensities in cd/klm.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "skylit/lights/photometry.h"

namespace skylit {

struct EulumdatLampSet {
  int number_of_lamps = 1;  // negative in some files for absolute photometry
  std::string type;
  double total_lumens = 0;  // of the set (for absolute photometry: of the luminaire)
  std::string colour;       // colour appearance / temperature
  std::string colour_rendering;
  double watts = 0;  // including ballast
};

struct EulumdatPhotometry {
  std::string company;
  int type_indicator = 0;      // Ityp: 0 point source, 1 axial, 2 linear, 3 point with other symmetry
  int symmetry_indicator = 0;  // Isym 0–4
  int c_planes = 0;            // Mc, over the full 0–360°
  int gamma_angles = 0;        // Ng
  std::string luminaire_name, luminaire_number, report_number;
  double length_mm = 0, width_mm = 0, height_mm = 0;
  double downward_flux_fraction = 0;       // DFF, %
  double light_output_ratio = 0;           // LORL, %
  double conversion_factor = 1;            // CFLI
  double tilt_deg = 0;                     // tilt during measurement (information only)
  std::vector<EulumdatLampSet> lamp_sets;  // at least one
  // Absolute candela: cd/klm × (lumens of lamp set 1) / 1000 × CFLI (0 read as 1).
  IntensityDistribution distribution = IntensityDistribution::isotropic(0);
};

// Throws InputError "file:line: what was expected" for an unreadable or malformed file.
EulumdatPhotometry read_eulumdat(const std::filesystem::path& file);
// The same from text; `name` stands for the file in messages.
EulumdatPhotometry parse_eulumdat(const std::string& text, const std::string& name);

}  // namespace skylit
