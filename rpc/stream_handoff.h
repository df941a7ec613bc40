#pragma once
// What a stream's mailbox shares between the loop thread, which fills it, and the stream's
// gRPC thread, which waits on it: one lock, one wake-up and the end of the stream
// (EventQueue, ProxyWatch).

#include <condition_variable>
#include <mutex>

namespace rs4sim::rpc {

class StreamHandoff {
 public:
  // Nothing more will come (the run ends): the waiting stream thread returns at once.
  void close() {
    {
      const std::lock_guard lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
  }
  [[nodiscard]] bool closed() const {
    const std::lock_guard lock(mutex_);
    return closed_;
  }

 protected:
  StreamHandoff() = default;
  ~StreamHandoff() = default;

  mutable std::mutex mutex_;
  std::condition_variable ready_;
  bool closed_ = false;  // guarded by mutex_
};

}  // namespace rs4sim::rpc
