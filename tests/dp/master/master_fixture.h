#pragma once
// Test helpers for the class 1 master: a manual clock, the [docs/references.md#dp-worked-example]
// worked-example configuration (master 2, slave 5, ident 0x1234) and byte-level send/expect
// helpers. Slave replies are written as annotated wire bytes and decoded with fdl::decode_frame.

#include "dp/fdl/decoder.h"
#include "dp/fdl/telegram.h"
#include "dp/master/master.h"
#include "dp/master/master_error.h"
#include "dp/time/clock.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace rs4sim::dp::master::testing {

using Bytes = std::vector<std::uint8_t>;

// [IEC 61158-4-3 FCS]: FCS = sum of DA..last DU byte mod 256, written here independently of the
// codec.
inline std::uint8_t fcs(std::initializer_list<std::uint8_t> da_to_du) {
  unsigned sum = 0;
  for (auto b : da_to_du) sum += b;
  return static_cast<std::uint8_t>(sum & 0xFF);
}

inline std::string hex(const Bytes& b) {
  static const char* d = "0123456789ABCDEF";
  std::string s;
  for (auto x : b) {
    if (!s.empty()) s += ' ';
    s += d[x >> 4];
    s += d[x & 15];
  }
  return s;
}

// The slave of the [docs/references.md#dp-worked-example] worked example: address 5, ident 0x1234,
// Set_Prm `88 0A 01 0B 12 34 00 80 20 00` (Lock+WD_On, WD 10·10·1, minTSDR 11, group 0, DPV1 80
// 20 00), Chk_Cfg `10 20` (1 byte in, 1 byte out).
inline SlaveEntry example_slave(std::uint8_t address = 5) {
  SlaveEntry s;
  s.address = address;
  s.prm.station_status.lock_req = true;
  s.prm.station_status.wd_on = true;
  s.prm.wd_fact_1 = 10;
  s.prm.wd_fact_2 = 1;
  s.prm.min_tsdr = 11;
  s.prm.ident_number = 0x1234;
  s.prm.group_ident = 0;
  pdu::Dpv1Status dpv1;
  dpv1.dpv1_enable = true;
  dpv1.enable_diagnostic_alarm = true;
  s.prm.dpv1 = dpv1;
  s.cfg = {0x10, 0x20};
  s.input_length = 1;
  s.output_length = 1;
  return s;
}

inline MasterConfig example_master() {
  MasterConfig m;
  m.address = 2;
  m.bus = BusParameters::defaults_for(BaudRate::k1M5);
  m.claim_token = false;
  m.cycle_target = std::chrono::milliseconds(10);
  m.slaves = {example_slave()};
  return m;
}

class MasterFixture {
 public:
  explicit MasterFixture(MasterConfig cfg = example_master()) : master(std::move(cfg)) {}

  // Advances the clock from deadline to deadline (never backwards), running on_time at
  // each, until the master transmits something (at most `max_wakeups` times); returns the
  // transmitted bytes (empty if nothing).
  Bytes step(int max_wakeups = 4) {
    for (int i = 0; i < max_wakeups; ++i) {
      if (auto d = master.next_deadline(); d && *d > clock.now()) clock.set(*d);
      master.on_time(clock.now());
      Bytes out = drain();
      if (!out.empty()) return out;
    }
    return {};
  }
  // Runs on_time at the current time without advancing.
  Bytes poke() {
    master.on_time(clock.now());
    return drain();
  }
  Bytes drain() {
    Bytes out;
    while (auto t = master.take_transmit()) fdl::encode(*t, out);
    return out;
  }
  // Delivers a reply given as wire bytes (one frame).
  void reply(const Bytes& frame) {
    fdl::Telegram t;
    const auto ec = fdl::decode_frame(frame, t);
    ASSERT_FALSE(ec) << "test frame does not decode: " << ec.message() << " " << hex(frame);
    master.on_telegram(t, clock.now());
  }
  // Removes and returns the events of type E raised so far (others stay for later).
  template <class E>
  std::vector<E> events() {
    master.take_events(log);
    std::vector<E> out;
    std::vector<MasterEvent> rest;
    for (auto& e : log) {
      if (auto* p = std::get_if<E>(&e))
        out.push_back(*p);
      else
        rest.push_back(std::move(e));
    }
    log = std::move(rest);
    return out;
  }

  // Runs the [docs/references.md#dp-worked-example] start-up of the example slave 5 to its first
  // Data_Exchange (FCB sequence 6D 5D 7D 5D 7D); the next frame to slave 5 has FC x5 with FCB=0.
  void bring_to_dx() {
    step();
    reply({0x10, 0x02, 0x05, 0x00, 0x07, 0x16});  // FDL_Status: slave, OK
    step();
    reply({0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x3E, 0x3C, 0x02, 0x05, 0x00, 0xFF, 0x12, 0x34,
           0xD5, 0x16});  // diag: Not_Ready, Prm_Req, Master_Add FF
    step();
    reply({0xE5});  // Set_Prm
    step();
    reply({0xE5});  // Chk_Cfg
    step();
    reply({0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x3E, 0x3C, 0x00, 0x0C, 0x00, 0x02, 0x12, 0x34,
           0xDD, 0x16});                                                  // diag: ready, master 2
    step();                                                               // DX 7D
    reply({0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0x3C, 0x4B, 0x16});  // DL, in 3C
    ASSERT_TRUE(step(1).empty());  // the turn ends; the next cycle is not yet due
    ASSERT_TRUE(master.slave_status(5)->state == PollState::kDataExchange);
    log.clear();
    master.take_events();
  }

  ManualClock clock;
  Master master;
  std::vector<MasterEvent> log;
};

}  // namespace rs4sim::dp::master::testing
