// Core helpers of hardened input and output: file checks, nesting bounds, message length,
// "did you mean", finite geometry and the reason of a failed atomic write.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <thread>

#include "fspm/atomic_file.hpp"
#include "fspm/closest_name.hpp"
#include "fspm/error.hpp"
#include "fspm/finite_geometry.hpp"
#include "fspm/input_file.hpp"
#include "fspm/nesting_depth.hpp"
#include "tests/scoped_memory_limit.hpp"

namespace fspm {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("fspm_input_checks_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(InputFile, SaysWhatIsWrongWithThePath) {
  const fs::path dir = scratch("paths");
  EXPECT_EQ(message_of([&] { read_input_file(dir.string()); }),
            dir.string() + ": is a directory, expected a file");
  EXPECT_EQ(message_of([&] { read_input_file((dir / "none").string()); }),
            (dir / "none").string() + ": cannot open for reading: No such file or directory");
  std::ofstream(dir / "ten") << "0123456789";
  EXPECT_EQ(read_input_file((dir / "ten").string()), "0123456789");
  EXPECT_EQ(message_of([&] { read_input_file((dir / "ten").string(), 9); }),
            (dir / "ten").string() + ": larger than the limit of 9 bytes for an input file");
  // A device without end is cut at the limit, not read until memory runs out.
  EXPECT_EQ(message_of([&] { read_input_file("/dev/zero", 1 << 20); }),
            "/dev/zero: larger than the limit of 1048576 bytes for an input file");
  fs::remove_all(dir);
}

// A NUL byte in a path (from Python or a library call) would cut it short at the system call
// and open another file: "ten\0.tree" must not read "ten". Control characters of the name are
// escaped in the message, which stays one line.
TEST(InputFile, PathWithANulByteIsRefused) {
  const fs::path dir = scratch("nul");
  std::ofstream(dir / "ten") << "0123456789";
  const std::string path = (dir / "ten").string() + std::string(1, '\0') + ".tree";
  EXPECT_THROW(read_input_file(path), ValueError);
  EXPECT_THROW(open_input_file(path), ValueError);
  EXPECT_EQ(message_of([&] { read_text_input_file(path); }),
            (dir / "ten").string() + "\\x00.tree: the file name holds a NUL byte");
  fs::remove_all(dir);
}

// A text reader refuses a NUL byte where it is read: /dev/zero at once, not after a gigabyte.
TEST(InputFile, TextReaderRefusesBinaryData) {
  const fs::path dir = scratch("text");
  const std::string text_file = (dir / "a.txt").string();
  std::ofstream(text_file) << "x = 1\n";
  EXPECT_EQ(read_text_input_file(text_file), "x = 1\n");
  const std::string binary = (dir / "b.txt").string();
  {
    std::ofstream out(binary, std::ios::binary);
    out << std::string(70000, 'a') << '\0' << "b";
  }
  EXPECT_EQ(message_of([&] { read_text_input_file(binary); }),
            binary + ": binary data (a NUL byte at byte 70000), expected a text file");
  EXPECT_EQ(message_of([&] { read_text_input_file("/dev/zero"); }),
            "/dev/zero: binary data (a NUL byte at byte 0), expected a text file");
  fs::remove_all(dir);
}

// Bytes read whole are kept: they stay within the memory limit, told before reading a regular
// file and as soon as a pipe or device passes it.
TEST(InputFile, WholeReadsStayWithinTheMemoryLimit) {
  const test_support::ScopedMemoryLimit limit(std::uint64_t{1} << 20);
  const fs::path dir = scratch("memory");
  const std::string two_mib = (dir / "big.treeb").string();
  std::ofstream(two_mib, std::ios::binary) << std::string(std::size_t{2} << 20, 'x');
  EXPECT_EQ(message_of([&] { read_input_file(two_mib); }),
            two_mib +
                ": reading the whole file needs about 2 MiB, above the memory limit of "
                "1 MiB (--memory-limit)");
  // A regular file is streamed, not held: its own limit applies, not the memory limit.
  EXPECT_NO_THROW(open_input_file(two_mib));
  const std::string device_message =
      "/dev/zero: a pipe or device holding more than the memory limit of 1 MiB (--memory-limit)";
  EXPECT_EQ(message_of([&] { read_input_file("/dev/zero"); }), device_message);
  EXPECT_EQ(message_of([&] { open_input_file("/dev/zero", kMaxTreeFileBytes); }), device_message);
  // A pipe with 1 MiB + 1 byte in it: one byte over.
  const fs::path fifo = dir / "in.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] {
    std::ofstream out(fifo, std::ios::binary);
    out << std::string((std::size_t{1} << 20) + 1, 'y');
  });
  EXPECT_EQ(message_of([&] { read_input_file(fifo.string()); }),
            fifo.string() +
                ": a pipe or device holding more than the memory limit of 1 MiB "
                "(--memory-limit)");
  writer.join();
  // Exactly at the limit is read.
  std::thread exact_writer([&] {
    std::ofstream out(fifo, std::ios::binary);
    out << std::string(std::size_t{1} << 20, 'z');
  });
  EXPECT_EQ(read_input_file(fifo.string()).size(), std::size_t{1} << 20);
  exact_writer.join();
  fs::remove_all(dir);
}

