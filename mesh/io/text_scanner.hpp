#pragma once
// Line-by-line reading of text mesh files with located errors: every number
// and index is parsed with std::from_chars (no locale, no silent garbage), and
// a failure names the file, line and column.

#include <cstdint>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

#include "mesh/input_error.hpp"

namespace umbra {

class TextScanner {
 public:
  // `lines_before`: the lines of the file ahead of `text`, which starts a
  // line, so that errors name the file's line.
  TextScanner(std::string_view text, std::string path, int lines_before = 0)
      : text_(text), path_(std::move(path)), line_number_(lines_before) {}

  // Moves to the next line; false at the end of the text. Lines end at \n, \r\n or \r.
  bool next_line();
  int line_number() const { return line_number_; }
  // The next whitespace-separated field of the current line; empty at its end.
  std::string_view field();
  // The rest of the current line after the fields read so far.
  std::string_view rest_of_line() const { return line_.substr(pos_); }
  bool at_line_end();

  double number(const char* what);                 // a finite number, or an error naming `what`
  double any_number(const char* what);             // the same, but also nan or inf
  glm::dvec3 vertex();                             // three numbers: a vertex's x, y and z
  int64_t integer(const char* what);               // a decimal integer
  uint64_t count(const char* what);                // a non-negative integer

  [[noreturn]] void fail(const std::string& message) const;  // at the current field
  [[noreturn]] void fail_at_line(const std::string& message) const;
  FileLoc where() const { return {path_, line_number_, column_}; }
  const std::string& path() const { return path_; }
  size_t offset() const { return line_start_ + pos_; }  // byte offset in the text

 private:
  std::string_view text_;
  std::string path_;
  size_t next_start_ = 0;
  size_t line_start_ = 0;
  std::string_view line_;
  size_t pos_ = 0;
  int line_number_ = 0;
  int column_ = 0;  // 1-based column of the last field returned
  std::string_view last_field_;  // the last number read
};

// Whether `field` is `word` (written in lower case) in any case: ascii STL's
// keywords come as "SOLID" and "FACET" too.
bool is_word(std::string_view field, std::string_view word);

// "\"abc\"", printable for error messages however odd the bytes are.
std::string quote_field(std::string_view field);

}  // namespace umbra
