#include "experiments/progress.hpp"

#include <fmt/format.h>

#include <ostream>
#include <string>

namespace fspm::experiments {
namespace {

std::string clock_text(double seconds) {
  const auto s = static_cast<long long>(seconds + 0.5);
  return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
}

}  // namespace

ProgressReporter::ProgressReporter(std::ostream* out, std::size_t total, bool bar,
                                   double interval_s)
    : out_(out), total_(total), bar_(bar), interval_s_(interval_s) {}

void ProgressReporter::update(std::size_t done, std::size_t failed, bool final) {
  if (out_ == nullptr) return;
  const Clock::time_point now = Clock::now();
  const double since_last = std::chrono::duration<double>(now - last_).count();
  if (!final && since_last < (bar_ ? 0.2 : interval_s_)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0.0 ? static_cast<double>(done) / elapsed : 0.0;
  const double eta = rate > 0.0 ? static_cast<double>(total_ - std::min(done, total_)) / rate : 0.0;
  const double fraction =
      total_ == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total_);
  if (bar_) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    *out_ << fmt::format("\r[{}{}] {}/{} {:3.0f}% {:.1f} runs/s, {} failed, ETA {} ",
                         std::string(static_cast<std::size_t>(filled), '#'),
                         std::string(static_cast<std::size_t>(kWidth - filled), ' '), done, total_,
                         100.0 * fraction, rate, failed, clock_text(eta));
    if (final) *out_ << '\n';
  } else {
    *out_ << fmt::format(
        "progress: {}/{} runs ({:.0f}%), {} failed, {:.1f} runs/s, elapsed {}, ETA {}\n", done,
        total_, 100.0 * fraction, failed, rate, clock_text(elapsed), clock_text(eta));
  }
  out_->flush();
  printed_ = true;
}

}  // namespace fspm::experiments
