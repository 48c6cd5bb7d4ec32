#include "fspm/compressed_tree_graph.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/number_text.hpp"

namespace fspm {
namespace {

constexpr char kMagic[8] = {'F', 'S', 'P', 'M', 'C', 'T', 'R', 'E'};
constexpr std::uint32_t kVersion = 1;
// Version 2: version 1 followed by the turtle geometry (CtreeGeometry).
constexpr std::uint32_t kGeometryVersion = 2;
constexpr std::uint8_t kGroupKind = 255;

// Topological order of the records (referrers before referred), or ValueError on a cycle.
std::vector<RecordId> topological_order(std::span<const CompressedRecord> records,
                                        std::span<const RecordId> refs) {
  const std::size_t n = records.size();
  std::vector<std::uint32_t> indegree(n, 0);
  for (const auto& r : records) {
    if (r.successor != kNoRecord) ++indegree[r.successor];
    for (std::uint32_t k = 0; k < r.axillary_count; ++k) ++indegree[refs[r.axillary_begin + k]];
  }
  std::vector<RecordId> order;
  order.reserve(n);
  for (RecordId i = 0; i < n; ++i) {
    if (indegree[i] == 0) order.push_back(i);
  }
  for (std::size_t head = 0; head < order.size(); ++head) {
    const auto& r = records[order[head]];
    auto visit = [&](RecordId c) {
      if (--indegree[c] == 0) order.push_back(c);
    };
    if (r.successor != kNoRecord) visit(r.successor);
    for (std::uint32_t k = 0; k < r.axillary_count; ++k) visit(refs[r.axillary_begin + k]);
  }
  if (order.size() != n) throw ValueError("compressed tree graph has a cycle");
  return order;
}

void put_bytes(std::string& out, const void* data, std::size_t size) {
  out.append(static_cast<const char*>(data), size);
}
template <typename T>
void put(std::string& out, T value) {
  // Little-endian on disk whatever the host.
  using U = std::conditional_t<
      sizeof(T) == 8, std::uint64_t,
      std::conditional_t<sizeof(T) == 4, std::uint32_t,
                         std::conditional_t<sizeof(T) == 2, std::uint16_t, std::uint8_t>>>;
  U u = std::bit_cast<U>(value);
  char bytes[sizeof(U)];
  for (std::size_t i = 0; i < sizeof(U); ++i) {
    bytes[i] = static_cast<char>(u & 0xFFu);
    if constexpr (sizeof(U) > 1) u = static_cast<U>(u >> 8);
  }
  put_bytes(out, bytes, sizeof(U));
}

class Reader {
 public:
  Reader(std::string_view bytes, const std::string& source) : bytes_(bytes), source_(source) {}
  template <typename T>
  T get(const char* what) {
    using U = std::conditional_t<
        sizeof(T) == 8, std::uint64_t,
        std::conditional_t<sizeof(T) == 4, std::uint32_t,
                           std::conditional_t<sizeof(T) == 2, std::uint16_t, std::uint8_t>>>;
    need(sizeof(U), what);
    U u = 0;
    for (std::size_t i = 0; i < sizeof(U); ++i) {
      u = static_cast<U>(u |
                         (static_cast<U>(static_cast<unsigned char>(bytes_[pos_ + i])) << (8 * i)));
    }
    pos_ += sizeof(U);
    return std::bit_cast<T>(u);
  }
  std::string_view take(std::size_t size, const char* what) {
    need(size, what);
    auto s = bytes_.substr(pos_, size);
    pos_ += size;
    return s;
  }
  std::size_t remaining() const { return bytes_.size() - pos_; }
  [[noreturn]] void fail(const std::string& message) const {
    throw ParseError(message + " at byte " + std::to_string(pos_), source_);
  }

