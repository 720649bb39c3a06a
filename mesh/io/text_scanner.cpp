#include "mesh/io/text_scanner.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include <fast_float/fast_float.h>

namespace umbra {

bool TextScanner::next_line() {
  if (next_start_ >= text_.size()) return false;
  // A plain loop: find_first_of tests each byte against the set in turn.
  size_t stop = next_start_;
  while (stop < text_.size() && text_[stop] != '\n' && text_[stop] != '\r') ++stop;
  line_start_ = next_start_;
  line_ = text_.substr(next_start_, stop - next_start_);
  next_start_ = stop;
  if (next_start_ < text_.size()) {
    const bool carriage_return = text_[next_start_] == '\r';
    ++next_start_;
    if (carriage_return && next_start_ < text_.size() && text_[next_start_] == '\n') ++next_start_;
  }
  pos_ = 0;
  column_ = 1;
  ++line_number_;
  return true;
}

namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
}  // namespace

std::string_view TextScanner::field() {
  while (pos_ < line_.size() && is_space(line_[pos_])) ++pos_;
  const size_t start = pos_;
  while (pos_ < line_.size() && !is_space(line_[pos_])) ++pos_;
  column_ = int(start) + 1;
  return line_.substr(start, pos_ - start);
}

bool TextScanner::at_line_end() {
  while (pos_ < line_.size() && is_space(line_[pos_])) ++pos_;
  column_ = int(pos_) + 1;
  return pos_ >= line_.size();
}

double TextScanner::number(const char* what) {
  const double value = any_number(what);
  if (!std::isfinite(value)) fail(std::string("the ") + what + " is " + quote_field(last_field_) + ", not a finite number");
  return value;
}

double TextScanner::any_number(const char* what) {
  const std::string_view text = field();
  last_field_ = text;
  if (text.empty()) fail(std::string("expected a number for the ") + what + ", got end of line");
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (*first == '+') ++first;  // from_chars refuses the '+' that C's strtod and many exporters write
  double value = 0.0;
  // fast_float: correctly rounded like std::from_chars, several times faster than libstdc++'s.
  const auto [ptr, ec] = fast_float::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || first == last)
    fail(std::string("expected a number for the ") + what + ", got " + quote_field(text));
  return value;
}

glm::dvec3 TextScanner::vertex() {
  glm::dvec3 p;
  p.x = number("vertex x coordinate");
  p.y = number("vertex y coordinate");
  p.z = number("vertex z coordinate");
  return p;
}

int64_t TextScanner::integer(const char* what) {
  const std::string_view text = field();
  if (text.empty()) fail(std::string("expected an integer for the ") + what + ", got end of line");
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (*first == '+') ++first;
  int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range) fail(std::string("the ") + what + " " + quote_field(text) + " is out of range");
  if (ec != std::errc() || ptr != last || first == last)
    fail(std::string("expected an integer for the ") + what + ", got " + quote_field(text));
  return value;
}

uint64_t TextScanner::count(const char* what) {
  const int64_t value = integer(what);
  if (value < 0) fail(std::string("the ") + what + " must not be negative, got " + std::to_string(value));
  return uint64_t(value);
}

void TextScanner::fail(const std::string& message) const {
  throw InputError({path_, line_number_, column_}, message);
}

void TextScanner::fail_at_line(const std::string& message) const { throw InputError({path_, line_number_, 0}, message); }

std::string quote_field(std::string_view field) {
  std::string out = "\"";
  const size_t shown = std::min<size_t>(field.size(), 40);
  for (size_t i = 0; i < shown; ++i) {
    const unsigned char c = static_cast<unsigned char>(field[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += char(c);
    } else {
      static const char* const kHex = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (shown < field.size()) out += "...";
  return out + "\"";
}

bool is_word(std::string_view field, std::string_view word) {
  if (field.size() != word.size()) return false;
  for (size_t i = 0; i < field.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(field[i])) != word[i]) return false;
  return true;
}

}  // namespace umbra
