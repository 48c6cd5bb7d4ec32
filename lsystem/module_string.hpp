#pragma once
// The derived string in a compact form: one 16-bit symbol id per module, and, only when some
// module carries parameters, a 32-bit offset per module into one pool of doubles. A
// non-parametric string costs 2 bytes per module.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace fspm::lsystem {

using SymbolId = std::uint16_t;

// Ids fixed in every symbol table.
inline constexpr SymbolId kOpenBranch = 0;   // [
inline constexpr SymbolId kCloseBranch = 1;  // ]
inline constexpr SymbolId kCut = 2;          // %

class SymbolTable {
 public:
  SymbolTable();
  // Id of `name`, adding it if new. Throws ValueError past 65535 names.
  SymbolId intern(const std::string& name);
  // Id of `name` or -1.
  int find(const std::string& name) const;
  const std::string& name(SymbolId id) const { return names_[id]; }
  std::size_t size() const { return names_.size(); }

 private:
  std::vector<std::string> names_;
  std::unordered_map<std::string, SymbolId> ids_;
};

class ModuleString {
 public:
  std::size_t size() const { return symbols_.size(); }
  bool empty() const { return symbols_.empty(); }
  bool parametric() const { return !offsets_.empty(); }
  SymbolId symbol(std::size_t i) const { return symbols_[i]; }
  std::size_t arity(std::size_t i) const {
    return offsets_.empty() ? 0 : offsets_[i + 1] - offsets_[i];
  }
  std::span<const double> parameters(std::size_t i) const {
    if (offsets_.empty()) return {};
    return {params_.data() + offsets_[i], offsets_[i + 1] - offsets_[i]};
  }
  std::span<double> parameters(std::size_t i) {
    if (offsets_.empty()) return {};
    return {params_.data() + offsets_[i], offsets_[i + 1] - offsets_[i]};
  }

  void clear();
  void reserve(std::size_t modules, std::size_t parameters = 0);
  // Switches to the parametric layout (offsets for every module so far).
  void make_parametric();
  void push_back(SymbolId s) {
    symbols_.push_back(s);
    if (!offsets_.empty()) offsets_.push_back(static_cast<std::uint32_t>(params_.size()));
  }
  void push_back(SymbolId s, std::span<const double> params);
  // Appends module i of `other`.
  void push_back_from(const ModuleString& other, std::size_t i) {
    push_back(other.symbol(i), other.parameters(i));
  }
  // Replaces the parameters of module i (count may change; O(n) when it does).
  void set_parameters(std::size_t i, std::span<const double> params);
  void swap(ModuleString& other) noexcept;
  // Bytes held by the containers (capacity), for memory figures.
  std::size_t memory_bytes() const;

  std::vector<SymbolId>& symbols() { return symbols_; }
  const std::vector<SymbolId>& symbols() const { return symbols_; }
  const std::vector<std::uint32_t>& offsets() const { return offsets_; }
  const std::vector<double>& pool() const { return params_; }

 private:
  std::vector<SymbolId> symbols_;
  std::vector<std::uint32_t> offsets_;  // empty, or size()+1 entries
  std::vector<double> params_;
};

// cpfg's text form: `F(1.25)[+A(0.6868)]` (parameters with up to 6 significant digits).
std::string to_string(const ModuleString& s, const SymbolTable& symbols);

}  // namespace fspm::lsystem