 private:
  void need(std::size_t size, const char* what) const {
    if (bytes_.size() - pos_ < size) {
      fail(std::string("truncated .ctree file: expected ") + what);
    }
  }
  std::string_view bytes_;
  const std::string& source_;
  std::size_t pos_ = 0;
};

// Multiplicities grow exponentially with the age of a branching plant: refuse to wrap around.
void add_checked(std::uint64_t& into, std::uint64_t value) {
  if (__builtin_add_overflow(into, value, &into)) {
    throw ValueError("compressed tree graph stands for more than 2^64 metamers");
  }
}

}  // namespace

RecordId CompressedTreeGraph::add_record(const CompressedRecord& record,
                                         std::span<const RecordId> axillaries) {
  CompressedRecord r = record;
  r.axillary_begin = static_cast<std::uint32_t>(axillary_refs_.size());
  r.axillary_count = static_cast<std::uint32_t>(axillaries.size());
  axillary_refs_.insert(axillary_refs_.end(), axillaries.begin(), axillaries.end());
  records_.push_back(r);
  return static_cast<RecordId>(records_.size() - 1);
}

void CompressedTreeGraph::set_volumes(RecordId id, double pith, double rings, double leaf) {
  auto& r = records_[id];
  r.pith_volume = pith;
  r.ring_volume = rings;
  r.leaf_volume = leaf;
}

void CompressedTreeGraph::reserve(std::size_t records, std::size_t axillaries) {
  records_.reserve(records);
  axillary_refs_.reserve(axillaries);
}

void CompressedTreeGraph::validate() const {
  const std::size_t n = records_.size();
  if (root_ != kNoRecord && root_ >= n)
    throw ValueError("compressed tree graph: root out of range");
  for (std::size_t i = 0; i < n; ++i) {
    const auto& r = records_[i];
    if (r.successor != kNoRecord && r.successor >= n) {
      throw ValueError("compressed tree graph: record " + std::to_string(i) +
                       " has an out-of-range successor");
    }
    if (static_cast<std::uint64_t>(r.axillary_begin) + r.axillary_count > axillary_refs_.size()) {
      throw ValueError("compressed tree graph: record " + std::to_string(i) +
                       " has an out-of-range axillary list");
    }
    for (RecordId a : axillaries(static_cast<RecordId>(i))) {
      if (a >= n) {
        throw ValueError("compressed tree graph: record " + std::to_string(i) +
                         " has an out-of-range axillary");
      }
    }
  }
  (void)topological_order(records_, axillary_refs_);
  if (has_geometry()) validate_geometry();
}

void CompressedTreeGraph::validate_geometry() const {
  const CtreeGeometry& g = geometry;
  const std::size_t n = records_.size();
  auto fail = [](const std::string& what) {
    throw ValueError("compressed tree graph geometry: " + what);
  };
  if (g.records.size() != n) fail("one record geometry per record expected");
  if (g.axillary_placements.size() != axillary_refs_.size()) {
    fail("one placement index per axillary reference expected");
  }
  for (const auto& [name, column] : g.attributes) {
    if (column.size() != n) fail("attribute '" + name + "' needs one value per record");
  }
  if (root_ != kNoRecord && !g.records[root_].group) fail("the root must be a group record");
  for (std::size_t i = 0; i < n; ++i) {
    const auto& r = records_[i];
    std::size_t organs = 0;
    if (r.successor != kNoRecord && !g.records[r.successor].group) ++organs;
    for (std::uint32_t k = 0; k < r.axillary_count; ++k) {
      const std::uint32_t p = g.axillary_placements[r.axillary_begin + k];
      const RecordId a = axillary_refs_[r.axillary_begin + k];
      if (p != kNoPlacement && p >= g.placements.size()) {
        fail("record " + std::to_string(i) + " refers to a missing placement");
      }
      if (!g.records[a].group) {
        ++organs;
        if (p != kNoPlacement) {
          fail("record " + std::to_string(i) + " places a record that is not a group");
        }
      }
    }
    if (g.records[i].group && organs > 1) {
      fail("group record " + std::to_string(i) + " has more than one member that is not a group");
    }
  }
}

std::uint64_t CompressedTreeGraph::compute_multiplicities() {
  validate();
  for (auto& r : records_) r.multiplicity = 0;
  if (root_ == kNoRecord) return 0;
  records_[root_].multiplicity = 1;
  for (RecordId id : topological_order(records_, axillary_refs_)) {
    const auto& r = records_[id];
    if (r.multiplicity == 0) continue;
    const std::uint64_t m = r.multiplicity;
    if (r.successor != kNoRecord) add_checked(records_[r.successor].multiplicity, m);
    for (std::uint32_t k = 0; k < r.axillary_count; ++k) {
      add_checked(records_[axillary_refs_[r.axillary_begin + k]].multiplicity, m);
    }
  }
  std::uint64_t total = 0;
  for (const auto& r : records_) add_checked(total, r.multiplicity);
  return total;
}

std::uint64_t CompressedTreeGraph::expanded_size() const {
  std::uint64_t total = 0;
  for (const auto& r : records_) total += r.multiplicity;
  return total;
}

TreeGraph CompressedTreeGraph::expand(double max_birth) const {
  TreeGraph tree;
  if (root_ == kNoRecord || records_[root_].birth > max_birth) return tree;
  struct Item {
    RecordId record;
    NodeId parent;
    std::uint16_t order;
  };
  std::vector<Item> stack{{root_, kNoNode, 0}};
  std::vector<RecordId> laterals;
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const auto& r = records_[item.record];
    NodeData d;
    d.birth_time = r.birth;
    d.physiological_age = r.physiological_age;
    d.order = item.order;
    d.length = 0.0;
    const NodeId node = tree.add_node(item.parent, d);
    // Pushed in reverse so the successor is expanded first, then laterals in their order.
    const auto ax = axillaries(item.record);
    for (std::size_t k = ax.size(); k-- > 0;) {
      if (records_[ax[k]].birth <= max_birth) {
        stack.push_back({ax[k], node, static_cast<std::uint16_t>(item.order + 1)});
      }
    }
    if (r.successor != kNoRecord && records_[r.successor].birth <= max_birth) {
      stack.push_back({r.successor, node, item.order});
    }
  }
  return tree;
}

