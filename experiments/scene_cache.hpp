#pragma once
// Scene files of an experiment's runs: relative paths are resolved against the experiment file's
// folder and every file is parsed once; runs on any thread share the parsed scenes read-only.
#include <map>
#include <mutex>
#include <string>

#include "environment/scene.hpp"

namespace fspm::experiments {

class SceneCache {
 public:
  explicit SceneCache(std::string base_dir) : base_dir_(std::move(base_dir)) {}
  // `path` relative to the base folder (or absolute), normalised.
  std::string resolve(const std::string& path) const;
  // The parsed scene of a resolved path; throws the scene reader's errors (IoError, ParseError).
  const environment::Scene& get(const std::string& resolved_path) const;

 private:
  std::string base_dir_;
  mutable std::mutex mutex_;
  mutable std::map<std::string, environment::Scene> scenes_;
};

}  // namespace fspm::experiments
