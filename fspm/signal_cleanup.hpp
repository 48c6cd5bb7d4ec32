#pragma once
// What a stopped command must not leave behind. SIGINT and SIGTERM end a process without
// unwinding its stack, so the temporaries of atomic writes (fspm/atomic_file.hpp) and the output
// folders a command created for outputs it had not written yet would stay. The paths registered
// here are removed by the signal's handler (unlink, or rmdir for an empty folder: both safe in a
// handler), which then ends the process with the signal's default action, so a shell still sees
// 130 for SIGINT and 143 for SIGTERM.
#include <string>

namespace fspm {

// Installs the handler for SIGINT and SIGTERM (once; later calls do nothing). Programs call it at
// start; a command that handles the signals itself restores this handler when it is done.
void install_signal_cleanup();

// Registers `path` to be removed should a signal end the process; returns a handle for
// unregister_signal_cleanup, or -1 when the table is full (the path is then not cleaned up).
int register_signal_cleanup(const std::string& path);

// Forgets the path registered as `handle` (ignored when -1).
void unregister_signal_cleanup(int handle);

// The handler itself: removes every registered path, then re-raises `signal` with its default
// action. Exposed for commands that install their own handler and chain to it.
extern "C" void fspm_signal_cleanup_handler(int signal);

}  // namespace fspm
