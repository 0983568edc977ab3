// Private: number formatting shared by the G-code writer and its tests. Locale-free
// (std::to_chars), so output does not depend on the user's LC_NUMERIC.
#pragma once

#include <charconv>
#include <string>

namespace swarf::detail {

/// `value` with exactly `decimals` digits after the point; never "-0.000"; with no
/// decimals still a trailing point ("12."), which Fanuc needs to read millimetres rather
/// than least increments.
inline std::string format_fixed(double value, int decimals) {
  char buf[400];  // DBL_MAX in fixed notation with up to 9 decimals fits
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  if (ec != std::errc()) return "nan";  // unreachable with decimals <= 9
  std::string s(buf, ptr);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  if (decimals == 0) s += '.';
  return s;
}

}  // namespace swarf::detail
