// Error messages stay one readable line whatever the input holds (docs/limits.md, "Messages").
#pragma once
#include <string>
#include <string_view>

namespace dspbr {

// Quoted input (a key, a value, a URI): bytes outside printable ASCII written \xNN, cut to
// kQuoteChars characters followed by "...".
inline constexpr std::size_t kQuoteChars = 200;
std::string quote_input(std::string_view s);
// quote_input between single quotes: 'text'.
inline std::string in_quotes(std::string_view s) { return "'" + quote_input(s) + "'"; }

// A whole message: control characters (newline, ESC, ...) written \xNN; everything else as is
// (UTF-8 file names stay readable).
std::string one_line(std::string_view s);

// The one wording of an integer setting out of its range, for the command line and Python alike:
// "must be <meaning> from <lo> to <hi> (decimal digits), got '<text>'" (text quoted, cut to 40).
std::string integer_range_message(const std::string& meaning, unsigned long long lo, unsigned long long hi,
                                  std::string_view text);

}  // namespace dspbr
