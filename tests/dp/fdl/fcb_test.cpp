// FCB/FCV rules of [IEC 61158-4-3 FCB/FCV] on both sides.
#include "dp/fdl/fcb.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::fdl {
namespace {

constexpr auto kSrd = RequestFunction::kSrdHigh;

FrameControl fc(std::uint8_t raw) { return FrameControl{raw}; }

Telegram reply_with(std::uint8_t byte) {
  return make_data_telegram(2, 5, FrameControl::response(ResponseStatus::kDataLow), std::nullopt,
                            std::nullopt, std::vector<std::uint8_t>{byte});
}

TEST(FdlFcbInitiator, FirstFrameThenTogglingAsInTheWorkedExample) {
  FcbInitiator m;
  // [docs/references.md#dp-worked-example]: Slave_Diag 6D, Set_Prm 5D, Chk_Cfg 7D, Slave_Diag 5D,
  // DX 7D.
  EXPECT_EQ(m.next(5, kSrd).raw, 0x6D);
  EXPECT_TRUE(m.last_was_first(5));
  EXPECT_EQ(m.next(5, kSrd).raw, 0x5D);
  EXPECT_FALSE(m.last_was_first(5));
  EXPECT_EQ(m.next(5, kSrd).raw, 0x7D);
  EXPECT_EQ(m.next(5, kSrd).raw, 0x5D);
  EXPECT_EQ(m.next(5, RequestFunction::kSrdLow).raw, 0x7C);
}

TEST(FdlFcbInitiator, RetryKeepsTheFcbAndStateIsPerResponder) {
  FcbInitiator m;
  EXPECT_EQ(m.repeat(7, kSrd).raw, 0x6D);  // nothing sent yet: a first frame
  m.next(5, kSrd);
  const FrameControl sent = m.next(5, kSrd);
  EXPECT_EQ(m.repeat(5, kSrd), sent);
  EXPECT_EQ(m.repeat(5, kSrd), sent);
  EXPECT_EQ(m.next(9, kSrd).raw, 0x6D);  // another responder starts fresh
  EXPECT_EQ(m.next(5, kSrd).raw, 0x7D);  // unaffected by responder 9
}

TEST(FdlFcbInitiator, ResponderLostRestartsWithAFirstFrame) {
  FcbInitiator m;
  m.next(5, kSrd);
  m.next(5, kSrd);
  m.responder_lost(5);
  EXPECT_EQ(m.next(5, kSrd).raw, 0x6D);
  m.next(6, kSrd);
  m.reset_all();
  EXPECT_EQ(m.next(6, kSrd).raw, 0x6D);
  EXPECT_EQ(FcbInitiator::unsequenced(RequestFunction::kFdlStatus).raw, 0x49);
  EXPECT_EQ(FcbInitiator::unsequenced(RequestFunction::kSdnHigh).raw, 0x46);
}

TEST(FdlFcbResponder, FirstNewRepeatSequence) {
  FcbResponder s;
  EXPECT_EQ(s.on_request(2, fc(0x6D)), FcbVerdict::kFirst);  // FCV=0 FCB=1
  EXPECT_EQ(s.initiator(), 2);
  s.store_reply(reply_with(0x01));
  EXPECT_EQ(s.on_request(2, fc(0x5D)), FcbVerdict::kNew);  // FCB toggled 1→0
  EXPECT_EQ(s.stored_reply(), nullptr);                    // cleared for the new request
  s.store_reply(reply_with(0x02));
  EXPECT_EQ(s.on_request(2, fc(0x5D)), FcbVerdict::kRepeat);  // same FCB: repetition
  ASSERT_NE(s.stored_reply(), nullptr);
  EXPECT_EQ(s.stored_reply()->data[0], 0x02);                 // the previous reply, not re-executed
  EXPECT_EQ(s.on_request(2, fc(0x5D)), FcbVerdict::kRepeat);  // still a repeat
  EXPECT_EQ(s.on_request(2, fc(0x7D)), FcbVerdict::kNew);
}

TEST(FdlFcbResponder, RepeatedFirstFrameIsExecutedAgain) {
  // [IEC 61158-4-3 FCB/FCV]: the first frame (FCV=0) is not FCB-evaluated; each one restarts the
  // cycle.
  FcbResponder s;
  EXPECT_EQ(s.on_request(2, fc(0x6D)), FcbVerdict::kFirst);
  EXPECT_EQ(s.on_request(2, fc(0x6D)), FcbVerdict::kFirst);
  EXPECT_EQ(s.on_request(2, fc(0x7D)), FcbVerdict::kRepeat);  // FCB=1 equals the stored 1
  EXPECT_EQ(s.on_request(2, fc(0x5D)), FcbVerdict::kNew);
}

TEST(FdlFcbResponder, OtherInitiatorIsNotEvaluatedButTakesOver) {
  FcbResponder s;
  s.on_request(2, fc(0x6D));
  s.on_request(2, fc(0x5D));
  s.store_reply(reply_with(0x02));
  EXPECT_EQ(s.on_request(3, fc(0x5D)), FcbVerdict::kNew);  // same FCB, but another SA
  EXPECT_EQ(s.initiator(), 3);
  EXPECT_EQ(s.stored_reply(), nullptr);
  EXPECT_EQ(s.on_request(3, fc(0x5D)), FcbVerdict::kRepeat);
  EXPECT_EQ(s.on_request(2, fc(0x5D)), FcbVerdict::kNew);  // master 2 again: new SA
}

TEST(FdlFcbResponder, UnsequencedFramesLeaveTheStateAlone) {
  FcbResponder s;
  s.on_request(2, fc(0x6D));
  s.store_reply(reply_with(0x09));
  EXPECT_EQ(s.on_request(2, fc(0x49)), FcbVerdict::kNotEvaluated);  // FDL_Status
  EXPECT_EQ(s.on_request(4, fc(0x46)), FcbVerdict::kNotEvaluated);  // SDN broadcast
  EXPECT_EQ(s.initiator(), 2);
  ASSERT_NE(s.stored_reply(), nullptr);
  EXPECT_EQ(s.on_request(2, fc(0x7D)), FcbVerdict::kRepeat);
}

TEST(FdlFcbResponder, FcvWithoutFirstFrameIsNew) {
  FcbResponder s;
  EXPECT_EQ(s.on_request(2, fc(0x7D)), FcbVerdict::kNew);
  EXPECT_EQ(s.on_request(2, fc(0x7D)), FcbVerdict::kRepeat);
  s.reset();
  EXPECT_FALSE(s.initiator());
  EXPECT_EQ(s.on_request(2, fc(0x7D)), FcbVerdict::kNew);
}

}  // namespace
}  // namespace rs4sim::dp::fdl
