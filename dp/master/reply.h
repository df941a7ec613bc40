#pragma once
// A slave's reply to the master's outstanding request, reduced to what the master
// evaluates ([IEC 61158-4-3 frame control] response FC, [IEC 61158-4-3 short acknowledgement] short
// acknowledgement).

#include "dp/fdl/telegram.h"

#include <cstdint>
#include <span>

namespace rs4sim::dp::master {

// A DataUnit (boost static_vector) as a byte span.
inline std::span<const std::uint8_t> bytes(const fdl::DataUnit& d) { return {d.data(), d.size()}; }

struct Reply {
  bool short_ack = false;  // E5 ([IEC 61158-4-3 short acknowledgement])
  fdl::ResponseStatus status = fdl::ResponseStatus::kOk;
  fdl::StationType station_type = fdl::StationType::kSlave;
  bool has_saps = false;
  std::uint8_t dsap = 0;  // reply DSAP = the master's SSAP of the request
  std::uint8_t ssap = 0;  // reply SSAP = the slave's DSAP of the request
  std::span<const std::uint8_t> data;

  static Reply from(const fdl::Telegram& t) {
    Reply r;
    if (t.type == fdl::FrameType::kShortAck) {
      r.short_ack = true;
      return r;
    }
    r.status = t.fc.status();
    r.station_type = t.fc.station_type();
    r.has_saps = t.dsap.has_value() && t.ssap.has_value();
    r.dsap = t.dsap.value_or(0);
    r.ssap = t.ssap.value_or(0);
    r.data = std::span<const std::uint8_t>(t.data.data(), t.data.size());
    return r;
  }

  // DL, DH, RDL, RDH: the reply carries response data ([IEC 61158-4-3 frame control]).
  [[nodiscard]] bool carries_data() const {
    using S = fdl::ResponseStatus;
    return !short_ack && (status == S::kDataLow || status == S::kDataHigh ||
                          status == S::kNotReceivedDataLow || status == S::kNotReceivedDataHigh);
  }
  // DH or RDH: the slave has diagnosis pending ([IEC 61158-6-3 Data_Exchange]).
  [[nodiscard]] bool diag_pending() const {
    using S = fdl::ResponseStatus;
    return !short_ack && (status == S::kDataHigh || status == S::kNotReceivedDataHigh);
  }
  // SC, or an SD1 reply "OK"/"no data" without SAPs and data
  // ([IEC 61158-4-3 short acknowledgement]).
  [[nodiscard]] bool empty_ack() const {
    using S = fdl::ResponseStatus;
    if (short_ack) return true;
    return !has_saps && data.empty() && (status == S::kOk || status == S::kNoData);
  }
  [[nodiscard]] bool from_saps(std::uint8_t reply_dsap, std::uint8_t reply_ssap) const {
    return has_saps && dsap == reply_dsap && ssap == reply_ssap;
  }
};

}  // namespace rs4sim::dp::master
