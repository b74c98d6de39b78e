// IES LM-63 reading (LM-63-19, LM-63-02): hand-written 2019, 2002, 1995, 1991 and 1986 files,
// TILT=INCLUDE, each Type C symmetry, absolute candela and flux; malformed files give
// one InputError naming file:line, and random byte mutations never crash.
#include "skylit/lights/ies_reader.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "../test_support.h"
#include "skylit/core/error.h"
#include "skylit/core/vec3.h"

namespace skylit {
namespace {

using skylit::testing::TempDir;

// 1000 lm isotropic: 1000 / 4π = 79.5775 cd everywhere; numbers wrap across lines
// and mix commas and spaces.
const char* kIsotropic2002 =
    "IESNA:LM-63-2002\n"
    "[TEST] 12345\n"
    "[MANUFAC] Skylit test lamps\n"
    "[MORE] second line\n"
    "TILT=NONE\n"
    "1 1000 1 19 1 1 1 0.1 0.1 0.0\n"
    "1.0 1.0 100\n"
    "0 10 20 30 40 50 60 70 80 90\n"
    "100,110,120, 130 140 150 160 170 180\n"
    "0\n"
    "79.5775 79.5775 79.5775 79.5775 79.5775 79.5775 79.5775 79.5775 79.5775 79.5775\n"
    "79.5775 79.5775 79.5775 79.5775 79.5775 79.5775 79.5775 79.5775 79.5775\n";

// One file per symmetry: γ 0, 90; values constant in γ so C interpolation shows.
std::string type_c_file(const std::string& header, const std::string& h_angles, int n_h, const std::string& candela) {
  return header + "TILT=NONE\n1 -1 1 2 " + std::to_string(n_h) + " 1 2 0 0 0\n1 1 50\n0 90\n" + h_angles + "\n" +
         candela + "\n";
}

std::string message_of(const std::string& text, const std::string& name = "lamp.ies") {
  return testing::input_error_of([&] { parse_ies(text, name); });
}

TEST(IesReader, Reads2002AxialFileAndFluxMatchesLumens) {
  TempDir dir;
  const auto file = dir.write("iso.ies", kIsotropic2002);
  const IesPhotometry ies = read_ies(file);
  EXPECT_EQ(ies.format, "LM-63-2002");
  ASSERT_EQ(ies.keywords.size(), 2u);
  EXPECT_EQ(ies.keywords[0].first, "TEST");
  EXPECT_EQ(ies.keywords[1].second, "Skylit test lamps\nsecond line");
  EXPECT_EQ(ies.distribution.symmetry(), CSymmetry::kAxial);
  EXPECT_DOUBLE_EQ(ies.rated_lumens(), 1000);
  EXPECT_DOUBLE_EQ(ies.input_watts, 100);
  EXPECT_NEAR(ies.width_m, 0.1 * 0.3048, 1e-12);  // units 1 = feet
  EXPECT_NEAR(ies.distribution.candela(77, 33), 79.5775, 1e-9);
  // Integration tolerance: 0.1 % (the midpoint rule is far better than that here).
  EXPECT_NEAR(ies.distribution.luminous_flux(), 1000, 1.0);
}

TEST(IesReader, Reads1995QuadrantFileWithTiltIncludeAndMultipliers) {
  const std::string text =
      "IESNA:LM-63-1995\n[TEST] quad\nTILT=INCLUDE\n1\n3\n0 45 90\n1.0 0.9\n0.8\n"
      "2 500 2.0 3 3 1 2 0.5 0.5 0.2\n0.5 2.0 150\n0 45 90\n0 45 90\n"
      "100 80 0\n200 150 0\n300 250 0\n";
  const IesPhotometry ies = parse_ies(text, "quad.ies");
  EXPECT_EQ(ies.format, "LM-63-1995");
  EXPECT_EQ(ies.tilt.lamp_to_luminaire_geometry, 1);
  ASSERT_EQ(ies.tilt.multipliers.size(), 3u);
  EXPECT_DOUBLE_EQ(ies.tilt.multiplier(45), 0.9);
  EXPECT_DOUBLE_EQ(ies.rated_lumens(), 1000);
  EXPECT_EQ(ies.distribution.symmetry(), CSymmetry::kQuadrant);
  // × multiplier 2 × ballast 0.5 × ballast-lamp factor 2 = × 2.
  const auto& d = ies.distribution;
  EXPECT_DOUBLE_EQ(d.candela(0, 0), 200);
  EXPECT_DOUBLE_EQ(d.candela(90, 0), 600);
  EXPECT_DOUBLE_EQ(d.candela(22.5, 0), 300);
  EXPECT_DOUBLE_EQ(d.candela(135, 0), 400);    // mirror of 45
  EXPECT_DOUBLE_EQ(d.candela(270, 45), 500);   // mirror of 90
  EXPECT_DOUBLE_EQ(d.candela(337.5, 0), 300);  // mirror of 22.5
}

TEST(IesReader, ReadsEachTypeCSymmetry) {
  const std::string h = "IESNA:LM-63-2002\n";
  {
    const auto d = parse_ies(type_c_file(h, "0 90 180", 3, "100 100 200 200 300 300"), "b.ies").distribution;
    EXPECT_EQ(d.symmetry(), CSymmetry::kBilateral0_180);
    EXPECT_DOUBLE_EQ(d.candela(270, 0), 200);
    EXPECT_DOUBLE_EQ(d.candela(225, 45), 250);
  }
  {
    const auto d = parse_ies(type_c_file(h, "90 180 270", 3, "10 10 20 20 30 30"), "b90.ies").distribution;
    EXPECT_EQ(d.symmetry(), CSymmetry::kBilateral90_270);
    EXPECT_DOUBLE_EQ(d.candela(90, 0), 10);
    EXPECT_DOUBLE_EQ(d.candela(180, 0), 20);
    EXPECT_DOUBLE_EQ(d.candela(270, 0), 30);
    EXPECT_DOUBLE_EQ(d.candela(0, 0), 20);    // mirror of 180
    EXPECT_DOUBLE_EQ(d.candela(45, 0), 15);   // mirror of 135
    EXPECT_DOUBLE_EQ(d.candela(315, 0), 25);  // mirror of 225
  }
  {
    const auto d = parse_ies(type_c_file(h, "0 90 180 270", 4, "1 1 2 2 3 3 4 4"), "n.ies").distribution;
    EXPECT_EQ(d.symmetry(), CSymmetry::kNone);
    EXPECT_DOUBLE_EQ(d.candela(45, 0), 1.5);
    EXPECT_DOUBLE_EQ(d.candela(315, 0), 2.5);  // wraps from C270 back to C360 = C0
    EXPECT_DOUBLE_EQ(d.candela(-45, 0), 2.5);
  }
  {
    const auto d = parse_ies(type_c_file(h, "0 90 180 270 360", 5, "1 1 2 2 3 3 4 4 1 1"), "n360.ies").distribution;
    EXPECT_DOUBLE_EQ(d.candela(315, 0), 2.5);
  }
}

TEST(IesReader, ReadsOlderHeaderForms) {
  const std::string body = "TILT=NONE\n1 -1 1 2 1 1 2 0 0 0\n1 1 50\n0 90\n0\n10 5\n";
  const auto a = parse_ies("IESNA91\n[TEST] old\n" + body, "old.ies");
  EXPECT_EQ(a.format, "LM-63-1991");
  const auto b = parse_ies("Some lamp, measured 1986\nfree text line\n" + body, "older.ies");
  EXPECT_EQ(b.format, "LM-63-1986");
  EXPECT_DOUBLE_EQ(b.distribution.candela(0, 45), 7.5);
  EXPECT_DOUBLE_EQ(b.rated_lumens(), -1);  // absolute photometry
  // CRLF line ends.
  std::string crlf = kIsotropic2002;
  for (std::size_t p = crlf.find('\n'); p != std::string::npos; p = crlf.find('\n', p + 2)) crlf.insert(p, 1, '\r');
  EXPECT_NEAR(parse_ies(crlf, "crlf.ies").distribution.candela(0, 0), 79.5775, 1e-9);
}

TEST(IesReader, The2019FormsFileGenerationTypeIsACodeNotAFactor) {
  // LM-63-19 Table 2: 1.10000 = tested at an accredited laboratory. Read as the
  // 1986 form's ballast-lamp factor it had made the luminaire 10 % too bright.
  const std::string body =
      "[TEST] 1\n[TESTLAB] lab\n[ISSUEDATE] 2024-01-01\n[MANUFAC] m\nTILT=NONE\n"
      "1 -1 1 2 1 1 2 0 0 0\n1 1.10000 50\n0 90\n0\n10 5\n";
  const auto ies = parse_ies("IES:LM-63-2019\n" + body, "new.ies");
  EXPECT_EQ(ies.format, "LM-63-2019");
  EXPECT_DOUBLE_EQ(ies.file_generation_type, 1.1);
  EXPECT_DOUBLE_EQ(ies.ballast_lamp_factor, 1);
  EXPECT_DOUBLE_EQ(ies.distribution.candela(0, 0), 10);
  EXPECT_DOUBLE_EQ(ies.distribution.candela(0, 90), 5);
  // Another year under the new identifier is not guessed at.
  EXPECT_NE(message_of("IES:LM-63-2031\n" + body).find("lamp.ies:1: unknown format identifier"), std::string::npos);
}

TEST(IesReader, AByteOrderMarkDoesNotHideTheIdentifier) {
  // A 2002 file whose future-use field is 0: read as the 1986 form (the identifier
  // hidden behind the mark), that 0 was a ballast-lamp factor and the file refused.
  std::string text = kIsotropic2002;
  text.replace(text.find("1.0 1.0 100"), 11, "1.0 0 100");
  const auto ies = parse_ies("\xEF\xBB\xBF" + text, "bom.ies");
  EXPECT_EQ(ies.format, "LM-63-2002");
  EXPECT_NEAR(ies.distribution.candela(0, 0), 79.5775, 1e-9);
}

TEST(IesReader, MalformedFilesNameFileAndLine) {
  const std::string good = kIsotropic2002;
  // Truncated inside the candela values: the error points at the last line.
  {
    const std::string m = message_of(good.substr(0, good.rfind("79.5775 79.5775\n")), "cut.ies");
    EXPECT_NE(m.find("cut.ies:12: expected candela value"), std::string::npos) << m;
    EXPECT_NE(m.find("end of the file"), std::string::npos) << m;
  }
  // A word where a number is expected, on line 8.
  {
    std::string t = good;
    t.replace(t.find("0 10 20"), 1, "abc");
    const std::string m = message_of(t);
    EXPECT_NE(m.find("lamp.ies:8: expected vertical angle 1 of 19, found 'abc'"), std::string::npos) << m;
  }
  // Bad counts.
  {
    std::string t = good;
    t.replace(t.find("1 1000 1 19 1"), 13, "1 1000 1 -3 1");
    const std::string m = message_of(t);
    EXPECT_NE(m.find("lamp.ies:6: expected the number of vertical angles"), std::string::npos) << m;
  }
  {
    std::string t = good;
    t.replace(t.find("1 1000 1 19 1"), 13, "1 1000 1 2.5 1");
    EXPECT_NE(message_of(t).find("lamp.ies:6:"), std::string::npos);
  }
  // Unsupported photometric type B.
  {
    std::string t = good;
    t.replace(t.find("1 1000 1 19 1 1 1"), 17, "1 1000 1 19 1 2 1");
    const std::string m = message_of(t);
    EXPECT_NE(m.find("lamp.ies:6: photometric type B is not supported"), std::string::npos) << m;
  }
  // TILT=<file>, no TILT line, unknown identifier, a C range with no symmetry, descending angles.
  {
    std::string t = good;
    t.replace(t.find("TILT=NONE"), 9, "TILT=lamp.tlt");
    EXPECT_NE(message_of(t).find("lamp.ies:5: TILT='lamp.tlt': a separate tilt file is not supported"),
              std::string::npos);
  }
  EXPECT_NE(message_of("IESNA:LM-63-2002\n[TEST] x\n").find("lamp.ies:2: expected a TILT= line"), std::string::npos);
  EXPECT_NE(message_of("IESNA:LM-63-2019\nTILT=NONE\n").find("lamp.ies:1: unknown format identifier"),
            std::string::npos);
  EXPECT_NE(message_of(type_c_file("IESNA:LM-63-2002\n", "0 45", 2, "1 1 1 1")).find("lamp.ies:6: horizontal angles"),
            std::string::npos);
  EXPECT_NE(message_of(type_c_file("IESNA:LM-63-2002\n", "0 90 45", 3, "1 1 1 1 1 1"))
                .find("lamp.ies:6: horizontal angles must increase"),
            std::string::npos);
  EXPECT_NE(message_of(type_c_file("IESNA:LM-63-2002\n", "0 90", 2, "1 1 1 -1"))
                .find("lamp.ies:7: candela values must not be negative"),
            std::string::npos);
  // A missing file.
  TempDir dir;
  try {
    read_ies(dir.path() / "missing.ies");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.ies:1: cannot open"), std::string::npos);
  }
}

TEST(IesReader, RandomByteMutationsNeverCrash) {
  const std::string good = std::string(kIsotropic2002);
  std::mt19937 rng(12345);
  int errors = 0, parsed = 0;
  const char alphabet[] = "0123456789.,- \n\t-eE+xTILT=[]\r\0\xff";
  for (int trial = 0; trial < 2000; ++trial) {
    std::string t = good;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t pos = rng() % t.size();
      switch (rng() % 3) {
        case 0:
          t[pos] = alphabet[rng() % (sizeof alphabet - 1)];
          break;
        case 1:
          t.erase(pos, 1 + rng() % 8);
          break;
        default:
          t.insert(pos, 1, static_cast<char>(rng() % 256));
          break;
      }
    }
    try {
      const IesPhotometry ies = parse_ies(t, "mutant.ies");
      ies.distribution.candela(10, 10);
      ++parsed;
    } catch (const InputError& e) {
      ++errors;
      EXPECT_EQ(std::string(e.what()).rfind("mutant.ies:", 0), 0u) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not an InputError: " << e.what() << "\n" << t;
    }
  }
  EXPECT_GT(errors, 100);
  EXPECT_GT(parsed, 100);
}

}  // namespace
}  // namespace skylit
