// Whether this test binary was built with AddressSanitizer (the debug-asan preset): its shadow
// memory reserves terabytes of address space and inflates the resident size, so address-space
// limits and peak-memory bounds cannot be tested under it.
#pragma once

namespace gt::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool under_address_sanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool under_address_sanitizer = true;
#else
inline constexpr bool under_address_sanitizer = false;
#endif
#else
inline constexpr bool under_address_sanitizer = false;
#endif

}  // namespace gt::testing
