#pragma once
// A scripted stand-in for the RS4/PROFIsafe adapter's side of the proxy exchange
// (docs/proxy.md, contract in docs/proxy-protocol.md), speaking the real codecs: block
// protocol ([RS4 manual §5.2.1]), 98/99 adapter commands and the 0x60..0x65 RS4 commands.
// It is not the device (rs4/adapter is): no timing, no OSSD, just the answers, plus hooks a
// test uses to break them.

#include "proxy/record.h"
#include "rs4/protocol/adapter_answer.h"
#include "rs4/protocol/adapter_command.h"
#include "rs4/protocol/block.h"
#include "rs4/protocol/parameter_transfer.h"

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::proxy::testing {

class DeviceDouble {
 public:
  DeviceDouble();

  // ---- the device's state (tests set it up and read it back)
  std::uint16_t device_type = 0x0504;
  std::uint32_t serial = 1001;
  std::vector<std::uint8_t> set;  // active set, transfer form
  bool factory = false;
  bool request = true;  // Proxy-Request
  rs4::protocol::SyncReason reason = rs4::protocol::SyncReason::kPowerUp;
  rs4::protocol::SyncDirection direction = rs4::protocol::SyncDirection::kVerify;
  bool sync_running = false;
  bool released = false;  // 99 success accepted (until a failure report)
  bool check_after_release = false;  // 99 success, no sync since: a 99 failed is still taken
  std::optional<rs4::protocol::ProxyEndCommand> last_end;
  bool download_broken = false;
  int not_ready_reads = 0;  // header-only READs before each answer
  bool pc_adapter = false;  // switched through: WRITEs ignored, READs flow state 010, bit 3
  std::size_t commands = 0;

  // Called with each answer before it is queued; may change it.
  std::function<void(std::uint8_t command, std::vector<std::uint8_t>& answer)> answer_hook;

  static std::vector<std::uint8_t> factory_set();
  // Bits 2 and 3 as set here: the double may show both at once, which the real adapter never
  // does ([RS4 manual §7.1.2]: no Proxy-Request while the PC adapter is attached); the proxy's
  // own guard against bit 3 is tested with it (Enable.NoSyncWhileThePcAdapterIsAttached).
  std::uint8_t input_byte() const noexcept {
    return static_cast<std::uint8_t>((request ? 0x04 : 0x00) | (pc_adapter ? 0x08 : 0x00));
  }

  RecordResult write(std::span<const std::uint8_t> record);
  RecordResult read(std::uint8_t length);

 private:
  std::vector<std::uint8_t> execute(std::span<const std::uint8_t> command);
  std::vector<std::uint8_t> transfer(std::span<const std::uint8_t> command);
  rs4::protocol::TransferAnswer download(const rs4::protocol::TransferRequest& request);
  void rollback();

  rs4::protocol::BlockAssembler assembler_{rs4::protocol::Direction::kWrite};
  std::deque<std::vector<std::uint8_t>> answers_;
  rs4::protocol::BlockSplitter reading_;
  int not_ready_left_ = 0;
  std::optional<rs4::protocol::DownloadBeginRequest> open_;
  std::vector<std::uint8_t> received_;
};

}  // namespace rs4sim::proxy::testing
