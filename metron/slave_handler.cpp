#include "metron/slave_handler.h"

#include <algorithm>
#include <array>
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

// #13: each flag that holds sets its bit of the table (EXTENSION, [docs/metron.md#replies]).
std::uint8_t curtain_status(const WireTable& t, const Scene& scene, const SlaveState& s) {
  const std::array<bool, kStatusFlagCount> holds{
      scene.synchronised(),  s.ossd == OssdFunction::kEnabled, s.ossd == OssdFunction::kStandby,
      s.ossd_measuring,      s.measuring.has_value(),          scene.any_interrupted(),
      scene.input_high()};
  unsigned v = 0;
  for (std::size_t i = 0; i < kStatusFlagCount; ++i) {
    if (holds[i]) v |= t.replies.curtain_status[i];
  }
  return static_cast<std::uint8_t>(v);
}

// #11: the table's items in its order.
std::vector<std::uint8_t> configuration(const Options& o) {
  std::vector<std::uint8_t> out;
  for (const ConfigItem item : o.wire.replies.configuration) {
    switch (item) {
      case ConfigItem::kBeams: out.push_back(static_cast<std::uint8_t>(o.beams)); break;
      case ConfigItem::kInputType: out.push_back(static_cast<std::uint8_t>(o.input_type)); break;
      case ConfigItem::kNode: out.push_back(o.node_enabled ? o.node : std::uint8_t{0}); break;
      case ConfigItem::kScanCycle: out.push_back(clamp_ms(o.scan_cycle)); break;
      case ConfigItem::kTResponse: out.push_back(clamp_ms(o.t_response)); break;
    }
  }
  return out;
}

// #8: the measurement's code and/or its maximum, in the table's order.
std::vector<std::uint8_t> stop_reply(const Options& o, const SlaveState& s) {
  std::vector<std::uint8_t> out;
  for (const StopItem item : o.wire.replies.stop_measurement) {
    out.push_back(item == StopItem::kCode ? code_of(o.wire, *s.measuring) : s.maximum);
  }
  return out;
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
    case C::kStopMeasurement: {
      auto reply = stop_reply(o, s);  // E5 has refused it without a measurement
      s.measuring.reset();
      return reply;
    }
    case C::kRequestBeamStatus:
      if (data[0] == o.wire.all_beams) return scene.packed(o.wire.beam_bits_lsb_first);
      return {scene.interrupted(data[0]) ? o.wire.replies.beam_interrupted
                                         : o.wire.replies.beam_free};
    case C::kRequestMeasurements: {
      std::vector<std::uint8_t> out;
      for (const auto f : data) out.push_back(scene.measure(*measurement_from_code(o.wire, f)));
      return out;
    }
    case C::kRequestConfiguration: return configuration(o);
    case C::kRequestOssdStatus: {
      const auto on = static_cast<std::uint8_t>(ossd_on(s, scene) ? 1 : 0);
      return {on, on};
    }
    case C::kRequestCurtainStatus: return {curtain_status(o.wire, scene, s)};
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
