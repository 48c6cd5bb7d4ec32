#pragma once
// Never leave a half-written output: write to a temporary file beside the target, then rename.
// A device or pipe (/dev/null, a FIFO) is written in place, never replaced.
#include <functional>
#include <iosfwd>
#include <string>

namespace fspm {

// Calls `write` with a stream on a temporary file in the target's directory; on success the
// temporary file replaces `path` atomically, on any exception it is removed and the exception
// propagates. A target that exists and is not a regular file (a device, a FIFO) is written
// directly. Throws IoError when the target is a directory or the directory is not writable.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

}  // namespace fspm
