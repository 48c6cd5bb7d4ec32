#include "cli/xvfb.hpp"

#include <spdlog/spdlog.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "graphics/render.hpp"

namespace fspm::cli {

namespace {

// Under xvfb-run this process is the script's child: a SIGTERM or SIGINT sent to the command the
// user started ends the script, not this process, which would go on and write its outputs after
// being stopped. The kernel sends it SIGTERM when its parent ends instead.
void stop_with_xvfb_run() {
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() == 1) std::raise(SIGTERM);  // the script already ended
}

}  // namespace

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
  std::vector<std::string> words = {xvfb_run, "-a", "-s", "-screen 0 1280x1024x24", self};
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
