#pragma once
// The HTTP server of a run (`--http HOST:PORT`, docs/http.md) on the run's Asio loop
// (Boost.Beast): the live-view page at `/`, every unary call of the gRPC API as JSON at
// `POST /api/<package.Service>/<Method>`, and Observation.StreamEvents as Server-Sent
// Events at `GET /api/events`.
//
// One implementation: a call is not handled here but forwarded, by method name, over the
// gRPC server's in-process channel to the very services `--grpc` serves (the request in
// protobuf's JSON mapping turned into the binary message of the method's input type, the
// answer back into JSON). The forwarded call completes on a gRPC thread, never on the loop
// (the services wait for the loop through rpc::Executor); its answer is posted back to the
// loop, which writes it. The loop never waits for a client: reads and writes are
// asynchronous with timeouts, and an event-stream client whose backlog passes its bound is
// dropped.

#include <boost/asio/io_context.hpp>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace grpc {
class Channel;
}

namespace rs4sim::http {

struct HttpOptions {
  std::string host = "127.0.0.1";  // the bind address (loopback; app/runtime checks the rule)
  std::uint16_t port = 0;          // 0: any free port
  // Not empty: every /api request needs `Authorization: Bearer <token>` (or, for browsers'
  // EventSource, which cannot set headers, `?access_token=<token>`, RFC 6750 section 2.3).
  std::string bearer_token{};
  // Both set (PEM text, the files of --grpc-tls-cert/--grpc-tls-key): HTTPS, TLS 1.2 or later
  // on every connection; empty: plain HTTP.
  std::string tls_cert_chain{};
  std::string tls_private_key{};
  std::size_t body_limit = 1U << 20;                 // request body bytes, else 413
  std::chrono::milliseconds read_timeout{10'000};    // a request's headers and body
  std::chrono::milliseconds write_timeout{10'000};   // one response or one event write
  std::chrono::milliseconds call_timeout{60'000};    // the forwarded call's deadline (504)
  std::chrono::milliseconds keep_alive{15'000};      // an SSE comment line when idle
  std::size_t event_backlog = 1024;                  // events waiting per SSE client, else dropped
  std::size_t event_backlog_bytes = 256U << 10;      // their bytes per SSE client, else dropped
  // Connections open at once (0: no cap). At the cap the server accepts no more until one
  // closes: the next ones wait in the kernel's listen queue (--http-max-connections).
  std::size_t max_connections = 256;
};

// What a server has done, for its tests and the end of a run (read on the loop).
struct HttpStats {
  std::size_t connections = 0;           // open now
  std::size_t event_bytes_waiting = 0;   // event bytes waiting for their SSE clients, summed
  std::uint64_t accept_failures = 0;     // accepts that failed (EMFILE, ...)
  std::uint64_t event_clients_dropped = 0;  // SSE clients dropped for their backlog
};

class HttpServer {
 public:
  // Binds and listens (throws std::runtime_error with the reason when it cannot, or when the
  // TLS certificate or key is refused); `channel`
  // reaches the services (grpc::Server::InProcessChannel). Runs on `io`'s thread.
  HttpServer(boost::asio::io_context& io, const HttpOptions& options,
             std::shared_ptr<grpc::Channel> channel);
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;
  ~HttpServer();

  [[nodiscard]] std::uint16_t port() const noexcept;
  // "http://127.0.0.1:PORT/" ("https://…" with TLS)
  [[nodiscard]] std::string url() const;
  // On the loop: stops accepting, cancels the forwarded calls and ends every connection.
  void close();
  // Off the loop, after close() (the loop still running, or the gRPC server shut down, so
  // the cancelled calls can end): waits until every forwarded call has completed and released
  // its gRPC context; false when `timeout` passed first. Call it before the gRPC server and
  // the last channel go, so gRPC is never torn down from one of its own threads.
  [[nodiscard]] bool wait_for_calls(std::chrono::milliseconds timeout) const;
  // On the loop.
  [[nodiscard]] HttpStats stats() const;

  struct Impl;

 private:
  std::shared_ptr<Impl> impl_;
};

// The HTTP status of a gRPC status code (docs/http.md "Errors").
[[nodiscard]] unsigned http_status_of(int grpc_code) noexcept;

}  // namespace rs4sim::http
