#include "cli/html_report_trees.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "cli/base64.hpp"
#include "cli/gzip.hpp"
#include "cli/run_scene_mesh.hpp"
#include "experiments/render_selection.hpp"
#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "graphics/mesh_writers.hpp"

namespace fspm::cli {
namespace {

namespace fs = std::filesystem;
namespace ex = fspm::experiments;
using nlohmann::json;

// A lighter mesh than kept meshes and renders, so that a report with a few dozen trees stays a
// few megabytes: coarser rings (3 to 6 sides, edges up to 5 cm), no caps, and 4 larger leaves
// per leaf cluster instead of 32 (about the same leaf area seen from afar).
graphics::MeshOptions web_mesh_options() {
  graphics::MeshOptions options;
  options.leaves = true;
  options.edge_length_m = 0.05;
  options.max_sides = 6;
  options.caps = false;
  options.foliage.leaves_per_cluster = 4;
  options.foliage.leaf_length_ratio = 0.8;
  return options;
}

// `v` rounded to `bits` bits of mantissa (of a float's 23): trailing zero bits let gzip shrink
// the mesh by a third; 12 bits keep positions to 0.025 % of their size (2.5 mm at 10 m).
float round_mantissa(float v, int bits) {
  const int drop = 23 - bits;
  std::uint32_t u = std::bit_cast<std::uint32_t>(v);
  u = (u + (std::uint32_t{1} << (drop - 1))) & ~((std::uint32_t{1} << drop) - 1);
  const float rounded = std::bit_cast<float>(u);
  return std::isfinite(rounded) ? rounded : v;
}

// Keeps what the page shows: positions, the attributes a reader may colour by (age, order and the
// tree's own, such as light) and the materials. Normals (the page shades flat) and texture
// coordinates go, as do birth_time and physiological_age (age and order say the same); numbers
// are rounded (round_mantissa).
void lighten_for_web(graphics::TriangleMesh& mesh) {
  mesh.normals.clear();
  mesh.uvs.clear();
  std::erase_if(mesh.attributes, [](const graphics::VertexAttribute& a) {
    return a.name == graphics::kAttributeBirthTime ||
           a.name == graphics::kAttributePhysiologicalAge;
  });
  for (Eigen::Vector3f& p : mesh.positions) {
    for (int i = 0; i < 3; ++i) p[i] = round_mantissa(p[i], 12);
  }
  // Colours need even less: 10 bits are 0.1 % of the value.
  for (graphics::VertexAttribute& a : mesh.attributes) {
    for (float& v : a.values) v = round_mantissa(v, 10);
  }
}

// Writes trees/<stem>.js for the run (once) and records it in `out.files`; false with a note when
// the tree cannot be read or meshed.
bool write_tree_script(const ex::Experiment& x, const ex::RunRecord& record, const std::string& dir,
                       const fs::path& report_dir, HtmlTrees& out) {
  const std::string key = std::to_string(record.run);
  if (out.files.contains(key)) return true;
  char stem[32];
  std::snprintf(stem, sizeof stem, "run-%07zu", record.run);
  const fs::path glb = report_dir / "trees" / (std::string(stem) + ".glb");
  try {
    fs::create_directories(glb.parent_path());
    Obstacles obstacles = Obstacles::kNone;
    graphics::TriangleMesh mesh = run_scene_mesh(x, record, dir, web_mesh_options(), obstacles);
    lighten_for_web(mesh);
    graphics::write_glb(mesh, glb.string());
    std::ifstream in(glb, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    fs::remove(glb);
    write_file_atomically((report_dir / "trees" / (std::string(stem) + ".js")).string(),
                          [&](std::ostream& js) {
                            js << "fspmGlb(\"" << stem << "\", \""
                               << base64_encode(gzip_compress(bytes.str())) << "\");\n";
                          });
  } catch (const Error& e) {
    out.notes.push_back("run " + key + " left out: " + e.what());
    return false;
  } catch (const fs::filesystem_error& e) {
    out.notes.push_back("run " + key + " left out: " + e.what());
    return false;
  }
  out.files[key] = stem;
  return true;
}

// Per comparison (in file order), the pair whose distance is the median (the lower middle of an
// even count), all groups pooled.
std::vector<const ex::PairDistance*> median_pairs(const ex::Experiment& x,
                                                  const ex::ComparisonResults& c) {
  std::vector<const ex::PairDistance*> out;
  for (const ex::ComparisonSpec& spec : x.comparisons) {
    std::vector<const ex::PairDistance*> pairs;
    for (const ex::PairDistance& p : c.pairs) {
      if (p.comparison == spec.name) pairs.push_back(&p);
    }
    if (pairs.empty()) continue;
    const auto middle = pairs.begin() + static_cast<std::ptrdiff_t>((pairs.size() - 1) / 2);
    std::nth_element(pairs.begin(), middle, pairs.end(),
                     [](const auto* a, const auto* b) { return a->distance < b->distance; });
    out.push_back(*middle);
  }
  return out;
}

}  // namespace

HtmlTrees write_html_trees(const ex::Experiment& x, const std::vector<ex::RunRecord>& runs,
                           const ex::ComparisonResults* comparisons, const std::string& dir,
                           const fs::path& report_dir) {
  HtmlTrees out;
  std::map<std::size_t, const ex::RunRecord*> by_run;
  for (const ex::RunRecord& r : runs) by_run[r.run] = &r;
  for (const ex::RenderChoice& c : ex::select_renders(x, runs)) {
    if (write_tree_script(x, *by_run.at(c.run), dir, report_dir, out)) {
      out.trees.push_back({{"run", c.run}, {"group", c.group}, {"caption", c.caption}});
    }
  }
  if (comparisons == nullptr) return out;
  for (const ex::PairDistance* p : median_pairs(x, *comparisons)) {
    const auto a = by_run.find(p->run_a);
    const auto b = by_run.find(p->run_b);
    if (a == by_run.end() || b == by_run.end()) continue;
    if (!write_tree_script(x, *a->second, dir, report_dir, out) ||
        !write_tree_script(x, *b->second, dir, report_dir, out)) {
      continue;
    }
    out.pair_views.push_back({{"comparison", p->comparison},
                              {"group", p->group},
                              {"run_a", p->run_a},
                              {"run_b", p->run_b},
                              {"distance", p->distance}});
  }
  return out;
}

}  // namespace fspm::cli
