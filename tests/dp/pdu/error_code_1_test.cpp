// DPV1 Error_Code_1 as an enum class with its category [IEC 61158-6-3, DPV1 Error_Code_1].
#include "dp/pdu/error_code_1.h"

#include "dp/pdu/dpv1.h"
#include "pdu_test_util.h"

namespace rs4sim::dp::pdu {
namespace {

using testing::Bytes;

TEST(ErrorCode1Test, ClassInTheHighNibbleCodeInTheLowNibble) {
  EXPECT_EQ(to_wire(ErrorCode1::kInvalidIndex), 0xB0);
  EXPECT_EQ(error_class(ErrorCode1::kInvalidIndex), ErrorClass::kAccess);
  EXPECT_EQ(error_code(ErrorCode1::kInvalidIndex), 0);
  EXPECT_EQ(to_wire(ErrorCode1::kStateConflict), 0xB5);
  EXPECT_EQ(error_code(ErrorCode1::kStateConflict), 5);
  EXPECT_EQ(error_class(ErrorCode1::kFeatureNotSupported), ErrorClass::kApplication);
  EXPECT_EQ(to_wire(ErrorCode1::kFeatureNotSupported), 0xA9);
  EXPECT_EQ(error_class(ErrorCode1::kResourceBusy), ErrorClass::kResource);
  EXPECT_EQ(to_wire(ErrorCode1::kResourceUnavailable), 0xC3);
  // 0xD0..0xFF are user specific; any byte converts and keeps its value.
  EXPECT_EQ(error_class(error_code_1_from_wire(0xE7)), static_cast<ErrorClass>(0xE));
  EXPECT_EQ(to_string(error_class(error_code_1_from_wire(0xE7))), "user specific");
  EXPECT_EQ(to_string(error_class(error_code_1_from_wire(0x12))), "reserved");
  EXPECT_EQ(to_wire(error_code_1_from_wire(0xE7)), 0xE7);
}

TEST(ErrorCode1Test, ErrorCodeNamesClassAndCode) {
  const std::error_code ec = ErrorCode1::kWriteLengthError;
  EXPECT_STREQ(ec.category().name(), "dp.dpv1");
  EXPECT_EQ(ec.value(), 0xB1);
  EXPECT_EQ(ec.message(), "DPV1 access error: write length error");
  EXPECT_EQ(to_string(ErrorCode1::kInvalidSlot), "invalid slot");
  EXPECT_EQ(make_error_code(error_code_1_from_wire(0xAA)).message(),
            "DPV1 application error: user specific or reserved code");
}

TEST(ErrorCode1Test, NegativeResponseCarriesTheEnumAndTheSameWireByte) {
  const Bytes du{
      0xDE,  // 0 Function_Num: Read | 0x80
      0x80,  // 1 Error_Decode: DPV1
      0xB6,  // 2 Error_Code_1: access / access denied
      0x00,  // 3 Error_Code_2
  };
  const auto r = decode_c1_response(du);
  ASSERT_TRUE(r);
  const auto& neg = std::get<Dpv1Error>(r.value());
  EXPECT_EQ(neg.error_code_1, ErrorCode1::kAccessDenied);
  fdl::DataUnit out;
  ASSERT_TRUE(encode(neg, out));
  EXPECT_EQ(testing::to_bytes(out), du);
}

}  // namespace
}  // namespace rs4sim::dp::pdu
