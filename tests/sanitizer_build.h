// Which sanitizer this test build runs under (scripts/test_sanitizers.sh,
// test_tsan.sh): GCC names them by macros, Clang by __has_feature.
#pragma once

#if defined(__has_feature)
#define FH_HAS_FEATURE(x) __has_feature(x)
#else
#define FH_HAS_FEATURE(x) 0
#endif

namespace fh {

// AddressSanitizer or ThreadSanitizer: malloc is theirs, not glibc's, and
// everything runs several times slower.
inline constexpr bool kMallocSanitized =
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__) || FH_HAS_FEATURE(address_sanitizer) || \
    FH_HAS_FEATURE(thread_sanitizer)
    true;
#else
    false;
#endif

// Any sanitizer, UndefinedBehaviorSanitizer included.
inline constexpr bool kSanitized =
#if defined(__SANITIZE_UNDEFINED__) || FH_HAS_FEATURE(undefined_behavior_sanitizer)
    true;
#else
    kMallocSanitized;
#endif

}  // namespace fh

#undef FH_HAS_FEATURE
