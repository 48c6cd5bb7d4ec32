#pragma once
// Never leave a half-written output: write to a temporary file beside the target, then rename.
// A device or pipe (/dev/null, a FIFO) is written in place, never replaced.
#include <functional>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace fspm {

// Calls `write` with a stream on a temporary file in the target's directory; on success the
// temporary file replaces `path` atomically, on any exception it is removed and the exception
// propagates. A target that exists and is not a regular file (a device, a FIFO) is written
// directly. Throws IoError when the target is a directory or the directory is not writable.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

// Where the bytes last written to `path` are now: the temporary file an open OutputTransaction on
// this thread holds back for it, else `path` itself. For a command that reads back what it wrote
// (the size of its output) before its transaction commits.
std::string written_file(const std::string& path);

// All of a command's outputs or none: while an OutputTransaction lives, write_file_atomically on
// its thread leaves each output in its temporary file; commit() renames them all into place at
// the end, and a transaction destroyed without commit() (an exception on the way: a full disk, a
// later error) removes them, so a command that fails on its third file leaves neither the first
// nor the second. Devices and pipes are still written in place. Transactions nest: the inner
// one's files join the outer one's at its commit().
class OutputTransaction {
 public:
  OutputTransaction();
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  // Renames every temporary over its target, in the order written. Throws IoError (and removes
  // the temporaries not renamed yet) when a rename fails.
  void commit();

  // Called by write_file_atomically: keeps `temporary` to be renamed to `target`; `cleanup` is
  // its handle of fspm/signal_cleanup.hpp, released once it is renamed or removed.
  void add(std::string temporary, std::string target, int cleanup = -1);

  // The thread's innermost open transaction, or nullptr.
  static OutputTransaction* current();

  // The temporary held back for `target` here or in an outer transaction (the latest written),
  // or an empty string.
  std::string temporary_of(const std::string& target) const;

 private:
  OutputTransaction* outer_;
  struct Pending {
    std::string temporary, target;
    int cleanup = -1;
  };
  std::vector<Pending> pending_;
  bool committed_ = false;
};

}  // namespace fspm
