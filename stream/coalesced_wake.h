#pragma once
// The wake handler a runner installs on its cores (dp::Station, stream::ByteDevice): a core
// that changed outside a runner call (a scene change from the API, a power cycle) gets one
// `on_wake` posted to the loop, however often it woke before that ran (coalesced). Handlers
// may outlive this object (a core outliving its runner): they then do nothing.

#include <boost/asio/any_io_executor.hpp>

#include <functional>
#include <memory>

namespace rs4sim::stream {

class CoalescedWake {
 public:
  CoalescedWake(boost::asio::any_io_executor executor, std::function<void()> on_wake);
  CoalescedWake(const CoalescedWake&) = delete;
  CoalescedWake& operator=(const CoalescedWake&) = delete;

  // The handler for set_wake_handler(); it posts only while enabled.
  [[nodiscard]] std::function<void()> handler() const;
  void set_enabled(bool enabled) { state_->enabled = enabled; }

 private:
  struct State {
    boost::asio::any_io_executor executor;
    std::function<void()> on_wake;
    bool enabled = false;
    bool posted = false;
  };
  static void wake(const std::weak_ptr<State>& weak);

  std::shared_ptr<State> state_;
};

}  // namespace rs4sim::stream
