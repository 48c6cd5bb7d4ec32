#pragma once
// `fspm report DIR --html --single-file`: the HTML report folder (cli/html_report.hpp) folded
// into one page that carries everything itself, to mail or archive: the style sheet, the browser
// libraries and data.js inline, and every tree as its gzipped glTF binary in base64 (the
// trees/*.js files) in a script of its own, which the page takes instead of loading the file.
#include <cstdint>
#include <filesystem>
#include <string>

namespace fspm::cli {

// Writes `out` (atomically) from the folder `report_dir` that write_html_report wrote, and
// returns its size in bytes. Throws IoError when a file the page names is missing or `out`
// cannot be written.
std::uintmax_t write_single_file_report(const std::filesystem::path& report_dir,
                                        const std::filesystem::path& out);

// Text placed inside <script>...</script>: every "</script" and "<!--" made harmless so that
// the HTML parser cannot end or bend the script early (a "<\/" in JavaScript is the same text in
// a string or a regular expression; minified code has no such sequence outside them).
std::string script_safe(std::string text);

}  // namespace fspm::cli
