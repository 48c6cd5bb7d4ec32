#pragma once
// An experiment as described by its TOML file (docs/experiments.md): the model, fixed and swept
// parameters, sampling, replicates, metrics and kept files. Parsing validates everything that can
// be checked without running the model; errors name the key and its line.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/comparison_spec.hpp"
#include "experiments/kept_file.hpp"
#include "experiments/model_kind.hpp"
#include "experiments/parameter_set.hpp"
#include "fspm/image_request.hpp"
#include "fspm/mesh_format.hpp"

namespace fspm::experiments {

// One swept parameter and the values it takes, in file order.
struct SweepAxis {
  std::string name;
  std::vector<ParameterValue> values;
  int line = 0;
};

// The single-mesh formats outputs.mesh_format accepts.
inline constexpr MeshFormat kKeptMeshFormats[] = {MeshFormat::kGlb, MeshFormat::kPly,
                                                  MeshFormat::kVtp};

enum class SamplingMethod { kRandom, kLatinHypercube };

// A parameter drawn by [sampling]: uniform on [low, high], or log-uniform, or uniform on the
// integers low..high.
struct SampledParameter {
  std::string name;
  double low = 0.0;
  double high = 1.0;
  bool log_scale = false;
  bool integer = false;
  int line = 0;
};

struct Sampling {
  SamplingMethod method = SamplingMethod::kRandom;
  std::size_t samples = 0;
  std::uint64_t seed = 0;
  std::vector<SampledParameter> parameters;  // file order
};

struct Experiment {
  std::string path;  // the experiment file ("<string>" when parsed from text)
  std::string text;  // its content, kept to fingerprint the result database
  std::string name;
  std::string description;  // experiment.description: one line, free text
  std::string about;        // report.about: what the experiment asks and what is known (report)
  std::uint64_t seed = 0;
  std::size_t replicates = 1;
  ModelKind model_kind = ModelKind::kSynthetic;
  std::string model_file;      // resolved against the experiment file's directory; may be empty
  std::string model_view;      // lsystem: optional view file, resolved likewise
  std::string model_scene;     // grow: optional scene file (JSON), resolved likewise
  std::string reference_file;  // outputs.reference: tree for the distance_to_reference metric
  DistanceSpec distance;       // [distance]: for comparisons and distance_to_reference
  std::vector<ComparisonSpec> comparisons;
  std::vector<TTestSpec> ttests;
  std::vector<SummaryTableSpec> tables;
  RenderSpec render;         // [report]
  bool report_html = false;  // report.html: fspm report also writes the HTML report
  ParameterSet fixed;
  std::vector<SweepAxis> sweep;
  std::optional<Sampling> sampling;
  std::vector<std::string> metrics;
  std::vector<KeptFile> keep;  // outputs.keep: per-run files to keep, in file order
  int keep_line = 0;
  MeshFormat mesh_format = MeshFormat::kGlb;  // outputs.mesh_format: one of kKeptMeshFormats
  int image_width = 640;  // outputs.image_size "WxH": kept images and report renders
  int image_height = 480;
  View image_view = View::kFront;  // outputs.image_view
  std::optional<double> time_limit_s;
  std::map<std::string, int> parameter_lines;  // line of every fixed, swept or sampled key
  int model_kind_line = 0;
  int model_file_line = 0;

  // Swept names (grid axes, then sampled parameters), as the CSV columns list them.
  std::vector<std::string> swept_names() const;
  std::size_t grid_points() const;  // product of the axis sizes (1 without axes)
  std::size_t points() const;       // grid points x samples
  std::size_t runs() const;         // points x replicates
};

// Throws ParseError for malformed TOML and ValueError for a wrong key, type or range, naming the
// key and its line. A missing model file is an IoError naming the key's line.
Experiment parse_experiment(std::string_view toml_text, const std::string& path = "<string>");
Experiment read_experiment(const std::string& path);

// Replaces the number of replicates (a quick, smaller version of a sweep) and records it in the
// experiment's text, which fingerprints the result database, so a resume must give it again.
void override_replicates(Experiment& experiment, std::size_t replicates);

}  // namespace fspm::experiments
