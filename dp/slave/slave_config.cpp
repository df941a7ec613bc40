#include "dp/slave/slave_config.h"

#include "dp/slave/slave_error.h"

namespace rs4sim::dp::slave {

std::error_code Config::validate() const {
  if (address > 126) return SlaveError::kInvalidAddress;
  if (max_diag_length < 6 || max_diag_length > 244) return SlaveError::kInvalidMaxDiagLength;
  if (min_tsdr_default < 11) return SlaveError::kInvalidMinTsdr;
  if (alarm_sequence_numbers < 1 || alarm_sequence_numbers > 32 || alarm_capacity < 1 ||
      alarm_capacity > 32 || alarm_capacity > alarm_sequence_numbers) {
    return SlaveError::kInvalidAlarmCapacity;
  }
  if (alarm_queue_capacity < 1) return SlaveError::kInvalidAlarmQueue;
  if (c2_rm_send_timeout == 0) return SlaveError::kInvalidC2Timeout;
  if (c1_max_data_length < 1 || c1_max_data_length > 240 || c2_max_data_length < 1 ||
      c2_max_data_length > 240) {
    return SlaveError::kInvalidAcyclicLength;
  }
  if (c2_sap > 48) return SlaveError::kInvalidC2Sap;
  return {};
}

}  // namespace rs4sim::dp::slave