bool CtreeGeometry::operator==(const CtreeGeometry& other) const {
  if (records.size() != other.records.size() || placements.size() != other.placements.size() ||
      axillary_placements != other.axillary_placements || attributes != other.attributes) {
    return false;
  }
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& a = records[i];
    const auto& b = other.records[i];
    if (a.group != b.group || a.kind != b.kind || a.order != b.order || a.start != b.start ||
        a.end != b.end || a.direction != b.direction || a.length != b.length ||
        a.radius != b.radius) {
      return false;
    }
  }
  for (std::size_t i = 0; i < placements.size(); ++i) {
    const auto& a = placements[i];
    const auto& b = other.placements[i];
    if (a.rotation != b.rotation || a.translation != b.translation || a.order != b.order) {
      return false;
    }
  }
  return true;
}

bool CompressedTreeGraph::operator==(const CompressedTreeGraph& other) const {
  if (geometry != other.geometry) return false;
  if (records_.size() != other.records_.size() || axillary_refs_ != other.axillary_refs_ ||
      root_ != other.root_ || metadata != other.metadata ||
      std::bit_cast<std::uint64_t>(final_age) != std::bit_cast<std::uint64_t>(other.final_age) ||
      std::bit_cast<std::uint64_t>(birth_date) != std::bit_cast<std::uint64_t>(other.birth_date)) {
    return false;
  }
  for (std::size_t i = 0; i < records_.size(); ++i) {
    const auto& a = records_[i];
    const auto& b = other.records_[i];
    if (a.successor != b.successor || a.axillary_begin != b.axillary_begin ||
        a.axillary_count != b.axillary_count || a.physiological_age != b.physiological_age ||
        a.apex != b.apex || a.birth != b.birth || a.pith_volume != b.pith_volume ||
        a.ring_volume != b.ring_volume || a.leaf_volume != b.leaf_volume ||
        a.multiplicity != b.multiplicity) {
      return false;
    }
  }
  return true;
}

namespace {

constexpr std::size_t kPlacementBytes = 13 * 8;
constexpr std::size_t kRecordGeometryBytes = 4 + 11 * 8;

void put_vector(std::string& out, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) put<double>(out, v[i]);
}

