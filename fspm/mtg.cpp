#include "fspm/mtg.hpp"

#include <array>
#include <charconv>
#include <chrono>
#include <utility>

#include "fspm/error.hpp"
#include "fspm/number_text.hpp"

namespace fspm {
namespace {

struct TypeName {
  MtgFeatureType type;
  std::string_view name;
};
// The type names of OpenAlea's reader and of the AMAPmod manual (ALPHA is the older STRING).
constexpr std::array<TypeName, 11> kTypeNames{{{MtgFeatureType::kInt, "INT"},
                                               {MtgFeatureType::kReal, "REAL"},
                                               {MtgFeatureType::kAlpha, "ALPHA"},
                                               {MtgFeatureType::kString, "STRING"},
                                               {MtgFeatureType::kDdMmYy, "DD/MM/YY"},
                                               {MtgFeatureType::kDdMmYyyy, "DD/MM/YYYY"},
                                               {MtgFeatureType::kMmYy, "MM/YY"},
                                               {MtgFeatureType::kDdMm, "DD/MM"},
                                               {MtgFeatureType::kGeometry, "GEOMETRY"},
                                               {MtgFeatureType::kAppearance, "APPEARANCE"},
                                               {MtgFeatureType::kObject, "OBJECT"}}};

// The whole of `text` as a non-negative whole number.
std::optional<int> whole(std::string_view text) {
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || v < 0) return std::nullopt;
  return v;
}

// Splits "a/b/c" at '/' into up to three whole numbers.
std::optional<std::array<int, 3>> date_parts(std::string_view text, std::size_t count) {
  std::array<int, 3> parts{};
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t slash = k + 1 < count ? text.find('/') : text.size();
    if (slash == std::string_view::npos) return std::nullopt;
    const auto v = whole(text.substr(0, slash));
    if (!v) return std::nullopt;
    parts[k] = *v;
    text = slash < text.size() ? text.substr(slash + 1) : std::string_view{};
  }
  return parts;
}

std::optional<double> days_since_1970(int year, int month, int day) {
  using namespace std::chrono;
  const year_month_day date{std::chrono::year(year),
                            std::chrono::month(static_cast<unsigned>(month)),
                            std::chrono::day(static_cast<unsigned>(day))};
  if (!date.ok()) return std::nullopt;
  return static_cast<double>(sys_days(date).time_since_epoch().count());
}

}  // namespace

std::string_view mtg_feature_type_name(MtgFeatureType type) {
  for (const TypeName& t : kTypeNames) {
    if (t.type == type) return t.name;
  }
  return "REAL";
}

std::optional<MtgFeatureType> mtg_feature_type_from_name(std::string_view name) {
  for (const TypeName& t : kTypeNames) {
    if (t.name == name) return t.type;
  }
  return std::nullopt;
}

bool mtg_feature_is_date(MtgFeatureType type) {
  return type == MtgFeatureType::kDdMmYy || type == MtgFeatureType::kDdMmYyyy ||
         type == MtgFeatureType::kMmYy || type == MtgFeatureType::kDdMm;
}

bool mtg_feature_is_number(MtgFeatureType type) {
  return type == MtgFeatureType::kInt || type == MtgFeatureType::kReal;
}

std::optional<double> mtg_date_days(std::string_view text, MtgFeatureType type) {
  switch (type) {
    case MtgFeatureType::kDdMmYy:
    case MtgFeatureType::kDdMmYyyy: {
      const auto p = date_parts(text, 3);
      if (!p) return std::nullopt;
      int year = (*p)[2];
      if (year < 100) year += year < 50 ? 2000 : 1900;
      return days_since_1970(year, (*p)[1], (*p)[0]);
    }
    case MtgFeatureType::kMmYy: {
      const auto p = date_parts(text, 2);
      if (!p) return std::nullopt;
      int year = (*p)[1];
      if (year < 100) year += year < 50 ? 2000 : 1900;
      return days_since_1970(year, (*p)[0], 1);
    }
    case MtgFeatureType::kDdMm: {
      const auto p = date_parts(text, 2);
      if (!p) return std::nullopt;
      // A leap year, so that 29/02 is a date; day of the year from 0.
      const auto d = days_since_1970(2000, (*p)[1], (*p)[0]);
      const auto jan1 = days_since_1970(2000, 1, 1);
      if (!d) return std::nullopt;
      return *d - *jan1;
    }
    default:
      return std::nullopt;
  }
}

