#include "cli/output.hpp"

#include <spdlog/spdlog.h>

#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <streambuf>
#include <system_error>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/number_text.hpp"

namespace fspm::cli {
namespace {
int g_verbosity = 1;

// std::cout's buffer: writes to file descriptor 1 and keeps the system's reason of the first
// failed write (errno is long overwritten by the time the command line ends).
class StandardOutputBuffer : public std::streambuf {
 public:
  StandardOutputBuffer() {
    setp(buffer_, buffer_ + sizeof buffer_);
    // Started with stdout closed (`>&-`): hold descriptor 1 with /dev/null so that no file the
    // command opens lands there, and fail the first write as a closed stdout would.
    if (::fcntl(STDOUT_FILENO, F_GETFD) == -1 && errno == EBADF) {
      const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
      if (null >= 0 && null != STDOUT_FILENO) {
        ::dup2(null, STDOUT_FILENO);
        ::close(null);
      }
      closed_ = true;
    }
  }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!write_out()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return write_out() ? 0 : -1; }

 private:
  // Writes the buffer out (dropped after a failure: nothing more can reach the output).
  bool write_out() {
    if (closed_ && pptr() > pbase()) error_ = EBADF;
    for (const char* p = pbase(); error_ == 0 && p < pptr();) {
      const ssize_t n = ::write(STDOUT_FILENO, p, static_cast<std::size_t>(pptr() - p));
      if (n >= 0) {
        p += n;
      } else if (errno != EINTR) {
        error_ = errno;
      }
    }
    setp(buffer_, buffer_ + sizeof buffer_);
    return error_ == 0;
  }

  char buffer_[1 << 16];
  int error_ = 0;
  bool closed_ = false;
};

std::string bound_text(double value) {
  if (value == std::floor(value) && std::abs(value) < 1e15) {
    return std::to_string(static_cast<long long>(value));
  }
  std::string out;
  append_number(out, value);
  return out;
}

CLI::Validator range_check(double low, double high, bool low_inclusive) {
  const std::string range =
      (low_inclusive ? "[" : "(") + bound_text(low) + ", " + bound_text(high) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const auto v = parse_number(text);
        if (v && (low_inclusive ? *v >= low : *v > low) && *v <= high) return {};
        const std::string shown = text.size() > 40 ? text.substr(0, 40) + "..." : text;
        return "expected a number in " + range + ", got '" + shown + "'";
      },
      "in " + range);
}

}  // namespace

void refuse_overwriting_input(const std::string& output,
                              std::initializer_list<std::string> inputs) {
  if (output.empty()) return;
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (!input.empty() && std::filesystem::equivalent(output, input, ec) && !ec) {
      throw ValueError(
          "the output would overwrite an input ('" + input + "'): choose another output file",
          output);
    }
  }
}

void refuse_same_output(const std::string& first, std::string_view first_option,
                        const std::string& second, std::string_view second_option) {
  if (first.empty() || second.empty()) return;
  namespace fs = std::filesystem;
  std::error_code ec1;
  std::error_code ec2;
  const fs::path a = fs::weakly_canonical(fs::absolute(first), ec1);
  const fs::path b = fs::weakly_canonical(fs::absolute(second), ec2);
  std::error_code ec;
  const bool same = (!ec1 && !ec2 && a == b) || (fs::equivalent(first, second, ec) && !ec);
  if (!same) return;
  throw ValueError(std::string(second_option) + " '" + second + "' and " +
                       std::string(first_option) +
                       " name the same file: one output would replace the other",
                   first);
}

CLI::Validator number_in(double low, double high) { return range_check(low, high, true); }
CLI::Validator positive_number(double high) { return range_check(0.0, high, false); }

void add_input_format_option(CLI::App* command, std::string& format) {
  command->add_option("--format", format, std::string("Input format: ") + kTreeFormats);
}

std::string json_text(const nlohmann::json& value, int indent) {
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

void print_json(const nlohmann::json& document) { std::cout << json_text(document, 2) << '\n'; }

std::string human_text(const nlohmann::json& value) {
  if (value.is_number_float()) return format_significant(value.get<double>());
  if (!value.is_array()) return json_text(value);
  std::string out = "[";
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (i > 0) out += ", ";
    out += human_text(value[i]);
  }
  return out + "]";
}

void use_checked_standard_output() {
  // Never destroyed: std::cout is flushed once more after main returns.
  static auto* buffer = new StandardOutputBuffer();
  std::cout.rdbuf(buffer);
}

void finish_standard_output() {
  std::cout.flush();
  auto* buffer = dynamic_cast<StandardOutputBuffer*>(std::cout.rdbuf());
  const int reason = buffer != nullptr ? buffer->error() : 0;
  if (std::cout && reason == 0) return;
  throw IoError(
      "cannot write: " + (reason != 0 ? std::generic_category().message(reason) : "write failed"),
      "standard output");
}

void run_reporting_command(const std::function<void()>& command) {
  OutputTransaction files;
  command();
  finish_standard_output();
  files.commit();
}

void set_verbosity(int level) {
  g_verbosity = level;
  spdlog::set_level(level <= 0 ? spdlog::level::warn
                               : (level == 1 ? spdlog::level::info : spdlog::level::debug));
}

int verbosity() { return g_verbosity; }

}  // namespace fspm::cli
