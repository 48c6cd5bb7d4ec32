#include "experiments/run_files.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <mutex>
#include <set>
#include <sstream>

#include "experiments/model_factory.hpp"
#include "experiments/results_db.hpp"
#include "experiments/runner.hpp"
#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "test_files.hpp"

namespace fspm::experiments {
namespace {

namespace fs = std::filesystem;

Experiment synthetic(const std::string& body) {
  return parse_experiment(
      "[experiment]\nname = \"k\"\nseed = 3\nreplicates = 2\n[model]\nkind = \"synthetic\"\n" +
          body,
      "k.toml");
}

// Stands in for the graphics writers: writes the tree's node count, atomically, and remembers
// which runs it was called for.
struct FakeWriter {
  std::string extension;
  std::shared_ptr<std::mutex> mutex = std::make_shared<std::mutex>();
  std::shared_ptr<std::set<std::size_t>> runs = std::make_shared<std::set<std::size_t>>();

  std::string operator()(const TreeGraph& tree, std::size_t run, const std::string& out_dir) const {
    const std::string rel = run_file_path(run, extension);
    write_file_atomically((fs::path(out_dir) / rel).string(),
                          [&](std::ostream& out) { out << tree.size() << '\n'; });
    const std::lock_guard lock(*mutex);
    runs->insert(run);
    return rel;
  }
};

RunnerSummary run(const Experiment& x, const fs::path& out, const RunFileWriters& writers) {
  const auto model = make_model(x);
  RunnerOptions o;
  o.out_dir = out.string();
  o.jobs = 2;
  o.file_writers = writers;
  return run_experiment(x, *model, o);
}

TEST(RunFiles, PathNamesTheRunWithSevenDigits) {
  EXPECT_EQ(run_file_path(42, "glb"), "runs/run-0000042.glb");
  EXPECT_EQ(run_file_path(1234567, "png"), "runs/run-1234567.png");
}

TEST(RunFiles, KeptMeshesAndImagesAreWrittenByTheWritersAndRecorded) {
  const auto dir = testing::scratch("keep_files");
  const Experiment x = synthetic(
      "[sweep]\nnodes = [2, 5, 9]\n[outputs]\nmetrics = [\"nodes\"]\n"
      "keep = [\"tree\", \"mesh\", \"image\"]\n");
  const FakeWriter mesh{"mesh.txt"};
  const FakeWriter image{"image.txt"};
  const RunnerSummary s = run(x, dir / "out", {{KeptFile::kMesh, mesh}, {KeptFile::kImage, image}});
  EXPECT_EQ(s.ok, 6u);
  EXPECT_EQ(mesh.runs->size(), 6u);
  EXPECT_EQ(image.runs->size(), 6u);
  const auto rows = ResultsDb((dir / "out").string(), ResultsDb::Mode::kRead).read_all();
  ASSERT_EQ(rows.size(), 6u);
  for (const RunRecord& r : rows) {
    // In outputs.keep order, relative to the output directory.
    const std::vector<std::string> expected = {run_file_path(r.run, "tree"),
                                               run_file_path(r.run, "mesh.txt"),
                                               run_file_path(r.run, "image.txt")};
    ASSERT_EQ(r.files, expected);
    // The writer got the run's own tree: a chain of `nodes` internodes (2, 5, 9 by point).
    const std::size_t nodes = std::vector<std::size_t>{2, 5, 9}[r.point];
    for (std::size_t f = 1; f < 3; ++f) {
      std::ifstream in(dir / "out" / r.files[f]);
      std::size_t written = 0;
      in >> written;
      EXPECT_EQ(written, nodes) << r.files[f];
    }
  }
}

TEST(RunFiles, AKeptKindWithoutAWriterStopsBeforeAnyRun) {
  const auto dir = testing::scratch("keep_missing");
  const Experiment x =
      synthetic("[sweep]\nnodes = [2, 5]\n[outputs]\nkeep = [\"tree\", \"image\"]\n");
  try {
    run(x, dir / "out", {{KeptFile::kMesh, FakeWriter{"glb"}}});
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.line(), 10);  // the keep line
    EXPECT_NE(std::string(e.what()).find("outputs.keep: 'image'"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "out" / kDatabaseFile));  // nothing was started
}

TEST(RunFiles, AFailingWriterMakesTheRunAnErrorAndTheSweepGoesOn) {
  const auto dir = testing::scratch("keep_fail");
  const Experiment x = synthetic("[sweep]\nnodes = [2, 5]\n[outputs]\nkeep = [\"mesh\"]\n");
  const RunFileWriter failing = [](const TreeGraph& tree, std::size_t run,
                                   const std::string&) -> std::string {
    if (tree.size() == 5) throw IoError("disk full");
    return run_file_path(run, "glb");
  };
  const RunnerSummary s = run(x, dir / "out", {{KeptFile::kMesh, failing}});
  EXPECT_EQ(s.ok, 2u);
  EXPECT_EQ(s.failed, 2u);
  const auto rows = ResultsDb((dir / "out").string(), ResultsDb::Mode::kRead).read_all();
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].status, RunStatus::kOk);
  EXPECT_EQ(rows[3].status, RunStatus::kError);
  EXPECT_NE(rows[3].error.find("keeping the run's mesh"), std::string::npos) << rows[3].error;
  EXPECT_NE(rows[3].error.find("disk full"), std::string::npos) << rows[3].error;
}

TEST(RunFiles, KeepAcceptsTreeMeshImageOnce) {
  EXPECT_NO_THROW(synthetic("[outputs]\nkeep = [\"mesh\", \"image\"]\n"));
  EXPECT_THROW(synthetic("[outputs]\nkeep = [\"video\"]\n"), ValueError);
  EXPECT_THROW(synthetic("[outputs]\nkeep = [\"mesh\", \"mesh\"]\n"), ValueError);
}

TEST(RunFiles, MeshFormatImageSizeAndView) {
  const Experiment defaults = synthetic("");
  EXPECT_EQ(defaults.mesh_format, MeshFormat::kGlb);
  EXPECT_EQ(defaults.image_width, 640);
  EXPECT_EQ(defaults.image_height, 480);
  EXPECT_EQ(defaults.image_view, View::kFront);
  const Experiment x = synthetic(
      "[outputs]\nmesh_format = \"ply\"\nimage_size = \"160x90\"\nimage_view = \"iso\"\n");
  EXPECT_EQ(x.mesh_format, MeshFormat::kPly);
  EXPECT_EQ(x.image_width, 160);
  EXPECT_EQ(x.image_height, 90);
  EXPECT_EQ(x.image_view, View::kIso);
  for (const char* bad :
       {"mesh_format = \"obj\"", "image_size = \"160\"", "image_size = \"0x90\"",
        "image_size = \"160x90x2\"", "image_size = \"20000x10\"", "image_view = \"below\""}) {
    try {
      synthetic(std::string("[outputs]\n") + bad + "\n");
      ADD_FAILURE() << "no error for " << bad;
    } catch (const ValueError& e) {
      EXPECT_EQ(e.line(), 8) << e.what();
      EXPECT_NE(std::string(e.what()).find("outputs."), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace fspm::experiments
