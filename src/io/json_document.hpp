// Parsing a JSON document with errors users can act on: nlohmann's byte offsets become line
// numbers. Shared by the problem reader (json_format.cpp) and the T-mesh reader
// (tmesh/tmesh_json.cpp).
#pragma once

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "bimdf/error.hpp"

namespace bimdf::detail {

// Parses `text`; throws InputError naming `source` and the line of a syntax error, or only
// `source` for a number beyond double's range (nlohmann gives no position for those).
inline nlohmann::json parse_json_document(std::string_view text, const std::string& source) {
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::out_of_range& e) {
    std::string what = e.what();
    if (const size_t k = what.find("] "); k != std::string::npos) what = what.substr(k + 2);
    throw InputError(source, "", "invalid JSON: " + what);
  } catch (const nlohmann::json::parse_error& e) {
    const size_t at = std::min<size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
    int line = 1;
    for (size_t i = 0; i < at; ++i) line += text[i] == '\n';
    std::string what = e.what();
    if (const size_t k = what.find("syntax error"); k != std::string::npos) what = what.substr(k);
    throw InputError(source, std::to_string(line), "invalid JSON: " + what);
  }
}

}  // namespace bimdf::detail
