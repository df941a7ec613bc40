// fuzz_adapter_acyclic: arbitrary sequences of DPV1 WRITE/READ (both channels, any slot,
// index and record), cyclic exchanges with arbitrary output bytes through a real FHost,
// time steps and user actions (PC adapter, proxy hooks, restart button, faults, obstacle).
// Invariants: no crash, every answer ≤ 240 bytes, and the OSSD bit is 1 only when the
// conditions of [RS4 manual §5.1.1, §5.1.2, §7.1, §7.2] hold (re-stated here independently of
// the adapter's own predicate; the RS4's OSSDs as the adapter sees them, 10 ms late).
#include "profisafe/f_host.h"
#include "rs4/adapter/adapter.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <span>
#include <vector>

namespace {

using namespace rs4sim;
using namespace std::chrono_literals;

struct Input {
  std::span<const std::uint8_t> d;
  std::size_t i = 0;
  bool empty() const { return i >= d.size(); }
  std::uint8_t byte() { return empty() ? 0 : d[i++]; }
};

// When the harness last saw the RS4's OSSDs go off: the adapter shows the RS4 10 ms late
// ("Reaktionszeit PROFIsafe-Adapter 10 ms" [RS4 manual, technical data]).
struct Rs4Watch {
  bool was_on = false;
  std::optional<dp::TimePoint> off_at;
  void observe(const rs4::adapter::Adapter& a, dp::TimePoint now) {
    const bool on = a.scanner().ossd();
    if (was_on && !on) off_at = now;
    was_on = on;
  }
  bool on_within(const rs4::adapter::Adapter& a, dp::TimePoint now, dp::Duration lag) const {
    return a.scanner().ossd() || (off_at && now < *off_at + lag);
  }
};

void check_ossd_invariant(const rs4::adapter::Adapter& a, const Rs4Watch& rs4, dp::TimePoint now,
                          dp::Duration lag) {
  if (!a.ossd_bit()) return;
  const auto v = a.view();
  // An output byte with a reserved bit set is not applied: the pair applied before it stays in
  // force [docs/decisions.md#rs4-inconsistent-outputs], and an invalid one shows as fperr.
  const bool pair_ok = v.output.field_pair_valid() || v.output.reserved != 0;
  const bool allowed = v.powered && v.connected && a.fdevice().sends_process_values() &&
                       a.released() && !v.field_pair_error && rs4.on_within(a, now, lag) && pair_ok;
  if (!allowed) {
    std::fprintf(
        stderr,
        "OSSD bit 1: powered %d connected %d fdev %d released %d fperr %d scanner %d pair %d\n",
        v.powered, v.connected, a.fdevice().sends_process_values(), a.released(),
        v.field_pair_error, rs4.on_within(a, now, lag), pair_ok);
    std::abort();
  }
}

void cyclic(rs4::adapter::Adapter& a, profisafe::FHost& host, std::uint8_t out, dp::TimePoint now) {
  host.set_output(std::span<const std::uint8_t>(&out, 1));
  const auto req = host.request(now);
  const std::vector<std::uint8_t> pdu(req.begin(), req.end());
  a.on_outputs(pdu, now);
  std::array<std::uint8_t, 5> in{};
  a.read_inputs(in, now);
  host.on_pdu(in, now);
}

void acyclic(rs4::adapter::Adapter& a, Input& in, bool write, dp::TimePoint now) {
  dp::slave::AcyclicRequest r;
  const auto sel = in.byte();
  r.channel = (sel & 1) ? dp::slave::AcyclicChannel::kC2 : dp::slave::AcyclicChannel::kC1;
  r.service = write ? dp::slave::AcyclicService::kWrite : dp::slave::AcyclicService::kRead;
  r.slot = (sel & 2) ? in.byte() : 0;
  r.index = (sel & 4) ? in.byte() : static_cast<std::uint8_t>(2 + ((sel >> 3) & 1));
  r.first_write_after_initiate = (sel & 0x10) != 0;
  std::vector<std::uint8_t> data;
  if (write) {
    const std::size_t n = std::min<std::size_t>(in.byte(), 240);
    for (std::size_t k = 0; k < n && !in.empty(); ++k) data.push_back(in.byte());
    if ((sel & 0x20) && data.size() >= 4) {  // mostly well-formed headers
      data[0] = 0;
      data[1] = static_cast<std::uint8_t>(data.size());
    }
    r.length = static_cast<std::uint8_t>(data.size());
  } else {
    r.length = in.byte();
  }
  r.data = data;
  const auto res = a.on_acyclic(r, now);
  if (res.data.size() > 240) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in{std::span<const std::uint8_t>(data, size)};
  rs4::adapter::AdapterConfig cfg;
  cfg.scanner.boot_duration = 200ms;  // reach operation within a short input
  cfg.init_duration = 50ms;
  rs4::adapter::Adapter a(cfg);
  profisafe::FParameters fp;
  fp.wd_time_ms = 1000;
  profisafe::FHost host(profisafe::FHostConfig{fp, 1, {}});
  dp::TimePoint now{};
  a.power_on(now);
  now += 60ms;
  a.on_time(now);
  dp::pdu::SetPrm prm;
  for (auto b : rs4::adapter::kFBlockHeader) prm.user_data.push_back(b);
  for (auto b : profisafe::encode_f_parameters(fp)) prm.user_data.push_back(b);
  if (a.check_parameters(prm, now) == dp::slave::PrmVerdict::kAccept) {
    a.on_state_change(dp::slave::State::kWaitCfg, dp::slave::State::kDataExch,
                      dp::slave::TransitionReason::kCfgAccepted, now);
  }
  Rs4Watch rs4;
  for (unsigned steps = 0; steps < 256 && !in.empty(); ++steps) {
    const auto op = in.byte();
    switch (op % 12) {
      case 0:
      case 1: acyclic(a, in, true, now); break;
      case 2: acyclic(a, in, false, now); break;
      case 3:
      case 4: cyclic(a, host, in.byte(), now); break;
      case 5:
        now += std::chrono::milliseconds(in.byte() * 10);
        a.on_time(now);
        break;
      case 6: (in.byte() & 1) ? a.attach_pc_adapter(now) : a.detach_pc_adapter(now); break;
      case 7: {
        const auto k = in.byte() % 3;
        (void)(k == 0   ? a.proxy_sync_started(now)
               : k == 1 ? a.proxy_sync_succeeded(now)
                        : a.proxy_sync_failed(now));
        break;
      }
      case 8: a.set_restart_button(in.byte() & 1, now); break;
      case 9: {
        const auto f = static_cast<rs4::scanner::Fault>(in.byte() % 4);
        (void)((op & 0x10) ? a.scanner().clear_fault(f, now) : a.scanner().inject_fault(f, now));
        a.on_time(now);  // the owner's loop runs the adapter after every harness action
        break;
      }
      case 10: {
        auto& scene = a.scanner().edit_scene(now);
        if (op & 0x10)
          scene.clear();
        else
          (void)scene.add(rs4::scanner::Circle{{double(in.byte()) * 10, 0}, 50});
        a.on_time(now);
        break;
      }
      default:
        if (const auto next = a.next_deadline(); next && *next > now && *next - now < 10s) {
          now = *next;
          a.on_time(now);
        }
        break;
    }
    rs4.observe(a, now);
    check_ossd_invariant(a, rs4, now, cfg.response_time);
  }
  return 0;
}
