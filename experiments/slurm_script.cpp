#include "experiments/slurm_script.hpp"

#include <fmt/format.h>

#include "experiments/shell_text.hpp"
#include "fspm/error.hpp"

namespace fspm::experiments {

void SlurmOptions::validate() const {
  if (shards == 0) throw ValueError("slurm: shards (--shards) must be at least 1");
  if (cpus_per_task == 0) throw ValueError("slurm: cpus_per_task (--jobs) must be at least 1");
  // sbatch reads its directives up to the line's end and honours only double quotes; the
  // comments name the script and the folder, so neither may break a line.
  for (const auto& [option, path] :
       {std::pair<const char*, const std::string&>{"out_dir (--out)", out_dir},
        {"script_path (--slurm-file)", script_path}}) {
    if (path.find_first_of("\"\n\r") != std::string::npos) {
      throw ValueError("slurm: " + std::string(option) +
                       ": a Slurm script cannot name a path with a double quote or a line break "
                       "in it, got '" +
                       path + "'");
    }
  }
}

std::string slurm_script(const SlurmOptions& o) {
  o.validate();
  return fmt::format(
      "#!/bin/bash\n"
      "# Written by `fspm run --emit-slurm`: runs the experiment as {shards} shards, one Slurm\n"
      "# array task each. Submit with `sbatch {script}`; a task that is requeued or resubmitted\n"
      "# resumes its shard (--resume). When all tasks are done, combine the shards with\n"
      "#   {fspm} results merge {out}/merged {out}/shard-*\n"
      "#SBATCH --job-name={name}\n"
      "#SBATCH --array=0-{last}\n"
      "#SBATCH --cpus-per-task={cpus}\n"
      "#SBATCH --ntasks=1\n"
      "#SBATCH --time={time}\n"
      "#SBATCH --output=\"{out_raw}/slurm-%A_%a.out\"\n"
      "set -euo pipefail\n"
      "shard=\"${{SLURM_ARRAY_TASK_ID:?run this script with sbatch}}\"\n"
      "exec {fspm} run {experiment} --jobs \"${{SLURM_CPUS_PER_TASK:-{cpus}}}\" \\\n"
      "  --out {out}/shard-\"$shard\" --shard \"$shard\"/{shards} --resume\n",
      fmt::arg("shards", o.shards), fmt::arg("script", shell_quote(o.script_path)),
      fmt::arg("fspm", shell_quote(o.fspm_executable)), fmt::arg("out", shell_quote(o.out_dir)),
      fmt::arg("out_raw", o.out_dir), fmt::arg("name", file_stem_from_name(o.job_name)),
      fmt::arg("last", o.shards - 1), fmt::arg("cpus", o.cpus_per_task),
      fmt::arg("time", o.time_limit), fmt::arg("experiment", shell_quote(o.experiment_file)));
}

}  // namespace fspm::experiments
