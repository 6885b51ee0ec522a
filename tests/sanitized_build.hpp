// Whether this test build runs under AddressSanitizer (.ci/run stages 2 and
// 3). There the longest sweeps take every k-th case: memory errors do not
// depend on the binade, and stage 1 runs each sweep in full.
#pragma once

#if defined(__SANITIZE_ADDRESS__)  // g++
#define DLAB_TEST_SANITIZED 1
#elif defined(__has_feature)  // clang
#if __has_feature(address_sanitizer)
#define DLAB_TEST_SANITIZED 1
#endif
#endif

namespace dlab::test {

#ifdef DLAB_TEST_SANITIZED
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

}  // namespace dlab::test