void encode_geometry(std::string& out, const CtreeGeometry& g) {
  put<std::uint32_t>(out, static_cast<std::uint32_t>(g.placements.size()));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(g.attributes.size()));
  for (const Placement& p : g.placements) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) put<double>(out, p.rotation(r, c));
    }
    put_vector(out, p.translation);
    put<double>(out, p.order);
  }
  for (const RecordGeometry& r : g.records) {
    put<std::uint8_t>(out, r.group ? kGroupKind : static_cast<std::uint8_t>(r.kind));
    put<std::uint8_t>(out, 0);
    put<std::uint16_t>(out, r.order);
    put_vector(out, r.start);
    put_vector(out, r.end);
    put_vector(out, r.direction);
    put<double>(out, r.length);
    put<double>(out, r.radius);
  }
  for (std::uint32_t p : g.axillary_placements) put<std::uint32_t>(out, p);
  for (const auto& [name, column] : g.attributes) {
    put<std::uint16_t>(out, static_cast<std::uint16_t>(name.size()));
    put_bytes(out, name.data(), name.size());
    for (double v : column) put<double>(out, v);
  }
}

}  // namespace

std::string encode_ctree(const CompressedTreeGraph& graph) {
  std::string out;
  out.reserve(48 + graph.size() * 52 + graph.axillary_refs().size() * 4);
  put_bytes(out, kMagic, sizeof(kMagic));
  put<std::uint32_t>(out, graph.has_geometry() ? kGeometryVersion : kVersion);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(graph.size()));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(graph.axillary_refs().size()));
  put<std::uint32_t>(out, graph.root());
  put<double>(out, graph.final_age);
  put<double>(out, graph.birth_date);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(graph.metadata.size()));
  for (const auto& [key, value] : graph.metadata) {
    put<std::uint16_t>(out, static_cast<std::uint16_t>(key.size()));
    put_bytes(out, key.data(), key.size());
    put<double>(out, value);
  }
  for (const auto& r : graph.records()) {
    put<std::uint32_t>(out, r.successor);
    put<std::uint32_t>(out, r.axillary_count);
    put<std::uint16_t>(out, r.physiological_age);
    put<std::uint8_t>(out, static_cast<std::uint8_t>(r.apex));
    put<std::uint8_t>(out, 0);
    put<double>(out, r.birth);
    put<double>(out, r.pith_volume);
    put<double>(out, r.ring_volume);
    put<double>(out, r.leaf_volume);
    put<std::uint64_t>(out, r.multiplicity);
  }
  for (RecordId a : graph.axillary_refs()) put<std::uint32_t>(out, a);
  if (graph.has_geometry()) encode_geometry(out, graph.geometry);
  return out;
}

namespace {

// Ages and dates of a plant in growth cycles: anything beyond this is a damaged header.
constexpr double kMaxCtreeAge = 1e6;

std::string number_text(double value) {
  std::string out;
  append_number(out, value);
  return out;
}

Eigen::Vector3d get_vector(Reader& in, const char* what) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = in.get<double>(what);
  if (!v.allFinite()) in.fail(std::string(what) + " is nan or infinite, expected finite numbers");
  return v;
}

double get_finite(Reader& in, const char* what) {
  const double v = in.get<double>(what);
  if (!std::isfinite(v))
    in.fail(std::string(what) + " is nan or infinite, expected a finite number");
  return v;
}

