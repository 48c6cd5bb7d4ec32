#include "fspm/warning.hpp"

#include "fspm/one_line.hpp"

#include <iostream>
#include <mutex>
#include <utility>

namespace fspm {
namespace {

std::mutex& handler_mutex() {
  static std::mutex m;
  return m;
}

WarningHandler& handler() {
  static WarningHandler h;
  return h;
}

}  // namespace

WarningHandler set_warning_handler(WarningHandler h) {
  const std::lock_guard<std::mutex> lock(handler_mutex());
  return std::exchange(handler(), std::move(h));
}

void warn(const std::string& text) {
  const std::string message = one_line(text);  // a file name's newline cannot split it
  WarningHandler h;
  {
    const std::lock_guard<std::mutex> lock(handler_mutex());
    h = handler();
  }
  if (h) {
    h(message);
  } else {
    std::cerr << "warning: " << message << '\n';
  }
}

}  // namespace fspm
