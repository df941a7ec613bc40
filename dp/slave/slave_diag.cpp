// dp::Slave diagnosis: Slave_Diag (DSAP 60) reply, station status bits, the diag flag
// (DH), device blocks and the alarm written into the diagnosis
// ([IEC 61158-6-3 Slave_Diag, Data_Exchange, DPV1 alarms, status PDUs]).
#include "codec/endian.h"
#include "dp/pdu/sap.h"
#include "dp/slave/slave.h"
#include "dp/slave/slave_error.h"

#include <algorithm>

namespace rs4sim::dp::slave {

namespace {

// Size of the [IEC 61158-6-3 Slave_Diag] block starting at `header`: device/identifier blocks carry
// their length (incl. header) in bits 5..0, channel blocks are 3 bytes; 11 = 1-byte revision
// (VPC3).
std::size_t block_size(std::uint8_t header) {
  switch (header >> 6) {
    case 0:
    case 1: return header & 0x3F;
    case 2: return 3;
    default: return 1;
  }
}

}  // namespace

fdl::DataUnit Slave::diagnosis() const {
  fdl::DataUnit du;
  // Station_Status_1 ([IEC 61158-6-3 Slave_Diag]): bits 0, 5, 7 are set by the master only — always
  // 0 here.
  std::uint8_t s1 = 0;
  if (state_ != State::kDataExch) s1 |= 0x02;  // Station_Not_Ready
  if (cfg_fault_) s1 |= 0x04;
  if (ext_diag_) s1 |= 0x08;
  if (not_supported_) s1 |= 0x10;
  if (prm_fault_) s1 |= 0x40;
  // Station_Status_2: bit 2 always 1; bit 7 Deactivated is the master's.
  std::uint8_t s2 = 0x04;
  if (state_ == State::kWaitPrm) s2 |= 0x01;  // Prm_Req
  if (stat_diag_) s2 |= 0x02;
  if (wd_on_) s2 |= 0x08;
  if (freeze_mode_) s2 |= 0x10;
  if (sync_mode_) s2 |= 0x20;
  du.push_back(s1);
  du.push_back(s2);
  du.push_back(0);  // Station_Status_3, bit 7 patched below
  du.push_back(master_);
  du.push_back(codec::high_byte(config_.ident_number));
  du.push_back(codec::low_byte(config_.ident_number));
  // Device blocks first (the RS4's PROFIsafe status PDU sits at bytes 7..11), then the
  // alarm; blocks that do not fit are dropped whole and Ext_Diag_Overflow is set.
  const std::size_t alarm_size = alarm_in_diag_ ? alarm_in_diag_->block_size() : 0;
  const std::size_t room =
      config_.max_diag_length - 6 - std::min<std::size_t>(alarm_size, config_.max_diag_length - 6U);
  std::size_t pos = 0;
  while (pos < device_diag_.size()) {
    const std::size_t n = block_size(device_diag_[pos]);
    if (pos + n > room) {
      du[2] = 0x80;  // Station_Status_3 Ext_Diag_Overflow
      break;
    }
    pos += n;
  }
  du.insert(du.end(), device_diag_.begin(),
            device_diag_.begin() + static_cast<std::ptrdiff_t>(pos));
  if (alarm_in_diag_) alarm_in_diag_->append_block(du);
  return du;
}

void Slave::on_slave_diag(const fdl::Telegram& t) {
  reply_data(t, fdl::ResponseStatus::kDataLow) = diagnosis();
  // Fetched by the owner (or anyone while unparameterised): the diag flag clears, the
  // alarm in it now only waits for its Alarm_Ack, the next alarm may follow
  // ([IEC 61158-6-3 DPV1 alarms]).
  if (master_ == pdu::sap::kNoMasterAddress || is_owner(t.sa)) {
    diag_flag_ = false;
    alarm_in_diag_.reset();
    promote_alarm();
  }
}

void Slave::promote_alarm() {
  if (diag_flag_ || alarm_in_diag_ || !alarms_.is_open()) return;
  if (auto a = alarms_.take_next()) {
    alarm_in_diag_ = std::move(*a);
    diag_flag_ = true;
  }
}

std::error_code Slave::submit_alarm(const AlarmRequest& a) {
  if (6 + 4 + a.user_data.size() > config_.max_diag_length) return SlaveError::kInvalidAlarm;
  if (const auto ec = alarms_.submit(a)) return ec;
  promote_alarm();
  wake();
  return {};
}

std::error_code Slave::set_device_diagnosis(std::span<const std::uint8_t> blocks, bool ext_diag,
                                            bool stat_diag) {
  if (blocks.size() > device_diag_.capacity()) return SlaveError::kDiagnosisTooLong;
  for (std::size_t pos = 0; pos < blocks.size();) {
    const std::size_t n = block_size(blocks[pos]);
    if (n < 2 && (blocks[pos] >> 6) < 2) return SlaveError::kInvalidDiagnosisBlock;
    if (pos + n > blocks.size()) return SlaveError::kInvalidDiagnosisBlock;
    pos += n;
  }
  const bool same =
      ext_diag == ext_diag_ && stat_diag == stat_diag_ &&
      std::equal(blocks.begin(), blocks.end(), device_diag_.begin(), device_diag_.end());
  if (same) return {};
  device_diag_.assign(blocks.begin(), blocks.end());
  ext_diag_ = ext_diag;
  stat_diag_ = stat_diag;
  diag_flag_ = true;  // new diagnosis: DH until the master fetched it
                      // ([IEC 61158-6-3 Data_Exchange])
  wake();
  return {};
}

}  // namespace rs4sim::dp::slave
