#pragma once
// The JSON API's tests (docs/http.md): an http::HttpServer in front of a test's RpcServer
// (its in-process channel), on the test's loop, and a blocking HTTP/1.1 client on loopback.
#include "google/rpc/status.pb.h"
#include "http/http_server.h"
#include "rpc/server.h"

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <future>
#include <optional>
#include <string>

namespace rs4sim::rpc {

struct HttpAnswer {
  unsigned status = 0;
  std::string body;
  std::string content_type;
  std::string allow;
};

class HttpFront {
 public:
  // `io` runs on the test's loop thread (the server's calls wait for it).
  HttpFront(boost::asio::io_context& io, RpcServer& server, http::HttpOptions options = {})
      : io_(io) {
    on_loop([&] { http_.emplace(io, options, server.in_process_channel()); });
    port_ = http_->port();
  }
  HttpFront(const HttpFront&) = delete;
  HttpFront& operator=(const HttpFront&) = delete;
  ~HttpFront() {
    on_loop([&] { http_->close(); });
    // the cancelled calls end while the loop runs; gRPC goes only after them (http_server.h)
    EXPECT_TRUE(http_->wait_for_calls(std::chrono::seconds(10)));
    on_loop([&] { http_.reset(); });
  }
  void on_loop(const std::function<void()>& f) {
    std::promise<void> done;
    boost::asio::post(io_, [&] {
      f();
      done.set_value();
    });
    done.get_future().wait();
  }

  [[nodiscard]] std::uint16_t port() const { return port_; }
  [[nodiscard]] http::HttpStats stats() {
    http::HttpStats s;
    on_loop([&] { s = http_->stats(); });
    return s;
  }
  [[nodiscard]] std::string url() const { return http_->url(); }

  HttpAnswer request(boost::beast::http::verb verb, const std::string& target,
                     const std::string& body = {}, const std::string& authorization = {}) {
    namespace bhttp = boost::beast::http;
    boost::asio::io_context io;
    boost::beast::tcp_stream stream(io);
    stream.connect(boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), port_));
    bhttp::request<bhttp::string_body> req(verb, target, 11);
    req.set(bhttp::field::host, "127.0.0.1");
    if (!authorization.empty()) req.set(bhttp::field::authorization, authorization);
    if (verb == bhttp::verb::post) req.set(bhttp::field::content_type, "application/json");
    req.body() = body;
    req.prepare_payload();
    bhttp::write(stream, req);
    boost::beast::flat_buffer buffer;
    bhttp::response<bhttp::string_body> res;
    stream.expires_after(std::chrono::seconds(30));
    bhttp::read(stream, buffer, res);
    return {res.result_int(), res.body(), std::string(res[bhttp::field::content_type]),
            std::string(res[bhttp::field::allow])};
  }
  // POST /api/<method> with a JSON body.
  HttpAnswer call(const std::string& method, const std::string& json = "{}",
                  const std::string& authorization = {}) {
    return request(boost::beast::http::verb::post, "/api/" + method, json, authorization);
  }

 private:
  boost::asio::io_context& io_;
  std::optional<http::HttpServer> http_;
  std::uint16_t port_ = 0;
};

// A JSON answer as the message it must be (a test failure when it is not).
template <class M>
M from_json(const std::string& json) {
  M m;
  const auto st = google::protobuf::util::JsonStringToMessage(json, &m);
  EXPECT_TRUE(st.ok()) << st.message() << " in " << json;
  return m;
}

// The google.rpc.Status of an error answer, checked against its HTTP status.
inline google::rpc::Status error_of(const HttpAnswer& a, unsigned http, int code) {
  EXPECT_EQ(a.status, http) << a.body;
  EXPECT_EQ(a.content_type, "application/json");
  auto s = from_json<google::rpc::Status>(a.body);
  EXPECT_EQ(s.code(), code) << a.body;
  return s;
}

}  // namespace rs4sim::rpc
