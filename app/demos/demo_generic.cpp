// The generic demo of `rs4sim demo --device generic` (app/demos/demos.h): our class 1 master and
// two generic slaves on the in-memory bus, on a manual clock with the 1.5 Mbit/s wire
// modelled. Narrates start-up, data exchange, a DPV1 write/read, an alarm round trip and a
// watchdog fault with recovery; exits 0 when every step did what the standard says and 1
// otherwise (CI runs it).
#include "app/demos/demo_narrator.h"
#include "app/demos/demos.h"
#include "app/demos/narration.h"
#include "dp/devices/generic_bus.h"

#include <ostream>
#include <variant>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using dp::devices::GenericBus;

class Demo {
 public:
  Demo(std::ostream& out, bool realtime, RunSession& session)
      : bus_(config()),
        n_(out, bus_.clock(), run_until(realtime, session), Narration::Stamp::kMilliseconds) {
    bus_.bus().add_observer([this](const dp::link::BusEvent& e) { on_wire(e); });
    for (std::uint8_t a : {std::uint8_t{5}, std::uint8_t{6}}) {
      bus_.slave(a).slave().set_trace([this, a](const dp::slave::Transition& t) {
        say("slave " + std::to_string(a) + " " + dp::slave::to_string(t.from) + " -> " +
            dp::slave::to_string(t.to) + " (" + dp::slave::to_string(t.why) + ")");
      });
    }
  }
  dp::link::MemoryBus& bus() { return bus_.bus(); }
  RunUntil run_until(bool realtime, RunSession& session) {
    RunUntil run = [this](const std::function<bool()>& done, dp::Duration limit) {
      return bus_.run_until(done, limit);
    };
    return in_session(std::move(run), bus_.clock(), realtime, session);
  }
  int run() {
    return run_story(n_, {[this] { return start_up(); }, [this] { return data_exchange(); },
                          [this] { return dpv1(); }, [this] { return alarm(); },
                          [this] { return watchdog(); }});
  }

 private:
  static dp::devices::GenericBusConfig config() {
    dp::devices::GenericBusConfig c;
    c.master_address = 1;
    c.slaves = {{5, 0x1234, {0x10, 0x20}, true}, {6, 0x4711, {0x31}, true}};  // 1+1 B, 2+2 B
    c.bus.wire_model = dp::BaudRate::k1M5;
    c.baud = dp::BaudRate::k1M5;
    return c;
  }
  void say(const std::string& text) const { n_.say(text); }
  void on_wire(const dp::link::BusEvent& e) {
    if (!verbose_ || e.telegram->type == dp::fdl::FrameType::kToken) return;
    const std::string to = e.to ? (*e.to == 127 ? "all" : std::to_string(*e.to)) : "?";
    std::string line = std::to_string(e.from) + " -> " + to + "  " + narrate::describe(*e.telegram);
    if (e.fate != dp::link::Fate::kDelivered) line += std::string("  [") + to_string(e.fate) + "]";
    say(line);
  }
  bool check(bool ok, const std::string& what) const { return n_.check(ok, what); }
  template <class E>
  const E* last() const {
    for (auto it = bus_.events().rbegin(); it != bus_.events().rend(); ++it) {
      if (const auto* e = std::get_if<E>(&*it)) return e;
    }
    return nullptr;
  }
  bool start_up();
  bool data_exchange();
  bool dpv1();
  bool alarm();
  bool watchdog();
  bool dpv1_result(std::uint32_t id);

  GenericBus bus_;
  Narration n_;
  bool verbose_ = true;
};

bool Demo::start_up() {
  n_.print(
      "== 1. Start-up ([IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py]): "
      "master 1 claims the token, then FDL_Status, Slave_Diag, "
      "Set_Prm, Chk_Cfg, Slave_Diag per slave\n");
  return check(bus_.run_until([&] { return bus_.slaves_in_data_exchange() == 2; }, 2s),
               "both slaves reach Data_Exch within 2 s");
}

