#pragma once
// Developers' safety net: checks of the engine's and contact's invariants (index ranges, finite
// forces, the element colouring's independence) that cost too much for a production run. They
// are compiled in the sanitizer build and in Debug builds (PLYFORM_CHECK_INVARIANTS, set by
// cmake/sanitizers.cmake), where the whole test suite runs through them; a broken invariant is
// a programming error, not a deck error, so it prints where it broke and aborts.

#include <cstdio>
#include <cstdlib>

#ifdef PLYFORM_CHECK_INVARIANTS
#define PLYFORM_INVARIANT(condition, what)                                                      \
  do {                                                                                          \
    if (!(condition)) {                                                                         \
      std::fprintf(stderr, "plyform: invariant broken at %s:%d: %s (%s)\n", __FILE__, __LINE__, \
                   what, #condition);                                                           \
      std::abort();                                                                             \
    }                                                                                           \
  } while (false)
#else
// Not evaluated (sizeof's operand), but the names in it still count as used.
#define PLYFORM_INVARIANT(condition, what) \
  do {                                     \
    (void)sizeof(condition);               \
    (void)sizeof(what);                    \
  } while (false)
#endif

namespace plyform::core {
/// Whether this build checks the invariants.
constexpr bool kCheckInvariants =
#ifdef PLYFORM_CHECK_INVARIANTS
    true;
#else
    false;
#endif
}  // namespace plyform::core
