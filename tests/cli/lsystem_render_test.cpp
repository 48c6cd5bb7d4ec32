// Every example L-system rendered from the front, leaves included, must look like a plant as ABOP
// draws it: thin axes, a trunk a small fraction of the plant's height, mostly sky inside its
// bounding box.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "graphics/image.hpp"
#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

// The background is a vertical gradient: a pixel is foreground when it differs from the first
// pixel of its row (the renderer frames the plant with a margin, so column 0 is sky).
std::vector<char> foreground_mask(const graphics::Image& image) {
  std::vector<char> mask(static_cast<std::size_t>(image.width) * image.height, 0);
  for (int y = 0; y < image.height; ++y) {
    const auto* sky = image.pixel(0, y);
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      const int d = std::abs(p[0] - sky[0]) + std::abs(p[1] - sky[1]) + std::abs(p[2] - sky[2]);
      mask[static_cast<std::size_t>(y) * image.width + x] = d > 24 ? 1 : 0;
    }
  }
  return mask;
}

struct Silhouette {
  int left = 0, right = -1, top = 0, bottom = -1;  // bounding box of the foreground, inclusive
  std::size_t pixels = 0;
  int trunk_px = 0;  // widest run of foreground pixels in the three lowest rows
  int height() const { return bottom - top + 1; }
  int width() const { return right - left + 1; }
};

Silhouette silhouette(const graphics::Image& image) {
  const std::vector<char> mask = foreground_mask(image);
  Silhouette s;
  s.left = image.width;
  s.top = image.height;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!mask[static_cast<std::size_t>(y) * image.width + x]) continue;
      ++s.pixels;
      s.left = std::min(s.left, x);
      s.right = std::max(s.right, x);
      s.top = std::min(s.top, y);
      s.bottom = std::max(s.bottom, y);
    }
  }
  for (int y = std::max(s.top, s.bottom - 2); y <= s.bottom; ++y) {
    int run = 0;
    for (int x = 0; x < image.width; ++x) {
      run = mask[static_cast<std::size_t>(y) * image.width + x] ? run + 1 : 0;
      s.trunk_px = std::max(s.trunk_px, run);
    }
  }
  return s;
}

TEST(LsystemRender, EveryExampleLooksLikeAPlant) {
  namespace fs = std::filesystem;
  const auto dir = scratch_dir("lsystem_render");
  const fs::path examples = fs::path(FSPM_SOURCE_DIR) / "examples" / "lsystems";
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(examples)) {
    if (entry.path().extension() == ".l") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 10u);
  std::size_t drawn = 0;
  for (const fs::path& l : files) {
    const std::string name = l.stem().string();
    const std::string tree = (dir / (name + ".tree")).string();
    const std::string png = (dir / (name + ".png")).string();
    auto r = run_fspm("lsystem interpret " + l.string() + " -o " + tree);
    if (r.err.find("draws nothing") != std::string::npos) continue;  // a string-only example
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    ++drawn;
    r = run_fspm("render " + tree + " -o " + png +
                 " --view front --no-ground --size 500x500 --leaves");
    if (r.exit_code != 0 && (r.err.find("without VTK") != std::string::npos ||
                             r.err.find("no X display") != std::string::npos)) {
      GTEST_SKIP() << r.err;
    }
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    const Silhouette s = silhouette(graphics::read_image(png));
    ASSERT_GT(s.pixels, 0u) << name;
    // A picture of a plant, not a cake: the trunk under a tenth of the height, and the
    // silhouette under 40 % of the box around it.
    EXPECT_GT(s.height(), 100) << name;
    EXPECT_LT(s.trunk_px, 0.1 * s.height()) << name << ": trunk " << s.trunk_px << " px";
    const double box = static_cast<double>(s.width()) * s.height();
    EXPECT_LT(static_cast<double>(s.pixels), 0.4 * box)
        << name << ": " << s.pixels << " of " << box << " px";
  }
  EXPECT_GE(drawn, 10u);
}

// Fig. 1.24a at n = 6 drawn explicitly and by instancing, substructures under a pixel as their
// chord: the same picture up to the pixels along the outline.
TEST(LsystemRender, CompressedRenderHasTheExplicitSilhouette) {
  const auto dir = scratch_dir("lsystem_render_compressed");
  const std::string l = std::string(FSPM_SOURCE_DIR) + "/examples/lsystems/abop_1_24a.l";
  std::vector<std::vector<char>> masks;
  for (const std::string mode : {"", " --compressed"}) {
    const std::string png = (dir / ("a" + std::to_string(masks.size()) + ".png")).string();
    const auto r = run_fspm("render " + l + mode +
                            " --steps 6 --view front --no-ground --size 240x320 -o " + png);
    if (r.exit_code != 0 && (r.err.find("without VTK") != std::string::npos ||
                             r.err.find("no X display") != std::string::npos)) {
      GTEST_SKIP() << r.err;
    }
    ASSERT_EQ(r.exit_code, 0) << r.err;
    masks.push_back(foreground_mask(graphics::read_image(png)));
  }
  std::size_t both = 0, either = 0;
  for (std::size_t i = 0; i < masks[0].size(); ++i) {
    both += masks[0][i] && masks[1][i] ? 1 : 0;
    either += masks[0][i] || masks[1][i] ? 1 : 0;
  }
  ASSERT_GT(either, 1000u);
  EXPECT_GT(static_cast<double>(both), 0.85 * static_cast<double>(either))
      << both << " of " << either << " foreground pixels shared";
}

}  // namespace
}  // namespace fspm
