#include "lsystem/module_string.hpp"

#include <cstdio>
#include <limits>

#include "fspm/error.hpp"

namespace fspm::lsystem {

SymbolTable::SymbolTable() {
  intern("[");
  intern("]");
  intern("%");
}

SymbolId SymbolTable::intern(const std::string& name) {
  auto it = ids_.find(name);
  if (it != ids_.end()) return it->second;
  if (names_.size() >= std::numeric_limits<SymbolId>::max()) {
    throw ValueError("too many distinct module names (more than 65535)");
  }
  const auto id = static_cast<SymbolId>(names_.size());
  names_.push_back(name);
  ids_.emplace(name, id);
  return id;
}

int SymbolTable::find(const std::string& name) const {
  auto it = ids_.find(name);
  return it == ids_.end() ? -1 : it->second;
}

void ModuleString::clear() {
  symbols_.clear();
  params_.clear();
  if (!offsets_.empty()) offsets_.assign(1, 0);
}

void ModuleString::reserve(std::size_t modules, std::size_t parameters) {
  symbols_.reserve(modules);
  if (!offsets_.empty()) offsets_.reserve(modules + 1);
  params_.reserve(parameters);
}

void ModuleString::make_parametric() {
  if (!offsets_.empty()) return;
  offsets_.assign(symbols_.size() + 1, 0);
}

void ModuleString::push_back(SymbolId s, std::span<const double> params) {
  if (!params.empty() && offsets_.empty()) make_parametric();
  symbols_.push_back(s);
  if (!offsets_.empty()) {
    params_.insert(params_.end(), params.begin(), params.end());
    if (params_.size() > std::numeric_limits<std::uint32_t>::max()) {
      throw ValueError("more than 4294967295 parameters in the string");
    }
    offsets_.push_back(static_cast<std::uint32_t>(params_.size()));
  }
}

void ModuleString::set_parameters(std::size_t i, std::span<const double> params) {
  if (offsets_.empty()) {
    if (params.empty()) return;
    make_parametric();
  }
  const std::size_t old = arity(i);
  if (old == params.size()) {
    std::copy(params.begin(), params.end(), params_.begin() + offsets_[i]);
    return;
  }
  params_.erase(params_.begin() + offsets_[i], params_.begin() + offsets_[i + 1]);
  params_.insert(params_.begin() + offsets_[i], params.begin(), params.end());
  const auto delta = static_cast<std::int64_t>(params.size()) - static_cast<std::int64_t>(old);
  for (std::size_t k = i + 1; k < offsets_.size(); ++k) {
    offsets_[k] = static_cast<std::uint32_t>(offsets_[k] + delta);
  }
}

void ModuleString::swap(ModuleString& other) noexcept {
  symbols_.swap(other.symbols_);
  offsets_.swap(other.offsets_);
  params_.swap(other.params_);
}

std::size_t ModuleString::memory_bytes() const {
  return symbols_.capacity() * sizeof(SymbolId) + offsets_.capacity() * sizeof(std::uint32_t) +
         params_.capacity() * sizeof(double);
}

std::string to_string(const ModuleString& s, const SymbolTable& symbols) {
  std::string out;
  out.reserve(s.size() * 2);
  for (std::size_t i = 0; i < s.size(); ++i) {
    out += symbols.name(s.symbol(i));
    const auto params = s.parameters(i);
    if (params.empty()) continue;
    out += '(';
    for (std::size_t k = 0; k < params.size(); ++k) {
      if (k) out += ',';
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%g", params[k]);
      out += buffer;
    }
    out += ')';
  }
  return out;
}

}  // namespace fspm::lsystem
