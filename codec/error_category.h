#pragma once
// One std::error_category for every error enum of the project (lely-core's SdoErrc and
// its category are the model). An error enum E, in its own namespace, provides:
//
//   std::string_view to_string(E e) noexcept;              // the message of each value
//   constexpr const char* error_category_name(E) noexcept;  // e.g. "dp.pdu"
//   inline std::error_code make_error_code(E e) noexcept { return codec::make_error_code_of(e); }
//
// and optionally `std::string error_message(E)` when the category message should say more
// than to_string (e.g. prefix the wire value). codec::category_of<E>() is the category.
// Such an E converts implicitly to std::error_code: std::is_error_code_enum<E> holds for
// every ErrorEnum (the partial specialization at the end of this header).

#include <concepts>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>

namespace rs4sim::codec {

template <class E>
concept ErrorEnum = std::is_enum_v<E> && requires(E e) {
  { to_string(e) } -> std::convertible_to<std::string_view>;
  { error_category_name(e) } -> std::convertible_to<const char*>;
};

template <ErrorEnum E>
class ErrorCategory final : public std::error_category {
 public:
  [[nodiscard]] const char* name() const noexcept override { return error_category_name(E{}); }
  [[nodiscard]] std::string message(int value) const override {
    const auto e = static_cast<E>(value);
    if constexpr (requires {
                    { error_message(e) } -> std::convertible_to<std::string>;
                  }) {
      return error_message(e);
    } else {
      return std::string(to_string(e));
    }
  }
};

// The single instance of E's category (compared by address inside std::error_code).
template <ErrorEnum E>
[[nodiscard]] const std::error_category& category_of() noexcept {
  static const ErrorCategory<E> category;
  return category;
}

template <ErrorEnum E>
[[nodiscard]] std::error_code make_error_code_of(E e) noexcept {
  return {static_cast<int>(e), category_of<E>()};
}

}  // namespace rs4sim::codec

// Opts every ErrorEnum into std::error_code's converting constructor, which then finds
// make_error_code(E) by argument-dependent lookup in E's namespace.
namespace std {
template <rs4sim::codec::ErrorEnum E>
struct is_error_code_enum<E> : true_type {};
}  // namespace std
