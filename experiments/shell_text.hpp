#pragma once
// Text built from what the user wrote (an experiment's name, a path) that becomes a file name or a
// shell command: a name never leaves the folder it is written in, a path is quoted for the shell.
#include <string>

namespace fspm::experiments {

// `text` single-quoted for a POSIX shell ('it'\''s'), so a printed command can be pasted as is.
std::string shell_quote(const std::string& text);

// A file name made from `name` that stays in the current folder: letters, digits, '.', '-', '_'
// and '+' kept, every other byte ('/', spaces, control characters, ...) replaced by '_', and a
// leading '.' replaced too, so "../escaped" gives "_._escaped" and never "." or "..". A leading
// '-' is replaced as well: "-rf" gives "_rf", never a name that sbatch or rm reads as an option.
std::string file_stem_from_name(const std::string& name);

}  // namespace fspm::experiments
