// EULUMDAT reading (format description by Stockmar, 1990): hand-written files for
// each symmetry Isym 0–4, cd/klm → absolute candela through the lamps' lumens, flux
// against the lamp lumens × LORL; malformed files give InputError naming file:line,
// and random byte mutations never crash.
#include "skylit/lights/eulumdat_reader.h"

#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../test_support.h"
#include "skylit/core/error.h"

namespace skylit {
namespace {

using skylit::testing::TempDir;

// A complete file: header lines 1–26, one lamp set, direct ratios, the angles and
// the given planes of intensities (cd/klm).
std::string ldt(int isym, const std::vector<double>& c_angles, const std::vector<double>& gammas,
                const std::vector<std::vector<double>>& planes, double lamp_lumens = 1000,
                const std::string& lorl = "100") {
  std::ostringstream o;
  o << "Skylit test company\n1\n"
    << isym << "\n"
    << c_angles.size() << "\n"
    << (c_angles.size() > 1 ? c_angles[1] - c_angles[0] : 0) << "\n"
    << gammas.size() << "\n"
    << (gammas[1] - gammas[0]) << "\n"
    << "report 1\nTest luminaire\nLUM-1\ntest.ldt\n2026-11-22 skylit\n"
    << "300\n0\n100\n250\n0\n50\n50\n50\n50\n"  // lines 13–21
    << "100\n"
    << lorl << "\n1.0\n0\n"  // DFF, LORL, CFLI, tilt
    << "1\n"                 // one lamp set
    << "1\nLED 4000K\n"
    << lamp_lumens << "\n4000K\n80\n25\n";
  for (int k = 0; k < 10; ++k) o << "0.5\n";
  for (double c : c_angles) o << c << "\n";
  for (double g : gammas) o << g << "\n";
  for (const auto& p : planes)
    for (double v : p) o << v << "\n";
  return o.str();
}

std::vector<double> constant(std::size_t n, double v) { return std::vector<double>(n, v); }

std::string message_of(const std::string& text, const std::string& name = "lum.ldt") {
  return testing::input_error_of([&] { parse_eulumdat(text, name); });
}

const std::vector<double> kGammas = {0, 30, 60, 90, 120, 150, 180};
const std::vector<double> kFourC = {0, 90, 180, 270};

TEST(EulumdatReader, ReadsAxialFileAndFluxMatchesLamps) {
  std::vector<double> c24;
  for (int i = 0; i < 24; ++i) c24.push_back(15.0 * i);
  std::vector<double> g19;
  for (int i = 0; i <= 18; ++i) g19.push_back(10.0 * i);
  // 1000/4π cd/klm everywhere: the luminaire emits all of its 2000 lamp lumens.
  TempDir dir;
  const auto file = dir.write("iso.ldt", ldt(1, c24, g19, {constant(19, 79.5775)}, 2000));
  const EulumdatPhotometry e = read_eulumdat(file);
  EXPECT_EQ(e.symmetry_indicator, 1);
  EXPECT_EQ(e.c_planes, 24);
  ASSERT_EQ(e.lamp_sets.size(), 1u);
  EXPECT_EQ(e.lamp_sets[0].type, "LED 4000K");
  EXPECT_EQ(e.luminaire_name, "Test luminaire");
  EXPECT_EQ(e.distribution.symmetry(), CSymmetry::kAxial);
  EXPECT_NEAR(e.distribution.candela(200, 45), 159.155, 1e-9);
  // Integration tolerance 0.1 %: flux = lamp lumens × LORL.
  EXPECT_NEAR(e.distribution.luminous_flux(), 2000 * e.light_output_ratio / 100, 2.0);
}

TEST(EulumdatReader, ReadsEachSymmetry) {
  {  // Isym 4: C0 and C90 stored.
    const auto d = parse_eulumdat(ldt(4, kFourC, kGammas, {constant(7, 100), constant(7, 300)}), "q.ldt").distribution;
    EXPECT_EQ(d.symmetry(), CSymmetry::kQuadrant);
    EXPECT_DOUBLE_EQ(d.candela(45, 10), 200);
    EXPECT_DOUBLE_EQ(d.candela(180, 10), 100);
    EXPECT_DOUBLE_EQ(d.candela(270, 10), 300);
  }
  {  // Isym 2: C0–C180.
    const auto d =
        parse_eulumdat(ldt(2, kFourC, kGammas, {constant(7, 100), constant(7, 200), constant(7, 300)}), "b.ldt")
            .distribution;
    EXPECT_EQ(d.symmetry(), CSymmetry::kBilateral0_180);
    EXPECT_DOUBLE_EQ(d.candela(270, 10), 200);
    EXPECT_DOUBLE_EQ(d.candela(225, 10), 250);
  }
  {  // Isym 3: planes Mc1 = 3Mc/4+1 … Mc1+Mc/2, i.e. C270, C0, C90.
    const auto d =
        parse_eulumdat(ldt(3, kFourC, kGammas, {constant(7, 30), constant(7, 20), constant(7, 10)}), "b90.ldt")
            .distribution;
    EXPECT_EQ(d.symmetry(), CSymmetry::kBilateral90_270);
    EXPECT_DOUBLE_EQ(d.candela(270, 10), 30);
    EXPECT_DOUBLE_EQ(d.candela(0, 10), 20);
    EXPECT_DOUBLE_EQ(d.candela(90, 10), 10);
    EXPECT_DOUBLE_EQ(d.candela(180, 10), 20);  // mirror of C0
    EXPECT_DOUBLE_EQ(d.candela(135, 10), 15);  // mirror of C45
  }
  {  // Isym 0: all planes; wraps from C270 to C360.
    const auto d =
        parse_eulumdat(ldt(0, kFourC, kGammas, {constant(7, 1), constant(7, 2), constant(7, 3), constant(7, 4)}, 2000),
                       "n.ldt")
            .distribution;
    EXPECT_EQ(d.symmetry(), CSymmetry::kNone);
    EXPECT_DOUBLE_EQ(d.candela(315, 10), 5);  // 2.5 cd/klm × 2 klm
  }
}

TEST(EulumdatReader, AcceptsDecimalCommas) {
  std::string t = ldt(1, kFourC, kGammas, {constant(7, 12.5)}, 1000, "87,5");
  const auto e = parse_eulumdat(t, "comma.ldt");
  EXPECT_DOUBLE_EQ(e.light_output_ratio, 87.5);
}

TEST(EulumdatReader, MalformedFilesNameFileAndLine) {
  const std::string good = ldt(4, kFourC, kGammas, {constant(7, 100), constant(7, 300)});
  // Truncated: 66 of the 67 lines (26 header + 6 lamp set + 10 ratios + 4 C + 7 γ + 14 values).
  {
    const std::string cut = good.substr(0, good.size() - 4);  // drops the last value "300\n"
    const std::string m = message_of(cut, "cut.ldt");
    EXPECT_NE(m.find("cut.ldt:"), std::string::npos) << m;
    EXPECT_NE(m.find("expected intensity 7 of 7 in C plane 2"), std::string::npos) << m;
    EXPECT_NE(m.find("end of the file"), std::string::npos) << m;
  }
  // A word where a number is expected: line 4 (Mc).
  {
    std::string t = good;
    const std::size_t p = t.find("\n4\n4\n") + 3;  // line 3 is Isym 4, line 4 is Mc 4
    t.replace(p, 1, "four");
    const std::string m = message_of(t);
    EXPECT_NE(m.find("lum.ldt:4: expected the number of C planes Mc (line 4), found 'four'"), std::string::npos) << m;
  }
  // Bad symmetry indicator and counts.
  {
    std::string t = good;
    t[t.find("\n4\n4\n") + 1] = '7';
    EXPECT_NE(message_of(t).find("lum.ldt:3: expected the symmetry indicator"), std::string::npos);
  }
  {
    const std::string t = ldt(4, {0, 120, 240}, kGammas, {constant(7, 1), constant(7, 1)});
    EXPECT_NE(message_of(t).find("lum.ldt:4: Mc = 3 does not suit symmetry Isym 4"), std::string::npos)
        << message_of(t);
  }
  {
    const std::string t = ldt(4, {0, 45, 180, 270}, kGammas, {constant(7, 1), constant(7, 1)});
    EXPECT_NE(message_of(t).find("do not span 0-90"), std::string::npos) << message_of(t);
  }
  {
    const std::string t = ldt(1, kFourC, kGammas, {constant(7, 1)}, -5);
    EXPECT_NE(message_of(t).find("lum.ldt:29: the total lumens of lamp set 1 must be positive"), std::string::npos)
        << message_of(t);
  }
  EXPECT_NE(message_of("").find("lum.ldt:1: expected the company"), std::string::npos);
}

TEST(EulumdatReader, RandomByteMutationsNeverCrash) {
  const std::string good = ldt(2, kFourC, kGammas, {constant(7, 100), constant(7, 200), constant(7, 300)});
  std::mt19937 rng(777);
  int errors = 0, parsed = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string t = good;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t pos = rng() % t.size();
      switch (rng() % 3) {
        case 0:
          t[pos] = static_cast<char>(rng() % 256);
          break;
        case 1:
          t.erase(pos, 1 + rng() % 8);
          break;
        default:
          t.insert(pos, 1, "0123456789\n-.,e"[rng() % 15]);
          break;
      }
    }
    try {
      parse_eulumdat(t, "mutant.ldt").distribution.candela(10, 10);
      ++parsed;
    } catch (const InputError& e) {
      ++errors;
      EXPECT_EQ(std::string(e.what()).rfind("mutant.ldt:", 0), 0u) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not an InputError: " << e.what();
    }
  }
  EXPECT_GT(errors, 100);
  EXPECT_GT(parsed, 100);
}

}  // namespace
}  // namespace skylit
