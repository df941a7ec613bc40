#include "rpc/diagnosis_view.h"

#include "dp/pdu/ext_diag.h"
#include "dp/pdu/slave_diag.h"
#include "gsd/station/gsd_station.h"
#include "gsd/unit_diag.h"
#include "rs4/protocol/adapter_error.h"
#include "rs4/protocol/alarm.h"
#include "rs4/safety/diagnosis.h"

#include <array>
#include <cstdio>
#include <type_traits>

namespace rs4sim::rpc {
namespace {

namespace pdu = dp::pdu;

// Station_Status_1..3 bit names [IEC 61158-6-3 Slave_Diag]; "" = not shown (byte 2 bit 2 is
// always 1, byte 3 bits 6..0 reserved).
constexpr std::array<std::array<const char*, 8>, 3> kStatusBits{{
    {"Station_Non_Existent", "Station_Not_Ready", "Cfg_Fault", "Ext_Diag", "Not_Supported",
     "Invalid_Slave_Response", "Prm_Fault", "Master_Lock"},
    {"Prm_Req", "Stat_Diag", "", "WD_On", "Freeze_Mode", "Sync_Mode", "reserved", "Deactivated"},
    {"", "", "", "", "", "", "", "Ext_Diag_Overflow"},
}};

// Channel error types 1..9 [IEC 61158-6-3 Slave_Diag]; 16..31 manufacturer specific.
constexpr std::array<const char*, 10> kChannelErrors{
    "reserved",           "short circuit",        "undervoltage",          "overvoltage",
    "overload",           "overtemperature",      "line break",            "upper limit exceeded",
    "lower limit exceeded", "error"};

constexpr std::array<const char*, 7> kAlarmTypes{"", "diagnostic", "process", "pull",
                                                 "plug", "status", "update"};

std::string hex4(unsigned v) {
  char s[8];
  std::snprintf(s, sizeof s, "0x%04X", v);
  return s;
}

// `module` and what the channel block says of it: "<module> channel 1 input: error 1 (short
// circuit)"; `named`: the device's name of a manufacturer-specific error type ("": none).
std::string channel_text(const pdu::ChannelDiag& c, const std::string& module,
                         const std::string& named = "") {
  static constexpr std::array<const char*, 4> kDirection{"reserved", "input", "output",
                                                         "input/output"};
  const std::string error =
      c.error_type < kChannelErrors.size()
          ? kChannelErrors[c.error_type]
          : (c.error_type < 16 ? "reserved" : named.empty() ? "manufacturer specific" : named);
  return module + " channel " + std::to_string(c.channel) + " " +
         kDirection[static_cast<std::size_t>(c.direction) & 3U] + ": error " +
         std::to_string(c.error_type) + " (" + error + ")";
}

std::string channel_summary(const pdu::ChannelDiag& c) {
  return channel_text(c, "module " + std::to_string(c.identifier));
}

std::string alarm_summary(const pdu::AlarmPdu& a) {
  static constexpr std::array<const char*, 4> kSpecifier{"", " appears", " disappears",
                                                         " disappears, still faulty"};
  const std::string type = a.alarm_type < kAlarmTypes.size() && a.alarm_type != 0
                               ? kAlarmTypes[a.alarm_type]
                               : "manufacturer specific";
  return "alarm type " + std::to_string(a.alarm_type) + " (" + type + ") slot " +
         std::to_string(a.slot) + " seq " + std::to_string(a.seq_nr) +
         kSpecifier[static_cast<std::size_t>(a.specifier) & 3U] + (a.add_ack ? ", Add_Ack" : "");
}

void add_block(const pdu::ExtDiagBlock& block, v1::DiagnosisView& out) {
  v1::DiagnosisBlock& b = *out.add_blocks();
  const auto data = [&b](std::span<const std::uint8_t> bytes) {
    b.set_data(std::string(bytes.begin(), bytes.end()));
  };
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, pdu::DeviceDiag>) {
          b.set_kind("device");
          data(x.data);
          b.set_summary(std::to_string(x.data.size()) + " bytes of device-related diagnosis");
        } else if constexpr (std::is_same_v<T, pdu::IdentifierDiag>) {
          b.set_kind("identifier");
          data(x.bits);
          std::string modules;
          for (std::size_t i = 0; i < x.bits.size() * 8; ++i) {
            if (x.has_diag(i)) modules += (modules.empty() ? "" : ", ") + std::to_string(i);
          }
          b.set_summary("modules with diagnosis: " + (modules.empty() ? "none" : modules));
        } else if constexpr (std::is_same_v<T, pdu::ChannelDiag>) {
          b.set_kind("channel");
          b.set_summary(channel_summary(x));
        } else if constexpr (std::is_same_v<T, pdu::AlarmPdu>) {
          b.set_kind("alarm");
          data(x.data);
          b.set_summary(alarm_summary(x));
        } else if constexpr (std::is_same_v<T, pdu::StatusPdu>) {
          b.set_kind("status");
          data(x.data);
          b.set_summary("status type " + std::to_string(x.status_type) + " slot " +
                        std::to_string(x.slot) + ", " + std::to_string(x.data.size()) +
                        " bytes");
        } else {
          b.set_kind("revision");
          b.set_summary("revision block " + hex4(x.header));
        }
      },
      block);
}

