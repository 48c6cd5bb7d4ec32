#include "cli/xvfb.hpp"

#include <spdlog/spdlog.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/signal_cleanup.hpp"
#include "graphics/render.hpp"

namespace fspm::cli {

namespace {

// The X server xvfb-run started (its pid from /tmp/.X<display>-lock) and the folder of its
// authority file: a script that was killed cannot stop or remove them, so this process does.
pid_t g_server = 0;
char g_authority[4096] = {};
char g_authority_dir[4096] = {};

void remember_server() {
  const char* display = std::getenv("DISPLAY");
  if (display != nullptr && display[0] == ':') {
    const std::string number(display + 1, display + 1 + std::strspn(display + 1, "0123456789"));
    std::ifstream lock("/tmp/.X" + number + "-lock");
    long pid = 0;
    if (!number.empty() && lock >> pid && pid > 1) g_server = static_cast<pid_t>(pid);
  }
  const char* authority = std::getenv("XAUTHORITY");
  const std::filesystem::path file = authority != nullptr ? authority : "";
  if (file.parent_path().filename().string().starts_with("xvfb-run.") &&
      file.string().size() < sizeof g_authority) {
    std::strcpy(g_authority, file.c_str());
    std::strcpy(g_authority_dir, file.parent_path().c_str());
  }
}

// Only when the script is gone (this process was re-parented): otherwise it cleans up itself.
void stop_orphaned_server() {
  if (::getppid() != 1) return;
  if (g_server > 0) ::kill(g_server, SIGTERM);
  if (g_authority[0] != '\0') {
    ::unlink(g_authority);
    ::rmdir(g_authority_dir);
  }
}

extern "C" void stop_with_server(int signal) {
  stop_orphaned_server();  // kill, unlink and rmdir are async-signal-safe
  fspm_signal_cleanup_handler(signal);
}

// Under xvfb-run this process is the script's child: a SIGTERM or SIGINT sent to the command the
// user started ends the script, not this process, which would go on and write its outputs after
// being stopped. The kernel sends it SIGTERM when its parent ends instead, and the X server the
// script leaves behind is stopped with it.
void stop_with_xvfb_run() {
  remember_server();
  std::signal(SIGTERM, stop_with_server);
  std::signal(SIGINT, stop_with_server);
  std::atexit(stop_orphaned_server);  // a command that stops gracefully (fspm run)
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() == 1) std::raise(SIGTERM);  // the script already ended
}

}  // namespace

namespace {

// Whether rerun_under_xvfb_if_needed() would start the command again.
bool will_rerun_under_xvfb() {
  return std::getenv("FSPM_UNDER_XVFB") == nullptr && !graphics::display_available() &&
         std::filesystem::exists("/usr/bin/xvfb-run");
}

}  // namespace

void check_inputs_readable_twice(const std::vector<std::string>& paths) {
  bool rerun_known = false, rerun = false;
  for (const std::string& path : paths) {
    if (path.empty()) continue;
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status) || std::filesystem::is_regular_file(status) ||
        std::filesystem::is_directory(status)) {
      continue;
    }
    if (!rerun_known) rerun = will_rerun_under_xvfb(), rerun_known = true;
    if (!rerun) return;
    throw IoError(
        "not a regular file (a pipe or device): without an X display the command runs again "
        "under xvfb-run and reads its inputs twice; expected a file on disk",
        path);
  }
}

void rerun_under_xvfb_if_needed() {
  if (std::getenv("FSPM_UNDER_XVFB") != nullptr) {
    stop_with_xvfb_run();
    return;
  }
  if (graphics::display_available()) return;
  const char* xvfb_run = "/usr/bin/xvfb-run";
  if (!std::filesystem::exists(xvfb_run)) return;
  std::ifstream cmdline("/proc/self/cmdline", std::ios::binary);
  const std::string all{std::istreambuf_iterator<char>(cmdline), {}};
  std::vector<std::string> args;
  for (std::size_t at = 0; at < all.size();) {
    const std::size_t end = all.find('\0', at);
    args.push_back(all.substr(at, end - at));
    if (end == std::string::npos) break;
    at = end + 1;
  }
  std::error_code ec;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
  if (ec || args.empty()) return;
  spdlog::info("no X display: rendering under xvfb-run");
  // -noreset: without it the server resets when this command disconnects and signals the script
  // (SIGUSR1), which, arriving while the script removes its authority folder, made xvfb-run end
  // with its own status 5 in place of the command's (one failed write in five).
  std::vector<std::string> words = {xvfb_run, "-a", "-s", "-screen 0 1280x1024x24 -noreset", self};
  words.insert(words.end(), args.begin() + 1, args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  ::setenv("FSPM_UNDER_XVFB", "1", 1);
  std::cout.flush();
  std::cerr.flush();
  ::execv(xvfb_run, argv.data());
  ::unsetenv("FSPM_UNDER_XVFB");  // exec failed: fall through to the caller's clear error
}

}  // namespace fspm::cli
