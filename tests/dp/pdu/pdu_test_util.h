#pragma once
// Test helpers for the PDU codecs.

#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <gtest/gtest.h>

#include <variant>
#include <vector>

namespace rs4sim::dp::pdu::testing {

using Bytes = std::vector<std::uint8_t>;

inline Bytes to_bytes(const fdl::DataUnit& du) { return Bytes(du.begin(), du.end()); }

// Encodes with `f(value, out)` and returns the bytes; fails the test on an error.
template <class F, class T>
Bytes encoded(F f, const T& value) {
  fdl::DataUnit out;
  const auto r = f(value, out);
  EXPECT_TRUE(r) << r.error().message();
  return to_bytes(out);
}

// Encodes with the codec's `encode(value, out)` overload (found by argument-dependent lookup)
// and returns the bytes; fails the test on an error.
template <class T>
Bytes enc(const T& value) {
  fdl::DataUnit out;
  const auto r = encode(value, out);
  EXPECT_TRUE(r) << r.error().message();
  return to_bytes(out);
}

// The known answer `du` decodes with `decode` to the alternative T equal to `expected`, and
// `expected` encodes back to `du`.
template <class T, class Decode>
void expect_known_answer(Decode decode, const Bytes& du, const T& expected) {
  const auto r = decode(du);
  ASSERT_TRUE(r) << r.error().message();
  const T* decoded = std::get_if<T>(&r.value());
  ASSERT_NE(decoded, nullptr);
  EXPECT_EQ(*decoded, expected);
  EXPECT_EQ(enc(expected), du);
}

// The error of a failed result (fails the test if it succeeded).
template <class R>
std::error_code error_of(const R& r) {
  EXPECT_FALSE(r.has_value());
  return r.has_value() ? std::error_code{} : r.error();
}

}  // namespace rs4sim::dp::pdu::testing
