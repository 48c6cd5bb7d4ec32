#include "fspm/json_fields.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "fspm/closest_name.hpp"
#include "fspm/error.hpp"
#include "fspm/json_duplicate_keys.hpp"
#include "fspm/json_location.hpp"
#include "fspm/nesting_depth.hpp"

namespace fspm {

using nlohmann::json;

json parse_json_text(std::string_view text, const std::string& file_name) {
  check_json_depth(text, file_name);
  try {
    json document = json::parse(text.begin(), text.end());
    check_json_duplicate_keys(text, file_name);
    return document;
  } catch (const json::parse_error& e) {
    // Line and column of the byte the parser stopped at.
    int line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::string what = e.what();
    const auto pos = what.find("syntax error");
    throw ParseError(
        "expected valid JSON (" + (pos == std::string::npos ? what : what.substr(pos)) + ")",
        file_name, line, column);
  } catch (const json::exception& e) {
    // Out-of-range numbers and the like, which nlohmann reports without a position.
    throw ParseError(std::string("expected valid JSON (") + e.what() + ")", file_name);
  }
}

void JsonFields::fail(const std::string& path, const std::string& expected, const json* got) const {
  std::string msg = (path.empty() ? std::string("/") : path) + ": expected " + expected;
  if (got) msg += ", got " + got->dump();
  const TextPosition at = json_pointer_position(text_, path);
  throw ValueError(msg, file_, at.line, at.column);
}

void JsonFields::check_keys(const json& obj, const std::string& path,
                            std::initializer_list<const char*> allowed) const {
  const std::vector<std::string> known(allowed.begin(), allowed.end());
  // A number or a list where an object belongs has no keys to check (nor to read).
  if (!obj.is_object()) fail(path.empty() ? "/" : path, "an object", &obj);
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
    const std::string key_path = path + "/" + it.key();
    const TextPosition at = json_pointer_position(text_, key_path);
    throw ValueError(unknown_key_message(key_path, it.key(), known), file_, at.line, at.column);
  }
}

double JsonFields::number(const json& obj, const std::string& path, const char* key, double lo,
                          double hi, const std::string& what) const {
  const std::string p = path + "/" + key;
  if (!obj.contains(key)) fail(p, what + " (missing)");
  const json& v = obj.at(key);
  if (!v.is_number()) fail(p, what, &v);
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi) fail(p, what, &v);
  return x;
}

std::optional<double> JsonFields::optional_number(const json& obj, const std::string& path,
                                                  const char* key, double lo, double hi,
                                                  const std::string& what) const {
  if (!obj.contains(key)) return std::nullopt;
  return number(obj, path, key, lo, hi, what);
}

std::optional<bool> JsonFields::optional_boolean(const json& obj, const std::string& path,
                                                 const char* key) const {
  if (!obj.contains(key)) return std::nullopt;
  if (!obj.at(key).is_boolean()) fail(path + "/" + key, "true or false", &obj.at(key));
  return obj.at(key).get<bool>();
}

std::string JsonFields::text(const json& obj, const std::string& path, const char* key,
                             const std::string& what) const {
  const std::string p = path + "/" + key;
  if (!obj.contains(key)) fail(p, what + " (missing)");
  const json& v = obj.at(key);
  if (!v.is_string() || v.get<std::string>().empty()) fail(p, what, &v);
  return v.get<std::string>();
}

std::string JsonFields::vec_what(int n) {
  return "an array of " + std::to_string(n) + " numbers within 1e9";
}

}  // namespace fspm
