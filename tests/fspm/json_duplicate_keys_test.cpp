// Duplicate keys in JSON objects: refused with the file, the line and column of the second key,
// and the line of the first; keys in different objects, and key-like strings among values, are
// not duplicates.
#include "fspm/json_duplicate_keys.hpp"

#include <gtest/gtest.h>

#include "fspm/error.hpp"
#include "fspm/json_fields.hpp"

namespace fspm {
namespace {

TEST(JsonDuplicateKeys, SecondKeyIsNamedWithItsPlace) {
  try {
    parse_json_text("{\n  \"a\": 1,\n  \"b\": [\"a\", \"a\"],\n  \"a\": 2\n}", "s.json");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "s.json");
    EXPECT_EQ(e.line(), 4);
    EXPECT_EQ(e.column(), 3);
    EXPECT_EQ(e.message(), "duplicate key 'a' (first given on line 2)");
  }
}

TEST(JsonDuplicateKeys, SameKeyInOtherObjectsAndAsValuesIsFine) {
  EXPECT_NO_THROW(check_json_duplicate_keys(
      R"({"a": {"a": 1, "b": {"a": 2}}, "b": [{"a": 1}, {"a": 2}], "c": "a", "d": ["a", "a"]})",
      "f.json"));
  // A string holding an escaped quote and a colon is one value, not a key.
  EXPECT_NO_THROW(check_json_duplicate_keys(R"({"a": "x\": 1, \"a", "b": 2})", "g.json"));
}

TEST(JsonDuplicateKeys, EscapedSpellingsOfOneKeyAreTheSameKey) {
  EXPECT_THROW(check_json_duplicate_keys(R"({"ab": 1, "a\u0062": 2})", "h.json"), ParseError);
  EXPECT_THROW(check_json_duplicate_keys(R"([{"x": 1}, {"y": 1, "y" : 2}])", "i.json"), ParseError);
}

}  // namespace
}  // namespace fspm
