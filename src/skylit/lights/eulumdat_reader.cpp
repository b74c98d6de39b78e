// EULUMDAT reader (format description by A. Stockmar, 1990): fixed header lines
// 1–26, six lines per lamp set, ten direct ratios, the Mc C angles, the Ng γ angles,
// then the intensities of planes Mc1…Mc2 as the symmetry Isym selects them. Numbers
// may use a decimal comma (German-language writers do). Errors name file:line.
#include "skylit/lights/eulumdat_reader.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"
#include "skylit/lights/number_text.h"

namespace skylit {
namespace {

using lights_detail::parse_number;

constexpr int kMaxAngles = 10000;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

class Lines {
 public:
  Lines(const std::string& text, const std::string& name) : name_(name) {
    std::string line;
    std::istringstream stream(text);
    while (std::getline(stream, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines_.push_back(line);
    }
  }

  // The next line's text (trimmed); `what` names it for a truncated file.
  std::string text(const std::string& what) {
    if (next_ >= lines_.size())
      fail_at(std::max<int>(static_cast<int>(lines_.size()), 1), "expected " + what + ", found the end of the file");
    return trim(lines_[next_++]);
  }

  double number(const std::string& what) {
    std::string t = text(what);
    for (char& ch : t)
      if (ch == ',') ch = '.';
    const auto v = parse_number(t);
    if (!v) fail("expected " + what + ", found " + quote_excerpt(t));
    return *v;
  }

  int integer(const std::string& what, int lo, int hi) {
    const double v = number(what);
    if (v != std::floor(v) || v < lo || v > hi)
      fail("expected " + what + " (a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ")");
    return static_cast<int>(v);
  }

  // The line just read (1-based).
  int line() const { return static_cast<int>(next_); }
  [[noreturn]] void fail(const std::string& message) const { fail_at(std::max(line(), 1), message); }
  [[noreturn]] void fail_at(int line, const std::string& message) const {
    throw InputError(name_ + ":" + std::to_string(line) + ": " + message);
  }

 private:
  std::string name_;
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
};

}  // namespace

EulumdatPhotometry parse_eulumdat(const std::string& text, const std::string& name) {
  Lines in(text, name);
  EulumdatPhotometry out;
  out.company = in.text("the company identification (line 1)");
  out.type_indicator = in.integer("the type indicator Ityp (line 2)", 0, 3);
  out.symmetry_indicator = in.integer("the symmetry indicator Isym (line 3)", 0, 4);
  const int isym = out.symmetry_indicator;
  out.c_planes = in.integer("the number of C planes Mc (line 4)", 1, kMaxAngles);
  const int mc = out.c_planes;
  const int mc_line = in.line();
  in.number("the distance between C planes Dc (line 5)");
  out.gamma_angles = in.integer("the number of intensities per C plane Ng (line 6)", 2, kMaxAngles);
  const int ng = out.gamma_angles;
  // Refuse absurd sizes before allocating (a corrupted count must not ask for gigabytes).
  if (static_cast<long>(mc) * ng > 4000000)
    in.fail("Mc x Ng = " + std::to_string(mc) + " x " + std::to_string(ng) + " is too large");
  in.number("the distance between intensities Dg (line 7)");
  out.report_number = in.text("the measurement report number (line 8)");
  out.luminaire_name = in.text("the luminaire name (line 9)");
  out.luminaire_number = in.text("the luminaire number (line 10)");
  in.text("the file name (line 11)");
  in.text("the date and user (line 12)");
  out.length_mm = in.number("the luminaire length or diameter in mm (line 13)");
  out.width_mm = in.number("the luminaire width in mm (line 14)");
  out.height_mm = in.number("the luminaire height in mm (line 15)");
  in.number("the luminous area length or diameter in mm (line 16)");
  in.number("the luminous area width in mm (line 17)");
  in.number("the luminous area height at C0 in mm (line 18)");
  in.number("the luminous area height at C90 in mm (line 19)");
  in.number("the luminous area height at C180 in mm (line 20)");
  in.number("the luminous area height at C270 in mm (line 21)");
  out.downward_flux_fraction = in.number("the downward flux fraction in % (line 22)");
  out.light_output_ratio = in.number("the light output ratio in % (line 23)");
  out.conversion_factor = in.number("the intensity conversion factor (line 24)");
  if (out.conversion_factor < 0) in.fail("the intensity conversion factor must not be negative");
  if (out.conversion_factor == 0) out.conversion_factor = 1;  // some writers leave it 0 meaning "none"
  out.tilt_deg = in.number("the tilt during measurement (line 25)");
  const int n_sets = in.integer("the number of lamp sets (line 26)", 1, 20);
  for (int s = 0; s < n_sets; ++s) {
    const std::string set = " of lamp set " + std::to_string(s + 1);
    EulumdatLampSet lamp;
    lamp.number_of_lamps = in.integer("the number of lamps" + set, -1000000, 1000000);
    lamp.type = in.text("the lamp type" + set);
    lamp.total_lumens = in.number("the total lumens" + set);
    if (lamp.total_lumens <= 0) in.fail("the total lumens" + set + " must be positive");
    lamp.colour = in.text("the colour appearance" + set);
    lamp.colour_rendering = in.text("the colour rendering" + set);
    lamp.watts = in.number("the wattage" + set);
    out.lamp_sets.push_back(lamp);
  }
  for (int k = 0; k < 10; ++k) in.number("direct ratio " + std::to_string(k + 1) + " of 10");

  // The symmetry fixes which planes carry data (Mc1…Mc2, 1-based, wrapping past Mc).
  if ((isym == 2 && mc % 2 != 0) || ((isym == 3 || isym == 4) && mc % 4 != 0))
    in.fail_at(mc_line, "Mc = " + std::to_string(mc) + " does not suit symmetry Isym " + std::to_string(isym) +
                            " (must be divisible by " + (isym == 2 ? "2)" : "4)"));
  int mc1 = 1, mc2 = mc;
  if (isym == 1)
    mc2 = 1;
  else if (isym == 2)
    mc2 = mc / 2 + 1;
  else if (isym == 3)
    mc1 = 3 * mc / 4 + 1, mc2 = mc1 + mc / 2;
  else if (isym == 4)
    mc2 = mc / 4 + 1;

  const int c_line = in.line() + 1;
  std::vector<double> c_all(static_cast<std::size_t>(mc));
  for (int i = 0; i < mc; ++i) c_all[i] = in.number("C angle " + std::to_string(i + 1) + " of " + std::to_string(mc));
  std::vector<double> gamma(static_cast<std::size_t>(ng));
  for (int i = 0; i < ng; ++i)
    gamma[i] = in.number("gamma angle " + std::to_string(i + 1) + " of " + std::to_string(ng));

  const int n_planes = mc2 - mc1 + 1;
  const double lumens = out.lamp_sets.front().total_lumens;
  const double scale = lumens / 1000.0 * out.conversion_factor;
  std::vector<double> c(static_cast<std::size_t>(n_planes)), candela(static_cast<std::size_t>(n_planes) * ng);
  for (int p = 0; p < n_planes; ++p) {
    double angle = c_all[static_cast<std::size_t>((mc1 - 1 + p) % mc)];
    // Isym 3 stores C270…C360=C0…C90; as one ascending run that is −90…90.
    if (isym == 3 && angle >= 180) angle -= 360;
    c[p] = angle;
    for (int g = 0; g < ng; ++g) {
      const double v = in.number("intensity " + std::to_string(g + 1) + " of " + std::to_string(ng) + " in C plane " +
                                 std::to_string(mc1 + p) + " (cd/klm)");
      if (v < 0) in.fail("intensities must not be negative");
      if (!(v * scale <= kMaxLuminousIntensityCd))
        in.fail("an intensity times the lumens and the conversion factor is over the limit of 1e9 cd");
      candela[static_cast<std::size_t>(p) * ng + g] = v * scale;
    }
  }
  const CSymmetry symmetries[] = {CSymmetry::kNone, CSymmetry::kAxial, CSymmetry::kBilateral0_180,
                                  CSymmetry::kBilateral90_270, CSymmetry::kQuadrant};
  try {
    out.distribution =
        IntensityDistribution::table(symmetries[isym], std::move(c), std::move(gamma), std::move(candela));
  } catch (const std::invalid_argument& e) {
    in.fail_at(c_line, e.what());
  }
  return out;
}

EulumdatPhotometry read_eulumdat(const std::filesystem::path& file) {
  return parse_eulumdat(read_text_file(file, "EULUMDAT file"), file.string());
}

}  // namespace skylit