// The geometry section of a version 2 file, after the axillary references.
CtreeGeometry decode_geometry(Reader& in, std::uint32_t n, std::uint32_t n_refs) {
  CtreeGeometry g;
  const auto n_placements = in.get<std::uint32_t>("the placement count");
  const auto n_attributes = in.get<std::uint32_t>("the attribute count");
  const std::uint64_t fixed = static_cast<std::uint64_t>(n_placements) * kPlacementBytes +
                              static_cast<std::uint64_t>(n) * kRecordGeometryBytes +
                              static_cast<std::uint64_t>(n_refs) * 4;
  if (in.remaining() < fixed) {
    in.fail("truncated .ctree geometry: expected " + std::to_string(n_placements) +
            " placements and the geometry of " + std::to_string(n) + " records");
  }
  g.placements.resize(n_placements);
  for (Placement& p : g.placements) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) p.rotation(r, c) = get_finite(in, "a placement rotation");
    }
    p.translation = get_vector(in, "a placement translation");
    p.order = get_finite(in, "a placement order");
    // Rigid transforms only: anything else would shear the substructures it places.
    if (!(p.rotation.transpose() * p.rotation).isApprox(Eigen::Matrix3d::Identity(), 1e-6)) {
      in.fail("a placement rotation is not orthonormal");
    }
  }
  g.records.resize(n);
  for (RecordGeometry& r : g.records) {
    const auto kind = in.get<std::uint8_t>("an organ kind");
    if (kind != kGroupKind && kind > static_cast<std::uint8_t>(OrganKind::kBud)) {
      in.fail("invalid organ kind " + std::to_string(kind) +
              " (expected 0..3, or 255 for a group)");
    }
    r.group = kind == kGroupKind;
    r.kind = r.group ? OrganKind::kInternode : static_cast<OrganKind>(kind);
    (void)in.get<std::uint8_t>("a reserved byte");
    r.order = in.get<std::uint16_t>("an order");
    r.start = get_vector(in, "a start point");
    r.end = get_vector(in, "an end point");
    r.direction = get_vector(in, "a direction");
    r.length = get_finite(in, "a length");
    r.radius = get_finite(in, "a radius");
  }
  g.axillary_placements.resize(n_refs);
  for (auto& p : g.axillary_placements) p = in.get<std::uint32_t>("a placement index");
  for (std::uint32_t i = 0; i < n_attributes; ++i) {
    const auto len = in.get<std::uint16_t>("an attribute name length");
    std::string name(in.take(len, "an attribute name"));
    if (in.remaining() < static_cast<std::uint64_t>(n) * 8) {
      in.fail("truncated .ctree geometry: expected the values of attribute '" + name + "'");
    }
    auto& column = g.attributes[name];
    column.resize(n);
    for (double& v : column) v = get_finite(in, "an attribute value");
  }
  if (in.remaining() != 0) in.fail("unexpected bytes after the geometry");
  return g;
}

// The fixed header after the magic.
struct CtreeHeader {
  std::uint32_t version = 0;
  std::uint32_t n = 0;       // records
  std::uint32_t n_refs = 0;  // axillary references
  std::uint32_t root = 0;
};

// Reads the version, counts and root into the header, the ages and metadata into g.
CtreeHeader decode_header(Reader& in, CompressedTreeGraph& g, const std::string& source_name) {
  if (in.take(sizeof(kMagic), "the magic FSPMCTRE") != std::string_view(kMagic, sizeof(kMagic))) {
    throw ParseError("not a .ctree file (magic FSPMCTRE expected)", source_name);
  }
  CtreeHeader h;
  h.version = in.get<std::uint32_t>("the version");
  if (h.version != kVersion && h.version != kGeometryVersion) {
    throw ParseError("unsupported .ctree version " + std::to_string(h.version) + " (expected " +
                         std::to_string(kVersion) + " or " + std::to_string(kGeometryVersion) + ")",
                     source_name);
  }
  h.n = in.get<std::uint32_t>("the record count");
  h.n_refs = in.get<std::uint32_t>("the axillary count");
  h.root = in.get<std::uint32_t>("the root");
  g.final_age = in.get<double>("the final age");
  g.birth_date = in.get<double>("the birth date");
  if (!(g.final_age >= 0.0 && g.final_age <= kMaxCtreeAge)) {
    in.fail("the final age " + number_text(g.final_age) +
            " is out of range: expected a finite age in [0, " + number_text(kMaxCtreeAge) + "]");
  }
  if (!(std::abs(g.birth_date) <= kMaxCtreeAge)) {
    in.fail("the birth date " + number_text(g.birth_date) +
            " is out of range: expected a finite date");
  }
  const auto n_meta = in.get<std::uint32_t>("the metadata count");
  for (std::uint32_t i = 0; i < n_meta; ++i) {
    const auto len = in.get<std::uint16_t>("a metadata key length");
    std::string key(in.take(len, "a metadata key"));
    g.metadata[key] = in.get<double>("a metadata value");
  }
  return h;
}

