#pragma once
// Test harness: one dp::slave::Slave with a FakeApplication on a manual clock, driven with wire
// bytes. Frames are framed here with an independent SD/LE/FCS/ED helper
// ([IEC 61158-4-3 frame formats, FCS]), not with the code under test; the slave's reply is encoded
// with fdl::encode and compared byte for byte.

#include "dp/fdl/decoder.h"
#include "dp/fdl/telegram.h"
#include "dp/slave/slave.h"
#include "dp/time/clock.h"
#include "tests/dp/slave/fake_application.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <vector>

namespace rs4sim::dp::testing {
using namespace ::rs4sim::dp::slave;  // the slave under test

// [IEC 61158-4-3 FCS]: FCS = sum of DA…last DU byte mod 256.
inline std::uint8_t fcs_of(const Bytes& body) {
  unsigned sum = 0;
  for (auto b : body) sum += b;
  return static_cast<std::uint8_t>(sum & 0xFF);
}
// SD2: 68 LE LEr 68 <body = DA SA FC [DSAP SSAP] DU> FCS 16 ([IEC 61158-4-3 frame formats]).
inline Bytes sd2(const Bytes& body) {
  Bytes f{0x68, static_cast<std::uint8_t>(body.size()), static_cast<std::uint8_t>(body.size()),
          0x68};
  f.insert(f.end(), body.begin(), body.end());
  f.push_back(fcs_of(body));
  f.push_back(0x16);
  return f;
}
// SD1: 10 DA SA FC FCS 16 ([IEC 61158-4-3 frame formats]).
inline Bytes sd1(std::uint8_t da, std::uint8_t sa, std::uint8_t fc) {
  return {0x10, da, sa, fc, fcs_of({da, sa, fc}), 0x16};
}
inline const Bytes kSc{0xE5};

// The [docs/references.md#dp-worked-example] slave: address 5, ident 0x1234, DPV1, 1 byte in / 1
// byte out.
inline Config example_config() {
  Config c;
  c.address = 5;
  c.ident_number = 0x1234;
  c.dpv1 = true;
  c.sync_supported = true;
  c.freeze_supported = true;
  c.set_slave_add_supported = true;
  c.fail_safe_supported = true;
  c.c2_supported = true;
  return c;
}

class SlaveHarness {
 public:
  explicit SlaveHarness(const Config& cfg = example_config()) : slave(cfg, app) {}

  ManualClock clock;
  FakeApplication app;
  Slave slave;

  // Delivers one complete frame and returns the reply's wire bytes (empty = no reply).
  Bytes send(const Bytes& frame) {
    fdl::Telegram t;
    const auto ec = fdl::decode_frame(frame, t);
    EXPECT_FALSE(ec) << "test frame does not decode: " << ec.message();
    slave.on_telegram(t, clock.now());
    auto reply = slave.take_transmit();
    EXPECT_FALSE(slave.take_transmit().has_value()) << "more than one reply";
    Bytes out;
    if (reply) fdl::encode(*reply, out);
    return out;
  }
  // Moves the clock like a link would: on_time() whenever the deadline has passed.
  void advance(Duration d) {
    clock.advance(d);
    const auto deadline = slave.next_deadline();
    if (deadline && clock.now() >= *deadline) slave.on_time(clock.now());
  }

  // Master 2 → slave 5 with the FCB sequence of [IEC 61158-4-3 FCB/FCV]: 6D first, then 5D/7D
  // alternating.
  std::uint8_t next_fc() {
    if (first_) {
      first_ = false;
      fcb_ = true;
      return 0x6D;
    }
    fcb_ = !fcb_;
    return fcb_ ? 0x7D : 0x5D;
  }
  // A DP service request: DA 5|0x80, SA 2|0x80, FC, DSAP, SSAP, DU.
  Bytes dp(std::uint8_t dsap, const Bytes& du, std::uint8_t ssap = 0x3E) {
    Bytes body{0x85, 0x82, next_fc(), dsap, ssap};
    body.insert(body.end(), du.begin(), du.end());
    return sd2(body);
  }
  Bytes dx(const Bytes& outputs) {
    const std::uint8_t fc = next_fc();
    if (outputs.empty()) return sd1(0x05, 0x02, fc);
    Bytes body{0x05, 0x02, fc};
    body.insert(body.end(), outputs.begin(), outputs.end());
    return sd2(body);
  }
  // A slave reply carrying SAPs: DA 2|0x80, SA 5|0x80, FC, DSAP, SSAP, DU.
  static Bytes reply(std::uint8_t fc, std::uint8_t dsap, std::uint8_t ssap, const Bytes& du) {
    Bytes body{0x82, 0x85, fc, dsap, ssap};
    body.insert(body.end(), du.begin(), du.end());
    return sd2(body);
  }

  // [docs/references.md#dp-worked-example]: Set_Prm (Lock+WD_On, 10·1·10 ms, minTSDR 11, ident
  // 1234, DPV1 80 20 00).
  static Bytes example_prm() {
    return {0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x20, 0x00};
  }

  // Runs Set_Prm + Chk_Cfg ([docs/references.md#dp-worked-example]) and checks that the slave is in
  // Data_Exch.
  void to_data_exchange(const Bytes& prm = example_prm(), const Bytes& cfg = {0x10, 0x20}) {
    EXPECT_EQ(send(dp(0x3D, prm)), kSc);
    EXPECT_EQ(send(dp(0x3E, cfg)), kSc);
    EXPECT_EQ(slave.state(), State::kDataExch);
  }
  // Fetches the diagnosis as the owner; returns the DU after DSAP/SSAP.
  Bytes diag() {
    const Bytes r = send(dp(0x3C, {}));
    if (r.size() < 12) return {};
    return Bytes(r.begin() + 9, r.end() - 2);
  }

 private:
  bool first_ = true;
  bool fcb_ = false;  // FCB of the last frame sent
};

}  // namespace rs4sim::dp::testing
