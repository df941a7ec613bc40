#include "rpc/executor.h"

#include <boost/asio/post.hpp>

#include <exception>
#include <future>

namespace rs4sim::rpc {

void AsioExecutor::run(const std::function<void()>& f) {
  if (io_.get_executor().running_in_this_thread()) {
    f();
    return;
  }
  std::promise<void> done;
  auto result = done.get_future();
  boost::asio::post(io_, [&f, &done] {
    try {
      f();
      done.set_value();
    } catch (...) {
      done.set_exception(std::current_exception());
    }
  });
  result.get();
}

}  // namespace rs4sim::rpc
