// Parsing ISO 8601 date-times with a UTC offset, and their Julian Day (UT).
// The day count is the proleptic-Gregorian "days from civil" of H. Hinnant
// (http://howardhinnant.github.io/date_algorithms.html), anchored at the Unix epoch,
// 1970-01-01 00:00 UT = JD 2440587.5 (Meeus, Astronomical Algorithms, ch. 7).
#include "skylit/sun/time.h"

#include <cctype>
#include <string>

#include "skylit/core/error.h"

namespace skylit {

namespace {

constexpr std::string_view kExample = "2026-06-21T07:00:00+09:00";
constexpr const char* kMonthNames[] = {"January", "February", "March",     "April",   "May",      "June",
                                       "July",    "August",   "September", "October", "November", "December"};

std::string quoted(std::string_view text) {
  constexpr size_t kMaxShown = 60;
  std::string result(1, '"');
  result.append(text.substr(0, kMaxShown));
  if (text.size() > kMaxShown) result.append("...");
  result.push_back('"');
  return result;
}

// Reads the characters of `text` one field at a time; any mismatch is a format error.
class Reader {
 public:
  Reader(std::string_view text, std::string_view where) : text_(text), where_(where) {}

  [[noreturn]] void fail(const std::string& what) const { throw InputError(std::string(where_) + ": " + what); }
  [[noreturn]] void fail_format() const {
    fail("expected an ISO 8601 date-time with a UTC offset, like " + std::string(kExample) + " or " +
         "2026-06-20T22:00:00Z, got " + quoted(text_));
  }

  bool at_end() const { return pos_ == text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[pos_]; }
  size_t position() const { return pos_; }

  int digits(int count) {
    int value = 0;
    for (int i = 0; i < count; ++i) {
      if (at_end() || std::isdigit(static_cast<unsigned char>(text_[pos_])) == 0) fail_format();
      value = value * 10 + (text_[pos_++] - '0');
    }
    return value;
  }
  void expect(char c) {
    if (peek() != c) fail_format();
    ++pos_;
  }
  bool accept(char c) {
    if (peek() != c) return false;
    ++pos_;
    return true;
  }
  // One or more digits after the decimal sign, as a fraction of one.
  double fraction() {
    double value = 0, scale = 0.1;
    if (std::isdigit(static_cast<unsigned char>(peek())) == 0) fail_format();
    while (std::isdigit(static_cast<unsigned char>(peek())) != 0) {
      value += scale * (text_[pos_++] - '0');
      scale *= 0.1;
    }
    return value;
  }

 private:
  std::string_view text_;
  std::string_view where_;
  size_t pos_ = 0;
};

}  // namespace

long long days_from_civil(long long year, int month, int day) {
  year -= month <= 2 ? 1 : 0;
  const long long era = (year >= 0 ? year : year - 399) / 400;
  const long long year_of_era = year - era * 400;
  const long long day_of_year = (153 * (month > 2 ? month - 3 : month + 9) + 2) / 5 + day - 1;
  const long long day_of_era = year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;
  return era * 146097 + day_of_era - 719468;
}

bool is_leap_year(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int days_in_month(int year, int month) {
  constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month == 2 && is_leap_year(year) ? 29 : kDays[month - 1];
}

OffsetDateTime parse_offset_date_time(std::string_view text, std::string_view where) {
  Reader in(text, where);
  OffsetDateTime t;
  t.year = in.digits(4);
  in.expect('-');
  t.month = in.digits(2);
  in.expect('-');
  t.day = in.digits(2);
  // ISO 8601 writes 'T'; RFC 3339 also allows a lower-case 't' or a space.
  if (!in.accept('T') && !in.accept('t') && !in.accept(' ')) {
    if (in.at_end())
      in.fail("expected a date and a time of day with a UTC offset, like " + std::string(kExample) +
              ", got only a date " + quoted(text));
    in.fail_format();
  }
  t.hour = in.digits(2);
  in.expect(':');
  t.minute = in.digits(2);
  if (in.accept(':')) {
    t.second = in.digits(2);
    if (in.accept('.') || in.accept(',')) t.second += in.fraction();
  }

  const std::string_view local = text.substr(0, in.position());
  if (in.at_end())
    in.fail(quoted(local) + " has no UTC offset, and a local time alone is ambiguous: add Z for UTC or the " +
            "local offset, e.g. " + std::string(local) + "+09:00");
  if (in.accept('Z') || in.accept('z')) {
    t.utc_offset_minutes = 0;
  } else {
    const char sign = in.peek();
    if (sign != '+' && sign != '-') in.fail_format();
    in.expect(sign);
    const int offset_hours = in.digits(2);
    int offset_minutes = 0;
    // Minutes after a colon (required then), or straight after the hours, or none.
    if (in.accept(':') || !in.at_end()) offset_minutes = in.digits(2);
    if (offset_minutes > 59 || offset_hours * 60 + offset_minutes > 18 * 60)
      in.fail("the UTC offset in " + quoted(text) + " is not a clock offset from -18:00 to +18:00");
    t.utc_offset_minutes = (sign == '-' ? -1 : 1) * (offset_hours * 60 + offset_minutes);
  }
  if (!in.at_end()) in.fail_format();

  if (t.month < 1 || t.month > 12)
    in.fail("month " + std::to_string(t.month) + " in " + quoted(text) + " is not 1 to 12");
  if (t.day < 1 || t.day > days_in_month(t.year, t.month))
    in.fail(std::string(text.substr(0, 10)) + " is not a date: " + kMonthNames[t.month - 1] + " " +
            std::to_string(t.year) + " has " + std::to_string(days_in_month(t.year, t.month)) + " days");
  if (t.hour > 23)
    in.fail("hour " + std::to_string(t.hour) + " in " + quoted(text) +
            " is not 0 to 23 (write midnight at the end of a day as 00:00 of the next)");
  if (t.minute > 59) in.fail("minute " + std::to_string(t.minute) + " in " + quoted(text) + " is not 0 to 59");
  if (t.second >= 61) in.fail("the seconds in " + quoted(text) + " are not below 61 (60 is a leap second)");
  return t;
}

double julian_day_ut(const OffsetDateTime& t) {
  constexpr double kJulianDayOfUnixEpoch = 2440587.5;
  const double seconds_of_day = t.hour * 3600.0 + t.minute * 60.0 + t.second - t.utc_offset_minutes * 60.0;
  // The whole days first: a half-integer near 2.4e6 is exact, so the fraction keeps its precision.
  return (kJulianDayOfUnixEpoch + static_cast<double>(days_from_civil(t.year, t.month, t.day))) +
         seconds_of_day / 86400.0;
}

}  // namespace skylit
