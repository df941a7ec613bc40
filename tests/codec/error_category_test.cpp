// codec::ErrorCategory: name and messages come from the enum's own functions.
#include "codec/error_category.h"

#include "codec/buffer_error.h"

#include <gtest/gtest.h>

#include <string>

namespace rs4sim::codec::testing {

enum class SampleError : std::uint8_t { kFirst = 1, kSecond };
std::string_view to_string(SampleError e) noexcept {
  return e == SampleError::kFirst ? "first" : "second";
}
constexpr const char* error_category_name(SampleError) noexcept { return "sample"; }
inline std::error_code make_error_code(SampleError e) noexcept { return make_error_code_of(e); }

enum class WireError : std::uint16_t { kA = 0x2A04 };
std::string_view to_string(WireError) noexcept { return "telegram not processed"; }
constexpr const char* error_category_name(WireError) noexcept { return "wire"; }
std::string error_message(WireError e) {
  return std::to_string(static_cast<int>(e)) + ": " + std::string(to_string(e));
}

}  // namespace rs4sim::codec::testing

template <>
struct std::is_error_code_enum<rs4sim::codec::testing::SampleError> : std::true_type {};

namespace rs4sim::codec::testing {
namespace {

TEST(ErrorCategoryTest, NameAndMessageComeFromTheEnum) {
  const std::error_code ec = SampleError::kSecond;
  EXPECT_STREQ(ec.category().name(), "sample");
  EXPECT_EQ(ec.message(), "second");
  EXPECT_EQ(ec.value(), 2);
  EXPECT_EQ(&ec.category(), &category_of<SampleError>());  // one instance
  EXPECT_EQ(ec, make_error_code(SampleError::kSecond));
  EXPECT_NE(ec, make_error_code(SampleError::kFirst));
}

TEST(ErrorCategoryTest, ErrorMessageOverridesToString) {
  EXPECT_EQ(make_error_code_of(WireError::kA).message(), "10756: telegram not processed");
}

TEST(ErrorCategoryTest, BufferErrorHasACategory) {
  EXPECT_STREQ(make_error_code(BufferError::kReadPastEnd).category().name(), "codec");
  EXPECT_EQ(make_error_code(BufferError::kWritePastEnd).message(),
            "write past the end of the buffer");
}

}  // namespace
}  // namespace rs4sim::codec::testing
