#pragma once
// Warnings of the libraries about doubtful input (centimetres read as metres, a value that is
// not of its declared type): one handler for the process. The command line logs them on stderr,
// Python raises them as UserWarning; the default handler writes "warning: ..." to stderr.
#include <functional>
#include <string>

namespace fspm {

using WarningHandler = std::function<void(const std::string& message)>;

// Replaces the handler (an empty one restores the default); returns the previous one.
WarningHandler set_warning_handler(WarningHandler handler);
void warn(const std::string& message);

}  // namespace fspm
