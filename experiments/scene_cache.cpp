#include "experiments/scene_cache.hpp"

#include <filesystem>

#include "environment/scene_file.hpp"

namespace fspm::experiments {

std::string SceneCache::resolve(const std::string& path) const {
  std::filesystem::path p(path);
  if (p.is_relative()) p = std::filesystem::path(base_dir_) / p;
  return p.lexically_normal().string();
}

const environment::Scene& SceneCache::get(const std::string& resolved_path) const {
  const std::lock_guard lock(mutex_);
  auto it = scenes_.find(resolved_path);
  if (it == scenes_.end()) {
    it = scenes_.emplace(resolved_path, environment::read_scene_file(resolved_path)).first;
  }
  return it->second;
}

}  // namespace fspm::experiments
