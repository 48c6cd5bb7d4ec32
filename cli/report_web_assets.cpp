#include "cli/report_web_assets.hpp"

#include <array>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"

namespace fspm::cli {
namespace {

namespace fs = std::filesystem;

// What index.html loads, and the libraries' licences.
constexpr std::array<const char*, 7> kFiles = {
    "three.min.js", "plotly.min.js", "marked.min.js",           "safe_markdown.js",
    "report.js",    "report.css",    "THIRD_PARTY_LICENSES.txt"};

}  // namespace

fs::path report_web_dir() {
  fs::path dir;
  if (const char* env = std::getenv(kReportWebDirVariable); env != nullptr && *env != '\0') {
    dir = env;
  } else {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw IoError("cannot find this executable's folder (/proc/self/exe): " + ec.message());
    dir = self.parent_path().parent_path() / "share" / "fspm" / "report_web";
  }
  for (const char* name : kFiles) {
    if (!fs::is_regular_file(dir / name)) {
      throw IoError("the HTML report's browser files are missing (" + (dir / name).string() +
                    "): build fspm with npm installed (scripts/deps.sh), or set " +
                    kReportWebDirVariable + " to a folder made by report_web/build.sh");
    }
  }
  return dir;
}

void copy_report_web(const fs::path& to) {
  const fs::path from = report_web_dir();
  std::error_code ec;
  fs::create_directories(to, ec);
  if (ec) throw IoError("cannot create " + to.string() + ": " + ec.message());
  for (const char* name : kFiles) {
    std::ifstream in(from / name, std::ios::binary);
    if (!in) throw IoError("cannot read " + (from / name).string());
    std::ostringstream bytes;
    bytes << in.rdbuf();
    write_file_atomically((to / name).string(), [&](std::ostream& out) { out << bytes.str(); },
                          true);
  }
}

}  // namespace fspm::cli
