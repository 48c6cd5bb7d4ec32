#pragma once
// FSPM_DCHECK(condition, message): an internal invariant of the library, checked while NDEBUG is
// not defined (Debug and sanitizer builds) and compiled out in Release, where the condition is
// not evaluated. A failed check is a bug in fspm, not a user mistake (those throw fspm::Error):
// it prints the condition, the message and the place to stderr and aborts, so a debugger or a
// sanitizer run stops where the invariant broke.

namespace fspm::detail {
[[noreturn]] void dcheck_failed(const char* condition, const char* message, const char* file,
                                int line);
}  // namespace fspm::detail

#ifdef NDEBUG
// Still compiled, so the names in it count as used, but never evaluated (false && ...).
#define FSPM_DCHECK(condition, message) static_cast<void>(false && static_cast<bool>(condition))
#else
#define FSPM_DCHECK(condition, message) \
  (static_cast<bool>(condition)         \
       ? static_cast<void>(0)           \
       : ::fspm::detail::dcheck_failed(#condition, message, __FILE__, __LINE__))
#endif
