// The one number grammar of the command line and the text readers (docs/limits.md, "Values"): a
// decimal number as JSON spells it (RFC 8259 section 6: an optional minus, 0 or digits without a
// leading zero, an optional fraction, an optional exponent). No hexadecimal floats, nan, inf,
// leading '+', '.5', spaces or empty text, whatever std::strtod would take.
#pragma once
#include <string_view>

namespace dspbr {

struct Decimal {
  enum Status { Ok, NotANumber, OutOfRange } status = NotANumber;
  double value = 0;  // Ok: the nearest double (a value too small for a normal double is subnormal or 0)
};

// OutOfRange: the grammar's, but beyond the largest double (1e999).
Decimal parse_decimal(std::string_view text);

}  // namespace dspbr
