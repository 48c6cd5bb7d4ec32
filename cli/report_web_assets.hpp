#pragma once
// The browser files of the HTML report (fspm report --html): three.js, Plotly, marked and the
// report's own script and style, built from the npm registry by report_web/build.sh at build time
// into share/fspm/report_web beside the executable's bin/ folder (build tree and install alike).
#include <filesystem>

namespace fspm::cli {

// Environment variable naming another folder with the same files.
inline constexpr const char* kReportWebDirVariable = "FSPM_REPORT_WEB_DIR";

// FSPM_REPORT_WEB_DIR when set, else <folder of this executable>/../share/fspm/report_web.
// Throws IoError naming the folder and how to build it when a file is missing.
std::filesystem::path report_web_dir();

// Copies the files into `to` (created if needed), each atomically. Throws IoError.
void copy_report_web(const std::filesystem::path& to);

}  // namespace fspm::cli
