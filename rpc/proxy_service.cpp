#include "rpc/proxy_service.h"

#include "dp/pdu/sap.h"
#include "rpc/status.h"

#include <algorithm>

namespace rs4sim::rpc {
namespace {

constexpr std::chrono::milliseconds kCancelCheck{100};
// A stream's backlog per RS4: statuses alternate between running and not only at the rate
// of syncs, so this is never reached by a reading client; it bounds a client that does not.
constexpr std::size_t kMaxPendingPerStation = 16;

bool waiting_or_running(const v1::ProxyStationStatus& s) noexcept {
  return s.running() || s.queue_position() >= 0;
}

}  // namespace

void fill_proxy_status(const proxy::StationStatus& s, const std::string& bus, std::int64_t now_ns,
                       v1::ProxyStationStatus& out) {
  out.set_bus(bus);
  out.set_address(s.address);
  out.set_running(s.running);
  out.set_queue_position(s.queue_position ? static_cast<std::int32_t>(*s.queue_position) : -1);
  out.set_step(std::string(proxy::to_string(s.progress.step)));
  out.set_position(s.progress.position);
  out.set_bytes_done(s.progress.bytes_done);
  out.set_bytes_total(s.progress.bytes_total);
  out.set_direction(std::string(rs4::protocol::to_token(s.progress.direction)));
  auto& o = *out.mutable_outputs();
  o.set_fb_busy(s.outputs.fb_busy);
  o.set_config_set_to_default(s.outputs.config_set_to_default);
  o.set_error_number_fb(s.outputs.error_number_fb);
  o.set_error_code_sfc(s.outputs.error_code_sfc);
  o.set_error_number_rs4(s.outputs.error_number_rs4);
  out.set_now_ns(now_ns);
}

// ---- ProxyWatch ---------------------------------------------------------------------------

void ProxyWatch::put(v1::ProxyStationStatus status) {
  {
    const std::lock_guard lock(mutex_);
    if (closed_) return;
    auto& pending = pending_[static_cast<std::uint8_t>(status.address())];
    // Replace the newest pending status unless that one marks a change between waiting or
    // running and not: then it must reach the client, and the new one queues behind it.
    if (!pending.empty() && (waiting_or_running(pending.back()) == waiting_or_running(status) ||
                             pending.size() >= kMaxPendingPerStation)) {
      pending.back() = std::move(status);
    } else {
      pending.push_back(std::move(status));
    }
  }
  ready_.notify_one();
}

std::vector<v1::ProxyStationStatus> ProxyWatch::take(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, timeout, [this] { return closed_ || !pending_.empty(); });
  std::vector<v1::ProxyStationStatus> out;
  for (auto& [address, statuses] : pending_) {
    for (auto& s : statuses) out.push_back(std::move(s));
  }
  pending_.clear();
  return out;
}

// ---- ProxyFeed ----------------------------------------------------------------------------

void ProxyFeed::subscribe(const std::shared_ptr<ProxyWatch>& watch) {
  const std::lock_guard lock(mutex_);
  if (closed_) {
    watch->close();
    return;
  }
  watches_.push_back(watch);
}

void ProxyFeed::unsubscribe(const std::shared_ptr<ProxyWatch>& watch) {
  const std::lock_guard lock(mutex_);
  std::erase(watches_, watch);
}

void ProxyFeed::publish(const proxy::StationStatus& status, const std::string& bus,
                        std::int64_t now_ns) {
  const std::lock_guard lock(mutex_);
  if (watches_.empty()) return;
  v1::ProxyStationStatus message;
  fill_proxy_status(status, bus, now_ns, message);
  for (const auto& w : watches_) {
    if (w->watches(status.address)) w->put(message);
  }
}

void ProxyFeed::close() {
  const std::lock_guard lock(mutex_);
  closed_ = true;
  for (const auto& w : watches_) w->close();
  watches_.clear();
}

std::size_t ProxyFeed::watchers() const {
  const std::lock_guard lock(mutex_);
  return watches_.size();
}