// The record table (52 bytes a record), after checking that the rest of the input can hold it
// and the axillary references; each record's axillary range follows from the counts before it.
std::vector<CompressedRecord> decode_records(Reader& in, const CtreeHeader& h) {
  const std::uint64_t table_bytes =
      static_cast<std::uint64_t>(h.n) * 52 + static_cast<std::uint64_t>(h.n_refs) * 4;
  if (h.version == kVersion ? in.remaining() != table_bytes : in.remaining() < table_bytes + 8) {
    in.fail("size does not match " + std::to_string(h.n) + " records and " +
            std::to_string(h.n_refs) + " axillary references");
  }
  std::vector<CompressedRecord> records(h.n);
  std::uint64_t begin = 0;
  for (auto& r : records) {
    r.successor = in.get<std::uint32_t>("a successor");
    r.axillary_count = in.get<std::uint32_t>("an axillary count");
    r.axillary_begin = static_cast<std::uint32_t>(begin);
    begin += r.axillary_count;
    r.physiological_age = in.get<std::uint16_t>("a physiological age");
    const auto apex = in.get<std::uint8_t>("an apex state");
    if (apex > 2) in.fail("invalid apex state " + std::to_string(apex));
    r.apex = static_cast<ApexState>(apex);
    (void)in.get<std::uint8_t>("a reserved byte");
    r.birth = in.get<double>("a birth date");
    r.pith_volume = in.get<double>("a pith volume");
    r.ring_volume = in.get<double>("a ring volume");
    r.leaf_volume = in.get<double>("a leaf volume");
    r.multiplicity = in.get<std::uint64_t>("a multiplicity");
    if (!std::isfinite(r.birth) || !std::isfinite(r.pith_volume) || !std::isfinite(r.ring_volume) ||
        !std::isfinite(r.leaf_volume)) {
      in.fail("a record's birth date or volume is nan or infinite, expected finite numbers");
    }
  }
  if (begin != h.n_refs) in.fail("axillary counts do not add up to the reference count");
  return records;
}

// The stored multiplicities must be the ones the graph gives (a corrupt file could claim any).
void check_stored_multiplicities(const CompressedTreeGraph& g,
                                 const std::vector<CompressedRecord>& records,
                                 const std::string& source_name) {
  CompressedTreeGraph check = g;
  try {
    check.compute_multiplicities();
  } catch (const ValueError& e) {
    throw ParseError(e.message(), source_name);
  }
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (check.record(static_cast<RecordId>(i)).multiplicity != records[i].multiplicity) {
      throw ParseError("record " + std::to_string(i) + " stores multiplicity " +
                           std::to_string(records[i].multiplicity) + " but the graph gives " +
                           std::to_string(check.record(static_cast<RecordId>(i)).multiplicity),
                       source_name);
    }
  }
}

}  // namespace

CompressedTreeGraph decode_ctree(std::string_view bytes, const std::string& source_name) {
  Reader in(bytes, source_name);
  CompressedTreeGraph g;
  const CtreeHeader h = decode_header(in, g, source_name);
  const std::vector<CompressedRecord> records = decode_records(in, h);
  std::vector<RecordId> refs(h.n_refs);
  for (auto& a : refs) a = in.get<std::uint32_t>("an axillary reference");
  if (h.version == kGeometryVersion) g.geometry = decode_geometry(in, h.n, h.n_refs);
  for (const auto& r : records) {
    const auto ax = std::span<const RecordId>(refs).subspan(r.axillary_begin, r.axillary_count);
    g.add_record(r, ax);
  }
  g.set_root(h.root);
  check_stored_multiplicities(g, records, source_name);
  return g;
}

void write_ctree_file(const CompressedTreeGraph& graph, const std::string& path) {
  const std::string bytes = encode_ctree(graph);
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      },
      true);
}

CompressedTreeGraph read_ctree_file(const std::string& path) {
  return decode_ctree(read_input_file(path), path);
}

}  // namespace fspm