Mtg::Mtg() {
  classes.push_back({"$", 0, "FREE", "FREE", "IMPLICIT"});
  scale_.push_back(0);
  class_.push_back(0);
  index_.push_back(-1);
  complex_.push_back(kNoMtgVertex);
  parent_.push_back(kNoMtgVertex);
  edge_.push_back(MtgEdge::kNone);
  line_.push_back(0);
  components_.emplace_back();
  children_.emplace_back();
}

std::size_t Mtg::add_feature(MtgFeature feature) {
  features_.push_back(std::move(feature));
  values_.emplace_back(size());
  return features_.size() - 1;
}

std::optional<std::size_t> Mtg::feature_index(std::string_view name) const {
  for (std::size_t f = 0; f < features_.size(); ++f) {
    if (features_[f].name == name) return f;
  }
  return std::nullopt;
}

std::optional<std::size_t> Mtg::class_index(std::string_view symbol) const {
  for (std::size_t c = 0; c < classes.size(); ++c) {
    if (classes[c].symbol == symbol) return c;
  }
  return std::nullopt;
}

MtgVertex Mtg::add_component(MtgVertex complex, std::size_t class_id, long index, int line) {
  const auto v = static_cast<MtgVertex>(size());
  const int s = scale_[complex] + 1;
  scale_.push_back(s);
  class_.push_back(static_cast<std::uint32_t>(class_id));
  index_.push_back(index);
  complex_.push_back(complex);
  parent_.push_back(kNoMtgVertex);
  edge_.push_back(MtgEdge::kNone);
  line_.push_back(line);
  components_.emplace_back();
  children_.emplace_back();
  components_[complex].push_back(v);
  for (auto& column : values_) column.emplace_back();
  max_scale_ = std::max(max_scale_, s);
  return v;
}

void Mtg::set_parent(MtgVertex child, MtgVertex parent, MtgEdge edge) {
  if (scale_[child] != scale_[parent]) {
    throw ValueError("Mtg: a parent must be at its child's scale");
  }
  if (parent_[child] != kNoMtgVertex) {
    throw ValueError("Mtg: vertex " + label(child) + " already has a parent");
  }
  parent_[child] = parent;
  edge_[child] = edge;
  children_[parent].push_back(child);
}

std::string Mtg::label(MtgVertex v) const {
  std::string s = symbol(v);
  if (index_[v] >= 0) s += std::to_string(index_[v]);
  return s;
}

std::vector<MtgVertex> Mtg::vertices(int scale) const {
  std::vector<MtgVertex> out;
  for (MtgVertex v = 0; v < size(); ++v) {
    if (scale_[v] == scale) out.push_back(v);
  }
  return out;
}

MtgVertex Mtg::complex_at_scale(MtgVertex v, int scale) const {
  while (v != kNoMtgVertex && scale_[v] > scale) v = complex_[v];
  return v != kNoMtgVertex && scale_[v] == scale ? v : kNoMtgVertex;
}

void Mtg::set_feature_text(MtgVertex v, std::size_t feature, std::string_view text) {
  values_[feature][v].assign(text);
}

std::optional<double> Mtg::feature_number(MtgVertex v, std::size_t feature) const {
  const std::string& text = values_[feature][v];
  if (text.empty()) return std::nullopt;
  const MtgFeatureType type = features_[feature].type;
  if (mtg_feature_is_date(type)) return mtg_date_days(text, type);
  return parse_number(text);
}

void Mtg::complete_topology() {
  for (int s = max_scale_ - 1; s >= 1; --s) {
    for (MtgVertex v = 1; v < size(); ++v) {
      if (scale_[v] != s || parent_[v] != kNoMtgVertex || components_[v].empty()) continue;
      const MtgVertex first = components_[v].front();
      if (parent_[first] == kNoMtgVertex) continue;
      const MtgVertex p = complex_[parent_[first]];
      if (p == kNoMtgVertex || p == v || scale_[p] != s) continue;
      set_parent(v, p, edge_[first]);
    }
  }
}

}  // namespace fspm
