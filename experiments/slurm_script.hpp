#pragma once
// A Slurm job-array script that runs an experiment as shards (fspm run --shard I/N), one array
// task per shard, each into its own output directory, to be combined by `fspm results merge`.
#include <cstddef>
#include <string>

namespace fspm::experiments {

struct SlurmOptions {
  std::string fspm_executable;  // absolute path of fspm on the cluster
  std::string experiment_file;  // absolute
  std::string out_dir;      // absolute; shards go to out_dir/shard-I, the merge to out_dir/merged
  std::string script_path;  // where the script is written (named in its comment)
  std::string job_name;
  std::size_t shards = 4;
  std::size_t cpus_per_task = 1;
  std::string time_limit = "24:00:00";  // Slurm --time of one array task

  // Throws ValueError naming the field (and its fspm run option): no shard, no CPU, a folder or
  // script path with a double quote or a line break (sbatch cannot read it).
  void validate() const;
};

std::string slurm_script(const SlurmOptions& options);

}  // namespace fspm::experiments