TEST(NestingDepth, JsonBoundCountsBracketsOutsideStrings) {
  EXPECT_NO_THROW(check_json_depth("[[1], {\"a\": [2]}]", "x.json", 3));
  EXPECT_NO_THROW(check_json_depth("[\"[[[[[[\"]", "x.json", 1));
  EXPECT_EQ(message_of([] { check_json_depth("[\n [[\"\\\"\"]]]", "x.json", 2); }),
            "x.json:2:3: nesting deeper than the limit of 2 levels (JSON arrays and objects)");
}

TEST(ErrorMessage, LongQuotedInputIsShortenedInTheMiddle) {
  const Error e("found '" + std::string(100000, 'x') + "' at the end", "f.txt", 3);
  EXPECT_LE(std::string(e.what()).size(), kMaxErrorMessageLength + 100);
  EXPECT_TRUE(std::string(e.what()).starts_with("f.txt:3: found 'xxx"));
  EXPECT_TRUE(std::string(e.what()).ends_with("x' at the end"));
}

TEST(ClosestName, SwapsAndTyposFindTheKnownName) {
  EXPECT_EQ(closest_name("LNE", {"LEN", "ANGLE"}), "LEN");
  EXPECT_EQ(closest_name("angel", {"LEN", "ANGLE"}), "ANGLE");
  EXPECT_EQ(closest_name("zz", {"LEN", "ANGLE"}), "");
  EXPECT_EQ(closest_name_hint("zz", {"LEN"}), " (known: LEN)");
  EXPECT_EQ(closest_name_hint("LNE", {"LEN"}), " (did you mean 'LEN'?)");
  EXPECT_EQ(closest_name_hint("LNE", {}), "");
}

TEST(FiniteGeometry, NanAndInfinityAreNamed) {
  TreeGraph t;
  NodeData d;
  d.end = {0, 0, 1};
  t.add_node(kNoNode, d);
  EXPECT_EQ(non_finite_geometry(t, 0), nullptr);
  t.set_radius(0, std::numeric_limits<double>::infinity());
  EXPECT_STREQ(non_finite_geometry(t, 0), "radius");
  EXPECT_THROW(require_finite_geometry(t, "t.tree"), ValueError);
}

TEST(AtomicFile, FailedWriteNamesThePathAndTheReasonAndLeavesNothing) {
  const fs::path dir = scratch("atomic");
  const std::string path = (dir / "big.txt").string();
  // A file size limit makes writes fail with EFBIG (SIGXFSZ ignored) in this process only.
  rlimit old{};
  ::getrlimit(RLIMIT_FSIZE, &old);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old;
  small.rlim_cur = 4096;
  ::setrlimit(RLIMIT_FSIZE, &small);
  const std::string message = message_of([&] {
    write_file_atomically(path, [](std::ostream& out) { out << std::string(1 << 20, 'x'); });
  });
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_EQ(message, path + ": cannot write: File too large");
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

// A device is written in place: renaming a temporary file over /dev/full would replace the
// device node (as root) and report success.
TEST(AtomicFile, DeviceIsWrittenInPlace) {
  const std::string message = message_of([] {
    write_file_atomically("/dev/full", [](std::ostream& out) { out << std::string(1 << 16, 'x'); });
  });
  EXPECT_EQ(message, "/dev/full: cannot write: No space left on device");
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

TEST(AtomicFile, FifoStaysAFifo) {
  const fs::path dir = scratch("atomic_fifo");
  const fs::path fifo = dir / "out.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo);
    std::getline(in, received);
  });
  write_file_atomically(fifo.string(), [](std::ostream& out) { out << "through the pipe\n"; });
  reader.join();
  EXPECT_EQ(received, "through the pipe");
  EXPECT_TRUE(fs::is_fifo(fifo));
  fs::remove_all(dir);
}

TEST(AtomicFile, DirectoryTargetIsRefused) {
  const fs::path dir = scratch("atomic_dir");
  const std::string message =
      message_of([&] { write_file_atomically(dir.string(), [](std::ostream& out) { out << 1; }); });
  EXPECT_EQ(message, dir.string() + ": is a directory, expected a file");
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fspm
