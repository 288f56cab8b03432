// Whether this test binary runs under AddressSanitizer (the sanitizer pass of scripts/test): tests
// then run a smaller instance of the same code path, the Release pass the full one.
#pragma once
// GCC defines __SANITIZE_ADDRESS__; clang (the sanitizer build's compiler) only answers
// __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif
