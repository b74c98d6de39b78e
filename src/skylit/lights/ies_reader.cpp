// IES LM-63 reader (ANSI/IES LM-63-19 and LM-63-02; also the 1995, 1991 and 1986 forms): the header and
// keyword lines up to TILT=, the optional inline tilt table, then a free-format
// numeric block in which numbers may wrap across lines and be separated by commas or
// whitespace. Every error names the file and the line where the expected item was
// (or where the file ended).
#include "skylit/lights/ies_reader.h"

#include <algorithm>
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

// Generous bounds: real files have at most a few hundred angles each way, and
// refusing absurd counts keeps a corrupted file from asking for gigabytes.
constexpr int kMaxAngles = 10000;
constexpr long kMaxValues = 4000000;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::string upper(std::string s) {
  for (char& ch : s)
    if (ch >= 'a' && ch <= 'z') ch = static_cast<char>(ch - 'a' + 'A');
  return s;
}

struct Token {
  std::string text;
  int line;
};

// The numeric block, tokenised with the line each number came from.
class Numbers {
 public:
  Numbers(const std::string& name, std::vector<Token> tokens, int last_line)
      : name_(name), tokens_(std::move(tokens)), last_line_(last_line) {}

  double number(const std::string& what) {
    if (next_ >= tokens_.size())
      throw InputError(name_ + ":" + std::to_string(last_line_) + ": expected " + what + ", found the end of the file");
    const Token& t = tokens_[next_++];
    const auto v = parse_number(t.text);
    if (!v)
      throw InputError(name_ + ":" + std::to_string(t.line) + ": expected " + what + ", found " +
                       quote_excerpt(t.text));
    return *v;
  }

  int integer(const std::string& what, int lo, int hi) {
    const int line = current_line();
    const double v = number(what);
    if (v != std::floor(v) || v < lo || v > hi)
      throw InputError(name_ + ":" + std::to_string(line) + ": expected " + what + " (a whole number from " +
                       std::to_string(lo) + " to " + std::to_string(hi) + "), found " +
                       quote_excerpt(tokens_[next_ - 1].text));
    return static_cast<int>(v);
  }

  // The line of the next token (or the last line at the end): for errors about a
  // value just read, call before reading it.
  int current_line() const { return next_ < tokens_.size() ? tokens_[next_].line : last_line_; }
  const std::string& name() const { return name_; }

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw InputError(name_ + ":" + std::to_string(line) + ": " + message);
  }

 private:
  std::string name_;
  std::vector<Token> tokens_;
  std::size_t next_ = 0;
  int last_line_;
};

std::vector<double> read_list(Numbers& in, int count, const std::string& what) {
  std::vector<double> v(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) v[i] = in.number(what + " " + std::to_string(i + 1) + " of " + std::to_string(count));
  return v;
}

void check_ascending(Numbers& in, const std::vector<double>& v, int line, const std::string& what, double lo,
                     double hi) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] < lo || v[i] > hi)
      in.fail(line, what + " must lie within " + std::to_string(static_cast<int>(lo)) + "-" +
                        std::to_string(static_cast<int>(hi)) + " degrees");
    if (i > 0 && !(v[i] > v[i - 1])) in.fail(line, what + " must increase strictly");
  }
}

}  // namespace

