#include "fspm/atomic_file.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <random>
#include <system_error>

#include "fspm/error.hpp"
#include "fspm/signal_cleanup.hpp"

namespace fspm {
namespace {

namespace fs = std::filesystem;

std::string system_reason(int error) {
  return error != 0 ? std::generic_category().message(error) : std::string("write failed");
}

// Opens `file`, runs `write` on it and closes it; every failure is an IoError naming `path`.
void write_stream(const fs::path& file, const std::string& path,
                  const std::function<void(std::ostream&)>& write, bool binary) {
  errno = 0;
  std::ofstream out(file, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
  if (!out) throw IoError("cannot open for writing: " + system_reason(errno), path);
  out.exceptions(std::ios::badbit);
  try {
    write(out);
    out.close();
  } catch (const std::ios_base::failure&) {
    // A failed write (full disk, file size limit): the reason is still in errno.
    throw IoError("cannot write: " + system_reason(errno), path);
  }
  if (out.fail()) throw IoError("cannot write: " + system_reason(errno), path);
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary) {
  const fs::path target(path);
  if (target.filename().empty()) throw IoError("output path names no file", path);
  std::error_code ec;
  const fs::file_status status = fs::status(target, ec);
  if (fs::is_directory(status)) throw IoError("is a directory, expected a file", path);
  // A device, pipe or socket (/dev/null, /dev/stdout, a FIFO) is written in place: renaming a
  // file over it would replace the device node itself, and a stream has no half-written state
  // to protect.
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    write_stream(target, path, write, binary);
    return;
  }
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) {
    throw IoError("cannot write: directory '" + dir.string() + "' does not exist", path);
  }
  // A random suffix keeps concurrent writers (threads, MPI ranks) of the same target apart.
  std::random_device rd;
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict, PR 105651) on chained operator+.
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp";
  name += std::to_string(rd() % 1000000);
  const fs::path tmp = dir / name;
  // Removed by the handler should SIGINT or SIGTERM end the process before the rename.
  const int cleanup = register_signal_cleanup(tmp.string());
  try {
    write_stream(tmp, path, write, binary);
    if (OutputTransaction* t = OutputTransaction::current()) {
      t->add(tmp.string(), path, cleanup);
      return;
    }
    fs::rename(tmp, target, ec);
    unregister_signal_cleanup(cleanup);
    if (ec) {
      fs::remove(tmp, ec);
      throw IoError("cannot replace the file: " + ec.message(), path);
    }
  } catch (...) {
    fs::remove(tmp, ec);
    unregister_signal_cleanup(cleanup);
    throw;
  }
}

namespace {
thread_local OutputTransaction* t_current = nullptr;
}  // namespace

OutputTransaction::OutputTransaction() : outer_(t_current) { t_current = this; }

OutputTransaction::~OutputTransaction() {
  t_current = outer_;
  if (committed_) return;
  std::error_code ec;
  for (const Pending& p : pending_) {
    fs::remove(p.temporary, ec);
    unregister_signal_cleanup(p.cleanup);
  }
}

OutputTransaction* OutputTransaction::current() { return t_current; }

std::string OutputTransaction::temporary_of(const std::string& target) const {
  for (auto p = pending_.rbegin(); p != pending_.rend(); ++p) {
    if (p->target == target) return p->temporary;
  }
  return outer_ != nullptr ? outer_->temporary_of(target) : std::string();
}

std::string written_file(const std::string& path) {
  const OutputTransaction* t = OutputTransaction::current();
  const std::string temporary = t != nullptr ? t->temporary_of(path) : std::string();
  return temporary.empty() ? path : temporary;
}

void OutputTransaction::add(std::string temporary, std::string target, int cleanup) {
  pending_.push_back({std::move(temporary), std::move(target), cleanup});
}

void OutputTransaction::commit() {
  committed_ = true;
  if (outer_ != nullptr) {
    for (Pending& p : pending_) outer_->add(std::move(p.temporary), std::move(p.target), p.cleanup);
    return;
  }
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    std::error_code ec;
    fs::rename(pending_[i].temporary, pending_[i].target, ec);
    unregister_signal_cleanup(pending_[i].cleanup);
    if (ec) {
      fs::remove(pending_[i].temporary, ec);
      for (std::size_t j = i + 1; j < pending_.size(); ++j) {
        fs::remove(pending_[j].temporary, ec);
        unregister_signal_cleanup(pending_[j].cleanup);
      }
      throw IoError("cannot replace the file: " + ec.message(), pending_[i].target);
    }
  }
}

}  // namespace fspm
