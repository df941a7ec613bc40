#pragma once
// The Proxy service of rs4sim.v1 (docs/rpc.md "Proxy"): the Proxy-FB of every RS4 a master
// serves ([RS4 manual §6.4]) and a progress stream of its syncs. The scheduler belongs to
// the loop thread: status is read there (through the Executor), and the loop publishes each
// change into a ProxyFeed, which hands it to the streams.
//
// A stream holds the latest status per RS4, not a queue of them: progress is a value, and a
// slow client needs the newest one, so memory stays bounded whatever the client does. A
// status that matters for the end of a sync (not running) is never replaced before it is
// sent by a running one: the stream sees every sync end.

#include "proxy/proxy_scheduler.h"
#include "rpc/executor.h"
#include "rpc/stream_handoff.h"
#include "rs4sim/v1/proxy_service.grpc.pb.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rs4sim::rpc {

// One status in the API's form.
void fill_proxy_status(const proxy::StationStatus& s, const std::string& bus, std::int64_t now_ns,
                       v1::ProxyStationStatus& out);

// One stream's mailbox: the loop thread puts, the stream's gRPC thread takes.
class ProxyWatch : public StreamHandoff {
 public:
  explicit ProxyWatch(std::set<std::uint8_t> addresses) : addresses_(std::move(addresses)) {}
  [[nodiscard]] bool watches(std::uint8_t address) const noexcept {
    return addresses_.empty() || addresses_.contains(address);
  }
  // Loop thread: the latest status of one RS4. A pending "ended" status (not running) is
  // kept until taken, so that the stream sees the sync end; later ones queue behind it.
  void put(v1::ProxyStationStatus status);
  // Stream thread: what changed since the last take, in address order (each RS4's statuses
  // in their order), waiting up to `timeout` for something.
  std::vector<v1::ProxyStationStatus> take(std::chrono::milliseconds timeout);

 private:
  const std::set<std::uint8_t> addresses_;
  std::map<std::uint8_t, std::vector<v1::ProxyStationStatus>> pending_;
};

// The loop thread's side: publish() after every change of a status, close() when the run
// ends. subscribe() runs on the loop thread (so a snapshot and the changes after it line
// up); unsubscribe() from the stream's thread, also after the loop has ended.
class ProxyFeed {
 public:
  void subscribe(const std::shared_ptr<ProxyWatch>& watch);
  void unsubscribe(const std::shared_ptr<ProxyWatch>& watch);
  void publish(const proxy::StationStatus& status, const std::string& bus, std::int64_t now_ns);
  void close();
  [[nodiscard]] std::size_t watchers() const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::shared_ptr<ProxyWatch>> watches_;
  bool closed_ = false;
};

// What the service reads on the loop thread.
struct ProxySource {
  std::string bus;
  std::size_t max_parallel = 1;
  std::function<std::vector<proxy::StationStatus>()> status;
  std::function<std::vector<std::uint8_t>()> queue;
  std::function<std::int64_t()> now_ns;
};

class ProxyService final : public v1::Proxy::Service {
 public:
  // `source` and `feed` are used on the loop thread only (through `executor`).
  ProxyService(ProxySource source, ProxyFeed& feed, Executor& executor)
      : source_(std::move(source)), feed_(feed), executor_(executor) {}

  grpc::Status GetStatus(grpc::ServerContext*, const v1::ProxyStatusRequest* in,
                         v1::ProxyStatusResponse* out) override;
  grpc::Status WatchSync(grpc::ServerContext* context, const v1::WatchSyncRequest* in,
                         grpc::ServerWriter<v1::ProxyStationStatus>* out) override;

 private:
  // The requested addresses, checked against the RS4s the master serves (loop thread).
  grpc::Status resolve(const google::protobuf::RepeatedField<std::uint32_t>& in,
                       const std::vector<proxy::StationStatus>& all,
                       std::set<std::uint8_t>& out) const;
  // On the loop: the RS4s' status and the requested ones among them, then `body(all, wanted)`;
  // the resolve error without calling `body`.
  template <class Body>
  grpc::Status on_loop_for(const google::protobuf::RepeatedField<std::uint32_t>& in, Body&& body);

  ProxySource source_;
  ProxyFeed& feed_;
  Executor& executor_;
};

}  // namespace rs4sim::rpc
