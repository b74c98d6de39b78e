// ΔT = TT − UT, the difference between the uniform time of the ephemerides and the
// time kept by the Earth's rotation, estimated from the date when no measured value is
// given. Source: F. Espenak and J. Meeus, "Five Millennium Canon of Solar Eclipses:
// −1999 to +3000", NASA/TP-2006-214141 (2006), section 2.6, "Polynomial Expressions
// for Delta T"; outside −1999..3000 their long-term parabola −20 + 32 u² is used.
#pragma once

namespace skylit {

// ΔT in seconds at a decimal year (e.g. 2026.5 for the start of July 2026). Good to
// about a second for 1900–2005; the 2005–2050 polynomial, fitted in 2006, is about
// 5 s high by 2025 (measured ΔT ≈ 69 s), which moves the sun by less than 0.0001°.
// Before 1600 its uncertainty grows to minutes and hours.
double delta_t_estimate_s(double decimal_year);

// The decimal year of a Julian Day (UT), near enough for delta_t_estimate_s.
double decimal_year_of_julian_day(double julian_day_ut);

}  // namespace skylit