// ---- ProxyService -------------------------------------------------------------------------

grpc::Status ProxyService::resolve(const google::protobuf::RepeatedField<std::uint32_t>& in,
                                   const std::vector<proxy::StationStatus>& all,
                                   std::set<std::uint8_t>& out) const {
  for (int i = 0; i < in.size(); ++i) {
    const auto a = in.Get(i);
    const std::string field = "addresses[" + std::to_string(i) + "]";
    if (a > dp::pdu::sap::kMaxStationAddress) {
      return invalid_argument(field, std::to_string(a) + " outside 0.." +
                                         std::to_string(dp::pdu::sap::kMaxStationAddress));
    }
    const bool served = std::any_of(all.begin(), all.end(),
                                    [a](const proxy::StationStatus& s) { return s.address == a; });
    if (!served) {
      return not_found("station " + std::to_string(a) +
                       " is not an RS4 of this master's proxy (bus " + source_.bus + ")");
    }
    out.insert(static_cast<std::uint8_t>(a));
  }
  return grpc::Status::OK;
}

template <class Body>
grpc::Status ProxyService::on_loop_for(const google::protobuf::RepeatedField<std::uint32_t>& in,
                                       Body&& body) {
  grpc::Status status;
  executor_.run([&] {
    const auto all = source_.status();
    std::set<std::uint8_t> wanted;
    status = resolve(in, all, wanted);
    if (status.ok()) body(all, wanted);
  });
  return status;
}

grpc::Status ProxyService::GetStatus(grpc::ServerContext*, const v1::ProxyStatusRequest* in,
                                     v1::ProxyStatusResponse* out) {
  return on_loop_for(in->addresses(), [&](const std::vector<proxy::StationStatus>& all,
                                          const std::set<std::uint8_t>& wanted) {
    const auto now = source_.now_ns();
    out->set_bus(source_.bus);
    out->set_max_parallel(static_cast<std::uint32_t>(source_.max_parallel));
    std::uint32_t running = 0;
    for (const auto& s : all) {
      if (s.running) ++running;
      if (wanted.empty() || wanted.contains(s.address)) {
        fill_proxy_status(s, source_.bus, now, *out->add_stations());
      }
    }
    out->set_running(running);
    for (const auto a : source_.queue()) out->add_queue(a);
  });
}

grpc::Status ProxyService::WatchSync(grpc::ServerContext* context, const v1::WatchSyncRequest* in,
                                     grpc::ServerWriter<v1::ProxyStationStatus>* out) {
  std::shared_ptr<ProxyWatch> watch;
  const auto status = on_loop_for(in->addresses(), [&](const std::vector<proxy::StationStatus>& all,
                                                       const std::set<std::uint8_t>& wanted) {
    watch = std::make_shared<ProxyWatch>(wanted);
    // The snapshot first, then the changes: both from the loop, so they line up.
    const auto now = source_.now_ns();
    for (const auto& s : all) {
      if (!watch->watches(s.address)) continue;
      v1::ProxyStationStatus message;
      fill_proxy_status(s, source_.bus, now, message);
      watch->put(std::move(message));
    }
    feed_.subscribe(watch);
  });
  if (!status.ok()) return status;
  std::set<std::uint32_t> seen;  // RS4s seen waiting or running
  bool open = true;
  bool done = false;
  while (open && !done && !context->IsCancelled()) {
    auto batch = watch->take(kCancelCheck);
    if (batch.empty() && watch->closed()) break;
    for (std::size_t i = 0; i < batch.size() && open && !done; ++i) {
      const auto& s = batch[i];
      open = out->Write(s);
      if (waiting_or_running(s)) {
        seen.insert(s.address());
      } else if (in->until_sync_done() && seen.contains(s.address())) {
        done = true;
      }
    }
  }
  feed_.unsubscribe(watch);
  return grpc::Status::OK;
}

}  // namespace rs4sim::rpc