// One error number of the diagnosis alarm: table 5.3-3's cause, or the RS4's own number.
std::string alarm_error(std::uint16_t number, std::uint16_t count, const char* coming) {
  const auto known = rs4::protocol::adapter_error_from_wire(number);
  const std::string what = known ? hex4(number) + " " + std::string(rs4::protocol::to_string(*known))
                                 : hex4(number) + " (an error number of the RS4)";
  return std::string(coming) + what + ", " + std::to_string(count) + " since power-up";
}

void alarm_texts(const pdu::AlarmPdu& a, std::vector<std::string>& out) {
  if (a.alarm_type != rs4::protocol::kAlarmTypeDiagnosis) return;
  std::vector<std::uint8_t> whole{static_cast<std::uint8_t>(4 + a.data.size()), a.alarm_type,
                                  a.slot, a.specifier_byte()};
  whole.insert(whole.end(), a.data.begin(), a.data.end());
  const auto decoded = rs4::protocol::decode_diagnosis_alarm(whole);
  if (!decoded) return;
  const rs4::protocol::DiagnosisAlarm* alarm = &decoded.value();
  const char* coming =
      alarm->differentiation == rs4::protocol::AlarmDifferentiation::kDisappears ? "going: "
                                                                                 : "coming: ";
  if (alarm->uc2_error != 0) out.push_back(alarm_error(alarm->uc2_error, alarm->uc2_count, coming));
  if (alarm->uc1_error != 0 && alarm->uc1_error != alarm->uc2_error) {
    out.push_back(alarm_error(alarm->uc1_error, alarm->uc1_count, coming));
  }
}

// `fn` on each block of `ext_diag` that reads, in order (a block that does not read ends it;
// fill_diagnosis says why).
void for_each_block(std::span<const std::uint8_t> ext_diag, bool dpv1,
                    const std::function<void(const pdu::ExtDiagBlock&)>& fn) {
  pdu::ExtDiagReader reader(ext_diag, dpv1);
  for (auto block = reader.next(); block && block.value(); block = reader.next()) {
    fn(*block.value());
  }
}

}  // namespace

void fill_diagnosis(std::span<const std::uint8_t> du, bool dpv1, const DiagnosisTexts& texts,
                    v1::DiagnosisView& out) {
  out.set_raw(std::string(du.begin(), du.end()));
  if (du.size() < pdu::kDiagStandardLength) {
    out.set_error(std::to_string(du.size()) + " bytes: shorter than the 6 standard ones");
    return;
  }
  for (std::size_t byte = 0; byte < kStatusBits.size(); ++byte) {
    for (std::size_t bit = 0; bit < 8; ++bit) {
      if (((du[byte] >> bit) & 1) != 0 && *kStatusBits[byte][bit] != '\0') {
        out.add_station_status(kStatusBits[byte][bit]);
      }
    }
  }
  out.set_master_address(du[3]);
  out.set_ident_number(static_cast<std::uint32_t>(du[4] << 8U | du[5]));
  const auto ext = du.subspan(pdu::kDiagStandardLength);
  pdu::ExtDiagReader reader(ext, dpv1);
  for (;;) {
    auto block = reader.next();
    if (!block) {
      out.set_error("extended diagnosis block " + std::to_string(out.blocks_size() + 1) + ": " +
                    block.error().message());
      break;
    }
    if (!block.value()) break;
    add_block(*block.value(), out);
  }
  if (texts) {
    for (auto& text : texts(ext)) out.add_texts(std::move(text));
  }
}

std::vector<std::string> rs4_diagnosis_texts(std::span<const std::uint8_t> ext_diag) {
  std::vector<std::string> out;
  for_each_block(ext_diag, true, [&out](const pdu::ExtDiagBlock& one) {
    if (const auto* status = std::get_if<pdu::StatusPdu>(&one)) {
      // [RS4 manual §6.3]: type 0x81 status message, slot 0, the number in the last byte
      if (status->status_type == pdu::status_type::kStatusMessage && !status->data.empty() &&
          status->data.back() != 0) {
        out.push_back(rs4::safety::error_message(
            static_cast<rs4::safety::FDiagnosis>(status->data.back())));
      }
    } else if (const auto* alarm = std::get_if<pdu::AlarmPdu>(&one)) {
      alarm_texts(*alarm, out);
    }
  });
  return out;
}

DiagnosisTexts gsd_diagnosis_texts(const gsd::GsdStationSpec& spec) {
  return [&spec](std::span<const std::uint8_t> ext_diag) {
    std::vector<std::string> out = gsd::diagnosis_texts(*spec.device, ext_diag);
    const auto module = [&spec](std::size_t i) {
      return i < spec.modules.size()
                 ? "slot " + std::to_string(i) + " \"" + spec.modules[i].name + "\""
                 : "slot " + std::to_string(i) + " (no module configured there)";
    };
    for_each_block(ext_diag, spec.device->dpv1.slave, [&](const pdu::ExtDiagBlock& one) {
      if (const auto* id = std::get_if<pdu::IdentifierDiag>(&one)) {
        for (std::size_t i = 0; i < id->bits.size() * 8; ++i) {
          if (id->has_diag(i)) out.push_back(module(i) + " reports diagnosis");
        }
      } else if (const auto* channel = std::get_if<pdu::ChannelDiag>(&one)) {
        out.push_back(channel_text(*channel, module(channel->identifier),
                                   gsd::channel_error_text(spec.device->unit_diag,
                                                           channel->error_type)));
      }
    });
    return out;
  };
}

}  // namespace rs4sim::rpc
