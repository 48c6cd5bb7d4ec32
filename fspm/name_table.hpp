#pragma once
// The one table between an enum's values and their names in files, options and messages: each
// configuration enum defines one NameTable, and its `*_name`/`*_from_name` functions, the
// command-line help and the "unknown ... (did you mean ...?)" message are all read from it.
#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fspm {

// One value, its name and a short phrase saying what it means (for --help and docs).
template <typename Enum>
struct NamedValue {
  Enum value{};
  std::string_view name;
  std::string_view help;
};

// "a", "a or b", "a, b or c".
std::string expected_names_text(const std::vector<std::string_view>& names);

// "unknown junction mode 'smoth': expected separate or continuous (did you mean 'smooth'?)";
// the hint is left out when no name is close.
std::string unknown_name_message(std::string_view noun, std::string_view name,
                                 const std::vector<std::string_view>& names);

// Throws ValueError with unknown_name_message, prefixed by "context: " when context is not empty.
[[noreturn]] void throw_unknown_name(std::string_view context, std::string_view noun,
                                     std::string_view name,
                                     const std::vector<std::string_view>& names);

template <typename Enum, std::size_t N>
class NameTable {
 public:
  // `noun` names the kind of value in messages ("junction mode", "light_model").
  constexpr NameTable(std::string_view noun, const NamedValue<Enum> (&entries)[N]) : noun_(noun) {
    for (std::size_t i = 0; i < N; ++i) {
      // A table given fewer entries than N: a compile-time error for the constexpr tables.
      if (entries[i].name.empty()) throw std::logic_error("NameTable: an entry without a name");
      entries_[i] = entries[i];
    }
  }

  constexpr std::string_view noun() const { return noun_; }
  constexpr std::size_t size() const { return N; }
  constexpr const std::array<NamedValue<Enum>, N>& entries() const { return entries_; }

  // The values in table order (the order of the help and of "expected ...").
  constexpr std::array<Enum, N> values() const {
    std::array<Enum, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = entries_[i].value;
    return out;
  }

  // The value's name; the first entry's for a value outside the table (a cast integer).
  constexpr std::string_view name(Enum value) const {
    for (const NamedValue<Enum>& e : entries_) {
      if (e.value == value) return e.name;
    }
    return entries_[0].name;
  }

  constexpr std::optional<Enum> find(std::string_view name) const {
    for (const NamedValue<Enum>& e : entries_) {
      if (e.name == name) return e.value;
    }
    return std::nullopt;
  }

  // The value named `name`, or a ValueError naming the closest name and every name;
  // `context` ("--light-model", "stages") goes before the message.
  Enum from_name(std::string_view name, std::string_view context = {}) const {
    if (const std::optional<Enum> v = find(name)) return *v;
    throw_unknown_name(context, noun_, name, names());
  }

  std::vector<std::string_view> names() const {
    std::vector<std::string_view> out;
    for (const NamedValue<Enum>& e : entries_) out.push_back(e.name);
    return out;
  }

  // "a, b or c".
  std::string expected() const { return expected_names_text(names()); }

  // "a (what a means), b (what b means)": the values for --help.
  std::string help() const {
    std::string out;
    for (const NamedValue<Enum>& e : entries_) {
      if (!out.empty()) out += ", ";
      out += e.name;
      if (!e.help.empty()) out += " (" + std::string(e.help) + ")";
    }
    return out;
  }

  std::string unknown_message(std::string_view name) const {
    return unknown_name_message(noun_, name, names());
  }

 private:
  std::string_view noun_;
  std::array<NamedValue<Enum>, N> entries_{};
};

}  // namespace fspm
