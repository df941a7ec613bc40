#include "metron/slave_handler.h"

#include <algorithm>
#include <chrono>

namespace rs4sim::metron {
namespace {

using C = Command;

bool is_ossd_command(C c) {
  return c == C::kEnableOssd || c == C::kDisableOssd || c == C::kOssdStandby ||
         c == C::kStartOssdMeasurement || c == C::kStopOssdMeasurement;
}

bool is_request(C c) {  // ignored when broadcast
  return static_cast<unsigned>(c) >= static_cast<unsigned>(C::kStopMeasurement);
}

bool measurements_allowed(const WireTable& t, std::span<const std::uint8_t> fields) {
  return std::all_of(fields.begin(), fields.end(),
                     [&](std::uint8_t f) { return measurement_from_code(t, f).has_value(); });
}

// E2: "the message is correct but the length (or an argument) is not".
bool e2(C c, const SlaveMessage& m, const Options& o) {
  const auto data = m.data();
  switch (c) {
    case C::kStartMeasurement: return m.length != 2 || !measurements_allowed(o.wire, data);
    case C::kRequestBeamStatus:
      return m.length != 2 ||
             !(data[0] == o.wire.all_beams || (data[0] >= 1 && data[0] <= o.beams));
    case C::kRequestMeasurements: return m.length < 2 || !measurements_allowed(o.wire, data);
    default:
      if (is_ossd_command(c) && o.input_type != InputType::kNoFunction) return true;
      return m.length != 1;
  }
}

std::optional<ErrorCase> state_error(C c, const Scene& scene, const SlaveState& s) {
  const bool enabled = s.ossd == OssdFunction::kEnabled;
  if ((c == C::kDisableOssd || c == C::kOssdStandby || c == C::kStartOssdMeasurement) && !enabled)
    return ErrorCase::kE3;
  if (c == C::kStopOssdMeasurement && !s.ossd_measuring) return ErrorCase::kE3;
  if (c == C::kStopMeasurement && !s.measuring) return ErrorCase::kE5;
  if ((c == C::kStartMeasurement || c == C::kStopMeasurement || c == C::kRequestMeasurements) &&
      !scene.synchronised())
    return ErrorCase::kE4;
  return std::nullopt;
}

std::uint8_t clamp_ms(stream::Duration d) {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(d).count();
  return static_cast<std::uint8_t>(std::clamp<long long>(ms, 0, 255));
}

std::uint8_t curtain_status(const Scene& scene, const SlaveState& s) {
  unsigned v = 0;
  if (scene.synchronised()) v |= 0x01U;
  if (s.ossd == OssdFunction::kEnabled) v |= 0x02U;
  if (s.ossd == OssdFunction::kStandby) v |= 0x04U;
  if (s.ossd_measuring) v |= 0x08U;
  if (s.measuring) v |= 0x10U;
  if (scene.any_interrupted()) v |= 0x20U;
  if (scene.input_high()) v |= 0x40U;
  return static_cast<std::uint8_t>(v);
}

// Runs the command; returns the reply data (EXTENSION layouts, [docs/metron.md#replies]).
std::vector<std::uint8_t> execute(C c, const SlaveMessage& m, const Options& o, const Scene& scene,
                                  SlaveState& s) {
  const auto data = m.data();
  switch (c) {
    case C::kResetSoftware: s = SlaveState{}; return {};
    case C::kEnableOssd: s.ossd = OssdFunction::kEnabled; return {};
    case C::kDisableOssd:
      s.ossd = OssdFunction::kDisabled;
      s.ossd_measuring = false;
      return {};
    case C::kOssdStandby: s.ossd = OssdFunction::kStandby; return {};
    case C::kStartOssdMeasurement: s.ossd_measuring = true; return {};
    case C::kStopOssdMeasurement: s.ossd_measuring = false; return {};
    case C::kStartMeasurement:
      s.measuring = measurement_from_code(o.wire, data[0]);
      s.maximum = scene.measure(*s.measuring);
      return {};
    case C::kStopMeasurement: s.measuring.reset(); return {s.maximum};
    case C::kRequestBeamStatus:
      if (data[0] == o.wire.all_beams) return scene.packed(o.wire.beam_bits_lsb_first);
      return {static_cast<std::uint8_t>(scene.interrupted(data[0]) ? 1 : 0)};
    case C::kRequestMeasurements: {
      std::vector<std::uint8_t> out;
      for (const auto f : data) out.push_back(scene.measure(*measurement_from_code(o.wire, f)));
      return out;
    }
    case C::kRequestConfiguration:
      return {static_cast<std::uint8_t>(o.beams), static_cast<std::uint8_t>(o.input_type),
              o.node_enabled ? o.node : std::uint8_t{0}, clamp_ms(o.scan_cycle),
              clamp_ms(o.t_response)};
    case C::kRequestOssdStatus: {
      const auto on = static_cast<std::uint8_t>(ossd_on(s, scene) ? 1 : 0);
      return {on, on};
    }
    case C::kRequestCurtainStatus: return {curtain_status(scene, s)};
  }
  return {};
}

Reaction refuse(ErrorCase e, std::optional<C> c, bool broadcast, const Options& o) {
  Reaction r;
  r.command = c;
  r.error = e;
  r.disposition = broadcast ? Disposition::kBroadcastIgnored : Disposition::kErrorAnswer;
  if (!broadcast) r.reply_code = code_of(o.wire, e);
  return r;
}

}  // namespace

Reaction handle(const SlaveMessage& m, const Options& o, const Scene& scene, SlaveState& s) {
  Reaction r;
  if (m.parity_error) {
    r.disposition = Disposition::kParityRejected;
    return r;
  }
  const bool broadcast = o.node_enabled && m.address == kBroadcast;
  if (o.node_enabled && !broadcast && m.address != o.node) {
    r.disposition = Disposition::kNotForUs;
    return r;
  }
  const auto command = command_from_code(o.wire, m.command());
  if (m.length_too_long || !m.checksum_ok) return refuse(ErrorCase::kE1, command, broadcast, o);
  // DECISION: no command (Length 0) or a code outside the table is a wrong message: E2.
  if (!command || e2(*command, m, o)) return refuse(ErrorCase::kE2, command, broadcast, o);
  if (broadcast && is_request(*command)) {
    r.command = command;
    r.disposition = Disposition::kBroadcastIgnored;
    return r;
  }
  if (const auto e = state_error(*command, scene, s)) return refuse(*e, command, broadcast, o);
  r.command = command;
  r.reply_data = execute(*command, m, o, scene, s);
  r.reset = *command == C::kResetSoftware;
  if (!broadcast && !r.reset) r.reply_code = code_of(o.wire, *command);
  return r;
}

}  // namespace rs4sim::metron
