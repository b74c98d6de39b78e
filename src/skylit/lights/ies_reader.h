// Reading IES photometric files: ANSI/IES LM-63 in its 2019, 2002 and 1995 forms
// ("IES:LM-63-2019", "IESNA:LM-63-2002", "IESNA:LM-63-1995") and the older 1991
// ("IESNA91") and 1986 (no identifier line) forms, which share the same numeric block.
// Type C only. Sources: ANSI/IES LM-63-19 and IES LM-63-02, "Standard File Format for
// the Electronic Transfer of Photometric Data and Related Information".
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "skylit/lights/photometry.h"

namespace skylit {

struct IesPhotometry {
  std::string format;  // "LM-63-2019", "LM-63-2002", "LM-63-1995", "LM-63-1991" or "LM-63-1986"
  // Keyword lines in file order, without brackets ("TEST", "MANUFAC", ...); [MORE]
  // lines are appended to the preceding keyword's value after a newline.
  std::vector<std::pair<std::string, std::string>> keywords;
  TiltTable tilt;  // empty for TILT=NONE
  int number_of_lamps = 1;
  double lumens_per_lamp = -1;  // -1: absolute photometry
  double candela_multiplier = 1;
  int photometric_type = 1;                        // always 1 (Type C) once read
  double width_m = 0, length_m = 0, height_m = 0;  // luminous opening, converted from feet if units = 1
  double ballast_factor = 1;
  double ballast_lamp_factor = 1;   // 1995 and older; the 2002 "future use" field is ignored
  double file_generation_type = 0;  // 2019 only (1.00000–1.11100, LM-63-19 Table 2): a code, not a factor
  double input_watts = 0;
  // Absolute candela: file values × candela multiplier × ballast factor (× the
  // ballast-lamp photometric factor before 2002), as the file says.
  IntensityDistribution distribution = IntensityDistribution::isotropic(0);

  // The file's rated lamp lumens (lamps × lumens per lamp), or -1 for absolute photometry.
  double rated_lumens() const { return lumens_per_lamp < 0 ? -1 : number_of_lamps * lumens_per_lamp; }
};

// Throws InputError "file:line: what was expected" for an unreadable or malformed
// file, an unsupported photometric type (B, A) or TILT=<file> (not supported: put
// the tilt data inline with TILT=INCLUDE).
IesPhotometry read_ies(const std::filesystem::path& file);
// The same from text; `name` stands for the file in messages.
IesPhotometry parse_ies(const std::string& text, const std::string& name);

}  // namespace skylit
