#pragma once
// Test helper: whether this is the sanitizer build (Debug + ASan + UBSan, ~20x slower), where
// the heaviest property tests run on fewer cases (tests/CMakeLists.txt defines the macro).
namespace selfalign::testing_support {
#ifdef SELFALIGN_SANITIZED_TESTS
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
}  // namespace selfalign::testing_support
