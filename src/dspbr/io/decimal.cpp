#include "dspbr/io/decimal.h"

#include <locale.h>
#include <stdlib.h>

#include <cerrno>
#include <cmath>
#include <string>

namespace dspbr {

namespace {

// The grammar of RFC 8259's `number`, matched by hand: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
bool json_number_grammar(std::string_view s) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t start = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i > start;
  };
  if (i < s.size() && s[i] == '-') ++i;
  if (i < s.size() && s[i] == '0') ++i;
  else if (!digits()) return false;
  if (i < s.size() && s[i] == '.') {
    ++i;
    if (!digits()) return false;
  }
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (!digits()) return false;
  }
  return i == s.size();
}

}  // namespace

Decimal parse_decimal(std::string_view text) {
  Decimal d;
  if (!json_number_grammar(text)) return d;
  // strtod_l in the "C" locale on text the grammar admits (whatever LC_NUMERIC the host set, e.g.
  // a Python program's locale.setlocale); ERANGE with an infinite result is an overflow, with a
  // finite one an underflow (kept: subnormal or 0).
  static const locale_t c_locale = ::newlocale(LC_NUMERIC_MASK, "C", locale_t(0));
  const std::string s(text);
  errno = 0;
  d.value = ::strtod_l(s.c_str(), nullptr, c_locale);
  d.status = errno == ERANGE && std::isinf(d.value) ? Decimal::OutOfRange : Decimal::Ok;
  return d;
}

}  // namespace dspbr
