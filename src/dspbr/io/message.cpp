#include "dspbr/io/message.h"

#include <cstdio>
#include <string>

namespace dspbr {

namespace {

void append_hex(std::string& out, unsigned char c) {
  char hex[5];
  std::snprintf(hex, sizeof hex, "\\x%02x", c);
  out += hex;
}

}  // namespace

std::string quote_input(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && i < kQuoteChars; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) out += static_cast<char>(c);
    else append_hex(out, c);
  }
  if (s.size() > kQuoteChars) out += "...";
  return out;
}

std::string one_line(std::string_view s) {
  std::string out;
  for (const char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) append_hex(out, c);
    else out += ch;
  }
  return out;
}

std::string integer_range_message(const std::string& meaning, unsigned long long lo, unsigned long long hi,
                                  std::string_view text) {
  const std::string shown = text.size() > 40 ? quote_input(text.substr(0, 40)) + "..." : quote_input(text);
  return "must be " + meaning + " from " + std::to_string(lo) + " to " + std::to_string(hi) + " (decimal digits), got '" +
         shown + "'";
}

}  // namespace dspbr