bool Demo::data_exchange() {
  n_.print("\n== 2. Data exchange: outputs are looped back to the inputs by the generic device\n");
  const std::vector<std::uint8_t> o5 = {0xA5}, o6 = {0xCA, 0xFE};
  bus_.master().set_outputs(5, o5);
  bus_.master().set_outputs(6, o6);
  const auto looped = [&] {
    const auto i5 = bus_.master().inputs(5), i6 = bus_.master().inputs(6);
    return std::equal(i5.begin(), i5.end(), o5.begin(), o5.end()) &&
           std::equal(i6.begin(), i6.end(), o6.begin(), o6.end());
  };
  const bool ok = bus_.run_until(looped, 100ms);
  verbose_ = false;
  bus_.run_for(1s);
  say("1 s later: " + std::to_string(bus_.master().counters().cycles) + " cycles, slave 6 inputs " +
      hex(bus_.master().inputs(6)));
  return check(ok, "inputs equal the outputs");
}

bool Demo::dpv1_result(std::uint32_t id) {
  const bool done = bus_.run_until(
      [&] {
        const auto* r = last<dp::master::Dpv1Result>();
        return r && r->id == id;
      },
      2s);
  return check(done && !last<dp::master::Dpv1Result>()->error,
               "DPV1 request " + std::to_string(id) + " succeeds");
}

bool Demo::dpv1() {
  n_.print(
      "\n== 3. DPV1 class-1 write and read of record slot 1 index 7 on slave 6 "
      "([IEC 61158-6-3 MSAC_C1, MSAC_C1 polling])\n");
  verbose_ = true;
  const std::vector<std::uint8_t> rec = {0x01, 0x02, 0x03};
  const auto w = bus_.master().write(6, 1, 7, rec);
  if (!check(w.has_value() && dpv1_result(w.value()), "write")) return false;
  const auto r = bus_.master().read(6, 1, 7, 16);
  if (!check(r.has_value() && dpv1_result(r.value()), "read")) return false;
  const auto& data = last<dp::master::Dpv1Result>()->data;
  return check(std::equal(data.begin(), data.end(), rec.begin(), rec.end()),
               "read returns what was written");
}

bool Demo::alarm() {
  n_.print(
      "\n== 4. Alarm round trip ([IEC 61158-6-3 DPV1 alarms]): slave 5 raises a process alarm; DH, "
      "diagnosis, "
      "Alarm_Ack\n");
  const std::vector<std::uint8_t> user = {0x42};
  if (!check(!bus_.slave(5).device().raise_alarm(2, 0, user), "alarm accepted by the slave"))
    return false;
  const bool acked =
      bus_.run_until([&] { return !bus_.slave(5).device().acknowledged_alarms().empty(); }, 1s);
  return check(acked && last<dp::master::AlarmReceived>() != nullptr,
               "master sees and acknowledges the alarm");
}

bool Demo::watchdog() {
  n_.print(
      "\n== 5. Watchdog ([IEC 61158-6-3 watchdog]): the master falls silent for 150 ms (T_WD = 100 "
      "ms), then "
      "returns\n");
  verbose_ = false;
  bus_.bus().set_silenced(1, true);
  const bool dropped = bus_.run_until(
      [&] { return bus_.slave(5).slave().state() == dp::slave::State::kWaitPrm; }, 150ms);
  bus_.run_for(50ms);
  bus_.bus().set_silenced(1, false);
  say("master back on the bus");
  const bool back = bus_.run_until(
      [&] {
        return bus_.slaves_in_data_exchange() == 2 &&
               bus_.slave(5).slave().state() == dp::slave::State::kDataExch &&
               bus_.slave(6).slave().state() == dp::slave::State::kDataExch;
      },
      2s);
  say("both slaves in Data_Exch again");
  return check(dropped, "slave 5 leaves Data_Exch on watchdog expiry") &&
         check(back, "recovery to Data_Exch");
}

}  // namespace

int run_generic_demo(RunSession& session, std::ostream& out, const DemoOptions& options) {
  Demo demo(out, options.realtime, session);
  const auto capture = open_capture(options.capture);
  attach_capture(capture.get(), demo.bus());
  return demo.run();
}

}  // namespace rs4sim::app