IesPhotometry parse_ies(const std::string& text, const std::string& name) {
  std::vector<std::string> lines;
  {
    std::string line;
    // A byte order mark had hidden the identifier line: the file was read as the 1986
    // form, its "future use" field as a factor.
    std::istringstream stream{std::string(without_byte_order_mark(text))};
    while (std::getline(stream, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines.push_back(line);
    }
  }
  const int n_lines = static_cast<int>(lines.size());
  auto fail = [&](int line, const std::string& message) -> void {
    throw InputError(name + ":" + std::to_string(line) + ": " + message);
  };

  IesPhotometry out;
  // The identifier line; a 1986 file has none and starts with free text.
  std::size_t li = 0;
  const std::string first = n_lines > 0 ? upper(trim(lines[0])) : std::string();
  if (first.rfind("IES:LM-63-2019", 0) == 0)
    out.format = "LM-63-2019", li = 1;
  else if (first.rfind("IESNA:LM-63-2002", 0) == 0)
    out.format = "LM-63-2002", li = 1;
  else if (first.rfind("IESNA:LM-63-1995", 0) == 0)
    out.format = "LM-63-1995", li = 1;
  else if (first.rfind("IESNA91", 0) == 0)
    out.format = "LM-63-1991", li = 1;
  else if (first.rfind("IESNA", 0) == 0 || first.rfind("IES:", 0) == 0)
    fail(1, "unknown format identifier " + quote_excerpt(trim(lines[0])) +
                " (expected IES:LM-63-2019, IESNA:LM-63-2002, IESNA:LM-63-1995 or IESNA91)");
  else
    out.format = "LM-63-1986";

  // Keyword (or, for 1986, free text) lines up to TILT=.
  int tilt_line = 0;
  std::string tilt_value;
  for (; li < lines.size(); ++li) {
    const std::string line = trim(lines[li]);
    // "TILT=" (spaces allowed before the '='), not merely a text line starting "Tilt".
    if (upper(line).rfind("TILT", 0) == 0 && trim(line.substr(4)).rfind('=', 0) == 0) {
      tilt_line = static_cast<int>(li) + 1;
      tilt_value = trim(line.substr(line.find('=') + 1));
      break;
    }
    if (line.size() > 1 && line[0] == '[') {
      const auto close = line.find(']');
      if (close == std::string::npos) {
        if (out.format != "LM-63-1986") fail(static_cast<int>(li) + 1, "keyword line without a closing ']'");
        continue;
      }
      const std::string key = upper(line.substr(1, close - 1));
      const std::string value = trim(line.substr(close + 1));
      if (key == "MORE" && !out.keywords.empty())
        out.keywords.back().second += "\n" + value;
      else
        out.keywords.emplace_back(key, value);
    }
  }
  if (tilt_line == 0) fail(std::max(n_lines, 1), "expected a TILT= line, found the end of the file");
  const std::string tilt = upper(tilt_value);
  if (tilt != "NONE" && tilt != "INCLUDE")
    fail(tilt_line,
         "TILT=" + quote_excerpt(tilt_value) +
             ": a separate tilt file is not supported (expected TILT=NONE or TILT=INCLUDE with the tilt data inline)");

  // Everything after the TILT line is numbers.
  std::vector<Token> tokens;
  for (std::size_t i = static_cast<std::size_t>(tilt_line); i < lines.size(); ++i) {
    std::string token;
    for (char ch : lines[i] + " ") {
      if (ch == ' ' || ch == '\t' || ch == ',' || ch == '\v' || ch == '\f') {
        if (!token.empty()) tokens.push_back({token, static_cast<int>(i) + 1}), token.clear();
      } else {
        token += ch;
      }
    }
  }
  Numbers in(name, std::move(tokens), std::max(n_lines, 1));

  if (tilt == "INCLUDE") {
    out.tilt.lamp_to_luminaire_geometry = in.integer("the lamp-to-luminaire geometry (1-3)", 1, 3);
    const int n = in.integer("the number of tilt angles", 1, kMaxAngles);
    const int line = in.current_line();
    out.tilt.angles_deg = read_list(in, n, "tilt angle");
    out.tilt.multipliers = read_list(in, n, "tilt multiplier");
    check_ascending(in, out.tilt.angles_deg, line, "tilt angles", 0, 180);
    for (double m : out.tilt.multipliers)
      // A multiplier is the lamp's relative output at a tilt, near 1; 100 bounds the
      // candela limit's product as well.
      if (!(m >= 0 && m <= 100)) in.fail(line, "tilt multipliers must be from 0 to 100");
  }

  out.number_of_lamps = in.integer("the number of lamps", 1, 1000000);
  {
    const int line = in.current_line();
    out.lumens_per_lamp = in.number("the lumens per lamp");
    if (out.lumens_per_lamp <= 0 && out.lumens_per_lamp != -1)
      in.fail(line, "lumens per lamp must be positive, or -1 for absolute photometry");
  }
  {
    const int line = in.current_line();
    out.candela_multiplier = in.number("the candela multiplier");
    if (out.candela_multiplier <= 0) in.fail(line, "the candela multiplier must be positive");
  }
  const int n_vertical = in.integer("the number of vertical angles", 2, kMaxAngles);
  const int n_horizontal = in.integer("the number of horizontal angles", 1, kMaxAngles);
  {
    const int line = in.current_line();
    out.photometric_type = in.integer("the photometric type (1, 2 or 3)", 1, 3);
    if (out.photometric_type != 1)
      in.fail(line, std::string("photometric type ") + (out.photometric_type == 2 ? "B" : "A") +
                        " is not supported (only Type C, photometric type 1)");
  }
  const int units = in.integer("the units type (1 = feet, 2 = metres)", 1, 2);
  const double to_m = units == 1 ? 0.3048 : 1.0;
  out.width_m = in.number("the luminaire width") * to_m;
  out.length_m = in.number("the luminaire length") * to_m;
  out.height_m = in.number("the luminaire height") * to_m;
  {
    const int line = in.current_line();
    out.ballast_factor = in.number("the ballast factor");
    if (out.ballast_factor <= 0) in.fail(line, "the ballast factor must be positive");
  }
  {
    const int line = in.current_line();
    // The ballast-lamp photometric factor until 1995; a field for future use in 2002;
    // in 2019 the file generation type (LM-63-2019 Table 2: 1.00000 to 1.11100 say
    // whether the file was measured, simulated, interpolated or scaled), a code and no
    // factor: an accredited lab's 1.10000 had made the luminaire 10 % too bright.
    const bool is_factor = out.format != "LM-63-2002" && out.format != "LM-63-2019";
    const double field = in.number(out.format == "LM-63-2002"   ? "the future-use field"
                                   : out.format == "LM-63-2019" ? "the file generation type"
                                                                : "the ballast-lamp photometric factor");
    if (out.format == "LM-63-2019") out.file_generation_type = field;
    if (is_factor) {
      if (field <= 0) in.fail(line, "the ballast-lamp photometric factor must be positive");
      out.ballast_lamp_factor = field;
    }
  }
  out.input_watts = in.number("the input watts");

  if (static_cast<long>(n_vertical) * n_horizontal > kMaxValues)
    in.fail(in.current_line(),
            "too many candela values (" + std::to_string(n_vertical) + " x " + std::to_string(n_horizontal) + ")");
  const int v_line = in.current_line();
  std::vector<double> gamma = read_list(in, n_vertical, "vertical angle");
  const int h_line = in.current_line();
  std::vector<double> c = read_list(in, n_horizontal, "horizontal angle");
  std::vector<double> candela(static_cast<std::size_t>(n_vertical) * n_horizontal);
  const double scale = out.candela_multiplier * out.ballast_factor * out.ballast_lamp_factor;
  for (int h = 0; h < n_horizontal; ++h) {
    for (int v = 0; v < n_vertical; ++v) {
      const int line = in.current_line();
      const double value = in.number("candela value " + std::to_string(v + 1) + " of " + std::to_string(n_vertical) +
                                     " for horizontal angle " + std::to_string(h + 1));
      if (value < 0) in.fail(line, "candela values must not be negative");
      if (!(value * scale <= kMaxLuminousIntensityCd))
        in.fail(line, "a candela value (times the multiplier and ballast factors) is over the limit of 1e9 cd");
      candela[static_cast<std::size_t>(h) * n_vertical + v] = value;
    }
  }
  // Anything after the candela values is ignored (some writers add a blank line or a checksum).

  check_ascending(in, gamma, v_line, "vertical angles", 0, 180);
  check_ascending(in, c, h_line, "horizontal angles", 0, 360);

  // The symmetry follows from the first and last horizontal angle (LM-63-02 §3.18).
  CSymmetry symmetry;
  const double c0 = c.front(), c1 = c.back();
  if (n_horizontal == 1)
    symmetry = CSymmetry::kAxial;
  else if (c0 == 0 && c1 == 90)
    symmetry = CSymmetry::kQuadrant;
  else if (c0 == 0 && c1 == 180)
    symmetry = CSymmetry::kBilateral0_180;
  else if (c0 == 90 && c1 == 270)
    symmetry = CSymmetry::kBilateral90_270;
  else if (c0 == 0 && c1 > 180 && c1 <= 360)
    symmetry = CSymmetry::kNone;
  else
    in.fail(h_line, "horizontal angles from " + std::to_string(c0) + " to " + std::to_string(c1) +
                        " match no Type C symmetry (expected one angle, 0-90, 0-180, 90-270 or 0 to more than 180)");

  if (symmetry == CSymmetry::kBilateral90_270) {
    // Store the mirror image, the half through C0: C' = 180 − C, columns reversed.
    std::vector<double> c2(c.size()), cd2(candela.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
      const std::size_t src = c.size() - 1 - i;
      c2[i] = 180.0 - c[src];
      std::copy_n(candela.begin() + static_cast<long>(src * n_vertical), n_vertical,
                  cd2.begin() + static_cast<long>(i * n_vertical));
    }
    c = std::move(c2);
    candela = std::move(cd2);
  }

  for (double& v : candela) v *= scale;  // each checked against the limit where it was read
  try {
    out.distribution = IntensityDistribution::table(symmetry, std::move(c), std::move(gamma), std::move(candela));
  } catch (const std::invalid_argument& e) {
    in.fail(h_line, e.what());
  }
  return out;
}

IesPhotometry read_ies(const std::filesystem::path& file) {
  return parse_ies(read_text_file(file, "IES file"), file.string());
}

}  // namespace skylit
