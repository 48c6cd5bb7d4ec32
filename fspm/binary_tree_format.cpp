#include "fspm/binary_tree_format.hpp"

#include <bit>
#include <cstring>
#include <istream>
#include <ostream>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/finite_geometry.hpp"

namespace fspm {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the .treeb writer stores columns in host order and assumes a little-endian host");

constexpr char kMagic[8] = {'F', 'S', 'P', 'M', 'T', 'R', 'E', 'B'};
constexpr std::uint32_t kMaxNameLength = 4096;

template <typename T>
void put(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}

template <typename T>
void put_array(std::ostream& out, std::span<const T> values) {
  out.write(reinterpret_cast<const char*>(values.data()),
            static_cast<std::streamsize>(values.size_bytes()));
}

class Reader {
 public:
  Reader(std::istream& in, const std::string& source) : in_(in), source_(source) {}

  void read(void* dst, std::size_t bytes, const char* what) {
    in_.read(static_cast<char*>(dst), static_cast<std::streamsize>(bytes));
    if (static_cast<std::size_t>(in_.gcount()) != bytes) {
      throw ParseError("the file is truncated while reading " + std::string(what) +
                           " at byte offset " + std::to_string(offset_ + in_.gcount()),
                       source_);
    }
    offset_ += bytes;
  }

  template <typename T>
  T get(const char* what) {
    T v;
    read(&v, sizeof(T), what);
    return v;
  }

  // Reads `n` values in chunks so a corrupt count fails at the end of the data, not by
  // allocating gigabytes first.
  template <typename T>
  std::vector<T> get_array(std::uint64_t n, const char* what) {
    std::vector<T> v;
    constexpr std::uint64_t kChunk = 1 << 20;
    for (std::uint64_t done = 0; done < n;) {
      const std::uint64_t m = std::min(kChunk, n - done);
      v.resize(done + m);
      read(v.data() + done, m * sizeof(T), what);
      done += m;
    }
    return v;
  }

  // A complete tree followed by more bytes is a damaged or concatenated file.
  void expect_end() {
    if (in_.peek() != std::char_traits<char>::eof()) {
      fail("unexpected data after the end of the tree");
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw ParseError(what + " (byte offset " + std::to_string(offset_) + ")", source_);
  }

 private:
  std::istream& in_;
  const std::string& source_;
  std::uint64_t offset_ = 0;
};

}  // namespace

void write_tree_binary(const TreeGraph& tree, std::ostream& out) {
  out.write(kMagic, sizeof(kMagic));
  put<std::uint32_t>(out, kBinaryTreeFormatVersion);
  put<std::uint32_t>(out, 0);  // flags, reserved
  put<std::uint64_t>(out, tree.size());
  const std::vector<std::string> names = tree.attribute_names();
  put<std::uint32_t>(out, static_cast<std::uint32_t>(names.size()));
  for (const std::string& name : names) {
    put<std::uint32_t>(out, static_cast<std::uint32_t>(name.size()));
    out.write(name.data(), static_cast<std::streamsize>(name.size()));
    put<double>(out, tree.attribute_default(name));
  }
  put_array(out, tree.parents());
  put_array(out, tree.kinds());
  put_array(out, tree.physiological_ages());
  put_array(out, tree.orders());
  put_array(out, tree.starts());
  put_array(out, tree.ends());
  put_array(out, tree.directions());
  put_array(out, tree.lengths());
  put_array(out, tree.radii());
  put_array(out, tree.birth_times());
  for (const std::string& name : names) put_array(out, tree.attribute(name));
}

TreeGraph read_tree_binary(std::istream& in, const std::string& source) {
  Reader r(in, source);
  char magic[8];
  r.read(magic, sizeof(magic), "the header");
  if (std::memcmp(magic, kMagic, sizeof(kMagic)) != 0) {
    r.fail("expected the .treeb magic 'FSPMTREB' (is this a binary tree file?)");
  }
  const auto version = r.get<std::uint32_t>("the version");
  if (version != kBinaryTreeFormatVersion) {
    r.fail("unsupported .treeb version " + std::to_string(version) + ", expected " +
           std::to_string(kBinaryTreeFormatVersion));
  }
  r.get<std::uint32_t>("the flags");
  const auto n = r.get<std::uint64_t>("the node count");
  if (n >= kNoNode) r.fail("node count " + std::to_string(n) + " is too large");
  const auto attr_count = r.get<std::uint32_t>("the attribute count");
  if (attr_count > 65536) r.fail("attribute count " + std::to_string(attr_count) + " is too large");
  std::vector<std::pair<std::string, double>> attrs;
  for (std::uint32_t k = 0; k < attr_count; ++k) {
    const auto len = r.get<std::uint32_t>("an attribute name length");
    if (len == 0 || len > kMaxNameLength) r.fail("attribute name length out of range");
    std::string name(len, '\0');
    r.read(name.data(), len, "an attribute name");
    attrs.emplace_back(std::move(name), r.get<double>("an attribute default"));
  }
  const auto parents = r.get_array<NodeId>(n, "the parent column");
  const auto kinds = r.get_array<std::uint8_t>(n, "the kind column");
  const auto ages = r.get_array<std::uint16_t>(n, "the physiological age column");
  const auto orders = r.get_array<std::uint16_t>(n, "the order column");
  const auto starts = r.get_array<Eigen::Vector3d>(n, "the start column");
  const auto ends = r.get_array<Eigen::Vector3d>(n, "the end column");
  const auto dirs = r.get_array<Eigen::Vector3d>(n, "the direction column");
  const auto lengths = r.get_array<double>(n, "the length column");
  const auto radii = r.get_array<double>(n, "the radius column");
  const auto births = r.get_array<double>(n, "the birth time column");

  TreeGraph tree;
  for (const auto& [name, def] : attrs) {
    if (tree.has_attribute(name)) r.fail("attribute '" + name + "' appears twice");
    tree.add_attribute(name, def);
  }
  tree.reserve(n);
  for (std::uint64_t i = 0; i < n; ++i) {
    const NodeId p = parents[i];
    if (i == 0 ? p != kNoNode : p >= i) {
      r.fail("node " + std::to_string(i) + " has parent " + std::to_string(p) +
             ", expected a smaller id (or none for node 0)");
    }
    if (kinds[i] > static_cast<std::uint8_t>(OrganKind::kBud)) {
      r.fail("node " + std::to_string(i) + " has unknown organ kind " + std::to_string(kinds[i]));
    }
    NodeData d;
    d.start = starts[i];
    d.end = ends[i];
    d.kind = static_cast<OrganKind>(kinds[i]);
    d.physiological_age = ages[i];
    d.order = orders[i];
    d.radius = radii[i];
    d.birth_time = births[i];
    const NodeId id = tree.add_node(p, d);
    tree.set_length(id, lengths[i]);
    tree.set_direction(id, dirs[i]);
    if (const char* field = non_finite_geometry(tree, id)) {
      r.fail("node " + std::to_string(i) + ": its " + field +
             " is nan or infinite, expected finite geometry");
    }
  }
  for (const auto& [name, def] : attrs) {
    const auto values = r.get_array<double>(n, "an attribute column");
    std::copy(values.begin(), values.end(), tree.attribute(name).begin());
  }
  r.expect_end();
  return tree;
}

}  // namespace fspm
