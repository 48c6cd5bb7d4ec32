// Image files through the OpenImageIO module: a PNG written and read back value for value, the
// refusals before any work (unknown format, missing folder, missing file), and the memory
// budget counting the values read, the decoder's buffer and the caller's extra bytes.
#include "fspm/image_file.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm {
namespace {

namespace fs = std::filesystem;

// Skips the test when fspm was built without the OpenImageIO module.
bool have_codec() {
  try {
    image_codec();
    return true;
  } catch (const ValueError&) {
    return false;
  }
}

// A 100 x 100 RGB PNG whose red is the column, green the row and blue 7.
std::string write_test_png(const fs::path& dir) {
  const std::string path = (dir / "ramp.png").string();
  std::vector<std::uint8_t> rgb(100 * 100 * 3);
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      std::uint8_t* p = &rgb[3 * (y * 100 + x)];
      p[0] = static_cast<std::uint8_t>(x);
      p[1] = static_cast<std::uint8_t>(y);
      p[2] = 7;
    }
  }
  write_image_file(path, ImageInfo{100, 100, 3, 1}, PixelType::kUint8, rgb.data());
  return path;
}

class ImageFile : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!have_codec()) GTEST_SKIP() << "fspm built without OpenImageIO";
    dir_ = fs::temp_directory_path() / ("fspm_image_file_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    set_memory_limit_bytes(0);  // back to the default
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path dir_;
};

TEST_F(ImageFile, PngRoundTripValueForValue) {
  const std::string path = write_test_png(dir_);
  ImageInfo info;
  const std::vector<std::uint8_t> bytes = read_image_bytes(path, 0, info);
  ASSERT_EQ(info.width, 100);
  ASSERT_EQ(info.height, 100);
  ASSERT_EQ(info.channels, 3);
  ASSERT_EQ(bytes.size(), 100u * 100u * 3u);
  EXPECT_EQ(bytes[3 * (20 * 100 + 30) + 0], 30);  // row 20, column 30: row 0 is the top
  EXPECT_EQ(bytes[3 * (20 * 100 + 30) + 1], 20);
  EXPECT_EQ(bytes[3 * (20 * 100 + 30) + 2], 7);
  // Channel 0 alone as floats: 8-bit values over 255.
  const std::vector<float> red = read_image_floats(path, 1, info);
  ASSERT_EQ(red.size(), 100u * 100u);
  EXPECT_FLOAT_EQ(red[20 * 100 + 51], 51.0f / 255.0f);
}

TEST_F(ImageFile, RefusedBeforeAnyWork) {
  EXPECT_THROW(check_image_output((dir_ / "out.nosuchformat").string()), ValueError);
  EXPECT_THROW(check_image_output((dir_ / "missing" / "out.png").string()), IoError);
  EXPECT_NO_THROW(check_image_output((dir_ / "out.png").string()));
  ImageInfo info;
  EXPECT_THROW(read_image_floats((dir_ / "none.png").string(), 0, info), IoError);
  const std::uint8_t pixel[3] = {1, 2, 3};
  EXPECT_THROW(write_image_file((dir_ / "missing" / "out.png").string(), ImageInfo{1, 1, 3, 1},
                                PixelType::kUint8, pixel),
               IoError);
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

// 100 x 100 pixels, 3 stored channels of 1 byte, under a limit of 100 000 bytes: all three as
// floats hold 3 x (4 + 1) = 15 bytes per pixel (150 000 bytes, refused); the red channel alone
// 4 + 3 = 7 (70 000, read); with 4 bytes per pixel the caller keeps beside them, 110 000 (refused).
TEST_F(ImageFile, MemoryBudgetCountsEveryBuffer) {
  const std::string path = write_test_png(dir_);
  ImageInfo info;
  set_memory_limit_bytes(100'000);
  EXPECT_THROW(read_image_floats(path, 0, info), MemoryLimitError);
  EXPECT_NO_THROW(read_image_floats(path, 1, info));
  EXPECT_THROW(read_image_floats(path, 1, info, 4.0), MemoryLimitError);
  // Bytes: 3 x (1 + 1) = 6 per pixel, 60 000 bytes.
  EXPECT_NO_THROW(read_image_bytes(path, 0, info));
}

}  // namespace
}  // namespace fspm
