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

bool CompressedTreeGraph::operator==(const CompressedTreeGraph& other) const {
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

std::string encode_ctree(const CompressedTreeGraph& graph) {
  std::string out;
  out.reserve(48 + graph.size() * 52 + graph.axillary_refs().size() * 4);
  put_bytes(out, kMagic, sizeof(kMagic));
  put<std::uint32_t>(out, kVersion);
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

}  // namespace

CompressedTreeGraph decode_ctree(std::string_view bytes, const std::string& source_name) {
  Reader in(bytes, source_name);
  if (in.take(sizeof(kMagic), "the magic FSPMCTRE") != std::string_view(kMagic, sizeof(kMagic))) {
    throw ParseError("not a .ctree file (magic FSPMCTRE expected)", source_name);
  }
  const auto version = in.get<std::uint32_t>("the version");
  if (version != kVersion) {
    throw ParseError("unsupported .ctree version " + std::to_string(version) + " (expected " +
                         std::to_string(kVersion) + ")",
                     source_name);
  }
  const auto n = in.get<std::uint32_t>("the record count");
  const auto n_refs = in.get<std::uint32_t>("the axillary count");
  const auto root = in.get<std::uint32_t>("the root");
  CompressedTreeGraph g;
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
  if (in.remaining() !=
      static_cast<std::uint64_t>(n) * 52 + static_cast<std::uint64_t>(n_refs) * 4) {
    in.fail("size does not match " + std::to_string(n) + " records and " + std::to_string(n_refs) +
            " axillary references");
  }
  std::vector<CompressedRecord> records(n);
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
  if (begin != n_refs) in.fail("axillary counts do not add up to the reference count");
  std::vector<RecordId> refs(n_refs);
  for (auto& a : refs) a = in.get<std::uint32_t>("an axillary reference");
  for (const auto& r : records) {
    const auto ax = std::span<const RecordId>(refs).subspan(r.axillary_begin, r.axillary_count);
    g.add_record(r, ax);
  }
  g.set_root(root);
  CompressedTreeGraph check = g;
  try {
    check.compute_multiplicities();
  } catch (const ValueError& e) {
    throw ParseError(e.message(), source_name);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (check.record(static_cast<RecordId>(i)).multiplicity != records[i].multiplicity) {
      throw ParseError("record " + std::to_string(i) + " stores multiplicity " +
                           std::to_string(records[i].multiplicity) + " but the graph gives " +
                           std::to_string(check.record(static_cast<RecordId>(i)).multiplicity),
                       source_name);
    }
  }
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
