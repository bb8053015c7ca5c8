// A whitespace tokenizer with line numbers and strict number parsing, shared by the text
// readers (.bimdf problems, plain-text flows). Every failure is an InputError that names the
// source, the line and what was expected.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bimdf/error.hpp"

namespace bimdf::detail {

struct Token {
  std::string_view text;  // empty at end of input
  int line = 0;
};

class TextScanner {
 public:
  TextScanner(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

  // Skips blanks and '#' comments (to the end of the line). Returns an empty token at the end.
  Token peek();
  Token next();
  // Skips the rest of the current line (used for libSatsuma's free first line).
  void skip_line();
  bool at_end() { return peek().text.empty(); }

  // Bytes not yet read: an upper bound on how many more tokens can follow (each needs ≥ 2).
  size_t remaining() const { return text_.size() - pos_; }
  int line() const { return line_; }

  // Reads the next token as the given kind of value; `what` says what is expected, e.g.
  // "the head flag of edge 3 (0 or 1)". End of input and malformed tokens throw.
  Token expect(const std::string& what);
  int64_t expect_int(const std::string& what);
  double expect_double(const std::string& what);

  [[noreturn]] void fail(int line, const std::string& message) const;
  const std::string& source() const { return source_; }

 private:
  void skip_blanks();
  std::string_view text_;
  std::string source_;
  size_t pos_ = 0;
  int line_ = 1;
  int last_token_line_ = 1;  // where "unexpected end of file" is reported
};

// Strict conversions of a whole token; false if the token is not exactly such a number.
bool parse_int64(std::string_view token, int64_t& out);
// Accepts decimal and C hexadecimal floats (libSatsuma writes std::hexfloat), `inf`, `nan`.
bool parse_double(std::string_view token, double& out);

// Shortest decimal text that reads back to the same double (std::to_chars).
std::string format_double(double v);

// The whitespace-separated words of one line, up to a '#' comment (OBJ, OFF and PLY headers).
std::vector<std::string_view> line_words(std::string_view line);

// Quotes a token for an error message, shortened if long.
std::string quote(std::string_view token);

}  // namespace bimdf::detail
