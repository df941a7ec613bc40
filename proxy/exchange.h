#pragma once
// One command and its answer through the acyclic block protocol ([RS4 manual §5.2.1]): the
// command as WRITE records of at most 240 bytes (block numbers 0, 1, …, the last 0xFFFF,
// flow-control byte 0 from the master), then READ records until the answer's last block.
// A READ that carries only the header while nothing was received means "answer not ready":
// the next READ is due after the poll interval. A whole answer whose first byte is neither
// the command's code, an RS4 error telegram 0x53 nor the adapter's 0x93 "error in telegram"
// ([RS4 manual §5.2.2]) is skipped and the READs go on: an RS4 telegram the adapter forwards
// on its own (PROFI_CMD_GET_RS4_DATA, [RS4 manual §5.2.2.2]) or a stale answer of an earlier
// command whose READ failed.

#include "dp/time/clock.h"
#include "proxy/record.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::proxy {

struct ExchangeTiming {
  dp::Duration poll_interval = std::chrono::milliseconds(10);
  // From the last WRITE: the RS4 may take "bis zu 2 Minuten" to process a command
  // [RS4 manual §5.2.1], so the proxy waits that long and 10 s more.
  dp::Duration answer_timeout = std::chrono::seconds(130);
};

class Exchange {
 public:
  enum class Status : std::uint8_t {
    kIdle,
    kBusy,
    kDone,         // answer() holds the whole answer
    kWriteFailed,  // a WRITE was refused (sfc())
    kReadFailed,   // a READ was refused (sfc()), the answer did not come in time (sfc 0), or
                   // the READ showed flow state 010 (pc_adapter_attached(), sfc 0)
    kBadRecord,    // a READ record that is no valid block, or blocks out of sequence
  };

  // Splits the command into WRITE records; an empty or too long command ends kBadRecord
  // at once (the caller's error: never happens with the codecs' commands).
  // The answer is expected to start with command[0].
  void start(std::span<const std::uint8_t> command, dp::TimePoint now, ExchangeTiming timing);
  void reset() noexcept;

  // The next record to issue, when one is due and none is outstanding.
  std::optional<RecordRequest> take_request(dp::TimePoint now);
  void on_result(const RecordResult& result, dp::TimePoint now);
  // Ends the exchange kReadFailed once the answer deadline passed.
  void tick(dp::TimePoint now);
  // When tick()/take_request() next has something to do (a poll or the deadline).
  std::optional<dp::TimePoint> next_wakeup() const noexcept;

  Status status() const noexcept { return status_; }
  bool outstanding() const noexcept { return outstanding_; }
  std::span<const std::uint8_t> answer() const noexcept { return answer_; }
  std::uint16_t sfc() const noexcept { return sfc_; }
  // A READ answered with flow state 010, "PC adapter attached" ([RS4 manual §5.2.1], table
  // 5.2-2): the adapter ignores WRITEs and answers nothing while it lasts ([RS4 manual §6.5] "Es
  // findet keine Kommunikation statt, solange der optische PC-Adapter am RS4/PROFIsafe
  // angebracht ist"), so the exchange ends at once instead of polling to the answer timeout.
  bool pc_adapter_attached() const noexcept { return pc_adapter_; }

 private:
  void on_write_result(const RecordResult& result, dp::TimePoint now);
  void on_read_result(const RecordResult& result, dp::TimePoint now);

  ExchangeTiming timing_;
  Status status_ = Status::kIdle;
  std::vector<std::vector<std::uint8_t>> writes_;
  std::size_t next_write_ = 0;
  bool outstanding_ = false;
  dp::TimePoint read_due_{};
  dp::TimePoint deadline_{};
  std::vector<std::uint8_t> answer_;
  std::uint16_t next_block_ = 0;
  std::uint8_t expected_ = 0;
  std::uint16_t sfc_ = 0;
  bool pc_adapter_ = false;
};

}  // namespace rs4sim::proxy
