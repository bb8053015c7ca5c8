#include "text_scan.hpp"

#include <cerrno>
#include <charconv>
#include <cstdlib>

namespace bimdf::detail {

void TextScanner::skip_blanks() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (c == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

Token TextScanner::peek() {
  skip_blanks();
  size_t end = pos_;
  while (end < text_.size()) {
    const char c = text_[end];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') break;
    ++end;
  }
  return {text_.substr(pos_, end - pos_), line_};
}

Token TextScanner::next() {
  Token t = peek();
  pos_ += t.text.size();
  if (!t.text.empty()) last_token_line_ = t.line;
  return t;
}

void TextScanner::skip_line() {
  while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
}

void TextScanner::fail(int line, const std::string& message) const {
  throw InputError(source_, std::to_string(line), message);
}

Token TextScanner::expect(const std::string& what) {
  Token t = next();
  if (t.text.empty()) fail(last_token_line_, "unexpected end of file: expected " + what);
  return t;
}

int64_t TextScanner::expect_int(const std::string& what) {
  Token t = expect(what);
  int64_t v = 0;
  if (!parse_int64(t.text, v)) fail(t.line, "expected " + what + ", got " + quote(t.text));
  return v;
}

double TextScanner::expect_double(const std::string& what) {
  Token t = expect(what);
  double v = 0;
  if (!parse_double(t.text, v)) fail(t.line, "expected " + what + ", got " + quote(t.text));
  return v;
}

bool parse_int64(std::string_view token, int64_t& out) {
  if (token.empty()) return false;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (*first == '+') ++first;  // from_chars rejects a leading '+'
  if (first == last || (*first == '-' && first + 1 == last)) return false;
  auto [ptr, ec] = std::from_chars(first, last, out);
  return ec == std::errc() && ptr == last;
}

bool parse_double(std::string_view token, double& out) {
  // strtod needs a terminated string and handles hex floats; tokens are short.
  if (token.empty() || token.size() > 512) return false;
  const std::string s(token);
  char* end = nullptr;
  errno = 0;
  out = std::strtod(s.c_str(), &end);
  // ERANGE on underflow still yields the nearest double (0 or a subnormal): accept it;
  // overflow yields ±HUGE_VAL, which validation then rejects as non-finite.
  return end == s.c_str() + s.size();
}

std::string format_double(double v) {
  char buf[64];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, ptr);
}

std::string quote(std::string_view token) {
  constexpr size_t kMax = 40;
  std::string s = "'";
  for (char c : token.substr(0, kMax)) s += (c >= 32 && c < 127) ? c : '?';
  if (token.size() > kMax) s += "...";
  return s + "'";
}

std::vector<std::string_view> line_words(std::string_view line) {
  const auto blank = [](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
  };
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    if (i < line.size() && line[i] == '#') break;
    const size_t start = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

}  // namespace bimdf::detail
