#include "http/http_server.h"

#include "http/page_files.h"
#include "json/message.h"
#include "json/request_body.h"
#include "rpc/server.h"
#include "rpc/status.h"

#include "google/rpc/status.pb.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <google/protobuf/descriptor.h>
#include <google/protobuf/dynamic_message.h>
#include <google/protobuf/util/json_util.h>
#include <grpcpp/channel.h>
#include <grpcpp/client_context.h>
#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/support/byte_buffer.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string_view>
#include <variant>
#include <vector>

namespace rs4sim::http {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace bhttp = boost::beast::http;
namespace pb = google::protobuf;
using tcp = asio::ip::tcp;
namespace ssl = asio::ssl;
// A connection's stream: plain TCP, or TLS over it when the server has a certificate.
using PlainStream = beast::tcp_stream;
using TlsStream = beast::ssl_stream<beast::tcp_stream>;
using AnyStream = std::variant<PlainStream, TlsStream>;

constexpr std::string_view kApi = "/api/";
constexpr std::string_view kEvents = "/api/events";
constexpr const char* kStreamMethod = "/rs4sim.v1.Observation/StreamEvents";
constexpr std::chrono::milliseconds kHeaderGrace{200};  // an SSE stream's first event

// ---- JSON and status ---------------------------------------------------------------------

std::string status_json(int code, const std::string& message, const std::string& details = {}) {
  google::rpc::Status status;
  if (!details.empty() && status.ParseFromString(details) && status.code() == code) {
    // the service's own google.rpc.Status with its details (BadRequest, PreconditionFailure)
  } else {
    status.Clear();
    status.set_code(code);
    status.set_message(message);
  }
  std::string json;
  pb::util::JsonPrintOptions print;
  print.always_print_primitive_fields = true;
  if (!pb::util::MessageToJsonString(status, &json, print).ok()) {
    status.clear_details();  // a detail of a type this binary does not know
    (void)pb::util::MessageToJsonString(status, &json, print);
  }
  return json;
}

std::string status_json(const grpc::Status& s) {
  return status_json(static_cast<int>(s.error_code()), s.error_message(), s.error_details());
}

std::string bytes_of(const grpc::ByteBuffer& buffer) {
  std::vector<grpc::Slice> slices;
  std::string out;
  if (!buffer.Dump(&slices).ok()) return out;
  for (const auto& s : slices) out.append(reinterpret_cast<const char*>(s.begin()), s.size());
  return out;
}

grpc::ByteBuffer buffer_of(const std::string& bytes) {
  grpc::Slice slice(bytes);
  return grpc::ByteBuffer(&slice, 1);
}

// The binary answer of a call as JSON (false: not a message of `type`).
bool to_json(const pb::Descriptor* type, const grpc::ByteBuffer& buffer, std::string& json) {
  std::unique_ptr<pb::Message> m(pb::MessageFactory::generated_factory()->GetPrototype(type)->New());
  if (!m->ParseFromString(bytes_of(buffer))) return false;
  pb::util::JsonPrintOptions print;
  print.always_print_primitive_fields = true;
  return pb::util::MessageToJsonString(*m, &json, print).ok();
}

struct Reply {
  unsigned status = 200;
  std::string body;
  std::string content_type = "application/json";
  std::string allow{};  // 405
};

Reply error_reply(unsigned http, int code, const std::string& message) {
  return {http, status_json(code, message)};
}

// Posts work to the loop while the server lives (gRPC threads call it; the server may be
// gone by the time a call completes), and counts the forwarded calls still alive.
struct Gate {
  std::mutex mutex;
  std::condition_variable idle;
  asio::io_context* io = nullptr;
  std::size_t calls = 0;
  template <class F>
  void post(F&& f) {
    std::lock_guard lock(mutex);
    if (io != nullptr) asio::post(*io, std::forward<F>(f));
  }
  void shut() {
    std::lock_guard lock(mutex);
    io = nullptr;
  }
  bool wait_idle(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex);
    return idle.wait_for(lock, timeout, [this] { return calls == 0; });
  }
};

// One forwarded call alive, from its start until its ClientContext is gone (the member
// declared first, so destroyed last). A call's last reference usually drops on a gRPC
// thread; its context holds the channel, and the channel holds gRPC itself: an owner that
// tears gRPC down must wait for these (HttpServer::wait_for_calls), else gRPC's last
// reference could drop on its own thread, where grpc_shutdown races the process's exit.
class CallTicket {
 public:
  explicit CallTicket(std::shared_ptr<Gate> gate) : gate_(std::move(gate)) {
    std::lock_guard lock(gate_->mutex);
    ++gate_->calls;
  }
  CallTicket(const CallTicket&) = delete;
  CallTicket& operator=(const CallTicket&) = delete;
  ~CallTicket() {
    std::lock_guard lock(gate_->mutex);
    if (--gate_->calls == 0) gate_->idle.notify_all();
  }

 private:
  std::shared_ptr<Gate> gate_;
};

std::string lowercase(std::string_view s) {
  std::string out(s);
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// "%41" -> "A"; false on a malformed escape.
bool url_decode(std::string_view in, std::string& out) {
  out.clear();
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (in[i] == '%') {
      if (i + 2 >= in.size()) return false;
      unsigned v = 0;
      const auto [p, ec] = std::from_chars(in.data() + i + 1, in.data() + i + 3, v, 16);
      if (ec != std::errc{} || p != in.data() + i + 3) return false;
      out += static_cast<char>(v);
      i += 2;
    } else {
      out += in[i] == '+' ? ' ' : in[i];
    }
  }
  return true;
}

bool parse_uint(std::string_view s, std::uint64_t max, std::uint64_t& v) {
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc{} && p == s.data() + s.size() && !s.empty() && v <= max;
}

}  // namespace

unsigned http_status_of(int code) noexcept {
  // google.rpc.Code and its HTTP mapping (google/rpc/code.proto), FAILED_PRECONDITION as 412.
  switch (static_cast<grpc::StatusCode>(code)) {
    case grpc::StatusCode::OK: return 200;
    case grpc::StatusCode::CANCELLED: return 499;
    case grpc::StatusCode::INVALID_ARGUMENT: return 400;
    case grpc::StatusCode::DEADLINE_EXCEEDED: return 504;
    case grpc::StatusCode::NOT_FOUND: return 404;
    case grpc::StatusCode::ALREADY_EXISTS: return 409;
    case grpc::StatusCode::PERMISSION_DENIED: return 403;
    case grpc::StatusCode::UNAUTHENTICATED: return 401;
    case grpc::StatusCode::RESOURCE_EXHAUSTED: return 429;
    case grpc::StatusCode::FAILED_PRECONDITION: return 412;
    case grpc::StatusCode::ABORTED: return 409;
    case grpc::StatusCode::OUT_OF_RANGE: return 400;
    case grpc::StatusCode::UNIMPLEMENTED: return 501;
    case grpc::StatusCode::UNAVAILABLE: return 503;
    default: return 500;  // UNKNOWN, INTERNAL, DATA_LOSS
  }
}

class Connection;

struct HttpServer::Impl : std::enable_shared_from_this<HttpServer::Impl> {
  Impl(asio::io_context& loop, const HttpOptions& o, std::shared_ptr<grpc::Channel> ch)
      : io(loop), options(o), acceptor(loop), channel(std::move(ch)), stub(channel),
        gate(std::make_shared<Gate>()) {
    gate->io = &loop;
  }
  void accept();
  void on_accept_error(const beast::error_code& ec);
  void close();

  asio::io_context& io;
  HttpOptions options;
  std::optional<ssl::context> tls;  // HTTPS: the certificate and key of HttpOptions
  tcp::acceptor acceptor;
  std::shared_ptr<grpc::Channel> channel;
  grpc::GenericStub stub;
  std::shared_ptr<Gate> gate;
  std::set<std::shared_ptr<Connection>> connections;
  std::uint16_t port = 0;
  bool closed = false;
  bool accepting = false;                  // an async_accept is pending
  asio::steady_timer retry{io};            // the back-off after a failed accept
  std::chrono::milliseconds backoff{0};    // 0 after a successful accept
  HttpStats stats;
};

namespace {

// A forwarded unary call: what must outlive it until gRPC calls back.
struct UnaryCall {
  explicit UnaryCall(std::shared_ptr<Gate> gate) : ticket(std::move(gate)) {}
  CallTicket ticket;
  grpc::ClientContext context;
  grpc::ByteBuffer request;
  grpc::ByteBuffer response;
};

// A forwarded StreamEvents: the reactor lives until OnDone; the connection may cancel it.
struct StreamCall {
  explicit StreamCall(std::shared_ptr<Gate> gate) : ticket(std::move(gate)) {}
  CallTicket ticket;
  grpc::ClientContext context;
};

}  // namespace

class Connection : public std::enable_shared_from_this<Connection> {
 public:
  Connection(tcp::socket socket, std::shared_ptr<HttpServer::Impl> server)
      : stream_(make_stream(std::move(socket), *server)), server_(std::move(server)),
        timer_(server_->io) {}

  // HTTPS: the TLS handshake first, within the read timeout (a client that does not speak
  // TLS, plain HTTP included, fails it and is closed).
  void start() {
    auto* tls = std::get_if<TlsStream>(&stream_);
    if (tls == nullptr) {
      read();
      return;
    }
    lowest().expires_after(server_->options.read_timeout);
    tls->async_handshake(ssl::stream_base::server,
                         [self = shared_from_this()](beast::error_code ec) {
                           if (self->closed_) return;
                           if (ec) {
                             self->close();
                             return;
                           }
                           self->read();
                         });
  }

  // On the loop: ends the connection and its forwarded call.
  void close() {
    if (closed_) return;
    closed_ = true;
    if (unary_) unary_->context.TryCancel();
    if (events_) events_->context.TryCancel();
    timer_.cancel();
    beast::error_code ignored;
    lowest().socket().shutdown(tcp::socket::shutdown_both, ignored);
    lowest().close();
    backlog_bytes_ = 0;
    const auto server = server_;  // this may go with the erase
    server->connections.erase(shared_from_this());
    server->accept();  // resumes accepting when the cap had stopped it
  }

  // ---- the event stream (from the reactor, posted to the loop) -------------------------
  void on_event(std::string json) {
    if (closed_) return;
    if (!sse_started_) start_sse();
    std::string event = "id: " + std::to_string(++event_id_) + "\ndata: " + json + "\n\n";
    if (backlog_.size() >= server_->options.event_backlog ||
        backlog_bytes_ + event.size() > server_->options.event_backlog_bytes) {
      // A client that stops reading: drop it rather than hold its events or wait for it.
      ++server_->stats.event_clients_dropped;
      close();
      return;
    }
    push_event(std::move(event));
    write_events();
  }
  void on_stream_done(const grpc::Status& s) {
    events_.reset();
    if (closed_) return;
    if (!sse_started_) {
      if (s.error_code() == grpc::StatusCode::UNIMPLEMENTED && s.error_message().empty()) {
        respond(error_reply(501, 12, "rs4sim.v1.Observation/StreamEvents: this run does not "
                                     "serve rs4sim.v1.Observation (no event stream)"),
                false);
        return;
      }
      if (!s.ok()) {
        sse_ = false;  // no byte sent yet: a plain error answer
        respond({http_status_of(static_cast<int>(s.error_code())), status_json(s)}, false);
        return;
      }
      start_sse();
    }
    push_event("event: end\ndata: " + status_json(s) + "\n\n");
    end_after_backlog_ = true;
    write_events();
  }

 private:
  void read() {
    parser_.emplace();
    parser_->body_limit(server_->options.body_limit);
    parser_->header_limit(16 * 1024);
    lowest().expires_after(server_->options.read_timeout);
    auto on_read = [self = shared_from_this()](beast::error_code ec, std::size_t) {
      self->on_read(ec);
    };
    std::visit([&](auto& s) { bhttp::async_read(s, buffer_, *parser_, std::move(on_read)); },
               stream_);
  }

  void on_read(beast::error_code ec) {
    if (closed_) return;
    if (ec == bhttp::error::body_limit) {
      respond(error_reply(413, static_cast<int>(grpc::StatusCode::RESOURCE_EXHAUSTED),
                          "request body over " + std::to_string(server_->options.body_limit) +
                              " bytes"),
              false);
      return;
    }
    if (ec == bhttp::error::header_limit) {
      respond(error_reply(431, static_cast<int>(grpc::StatusCode::RESOURCE_EXHAUSTED),
                          "request header over 16384 bytes"),
              false);
      return;
    }
    if (ec && &ec.category() == &bhttp::make_error_code(bhttp::error::end_of_stream).category() &&
        ec != bhttp::error::end_of_stream && ec != bhttp::error::partial_message) {
      respond(error_reply(400, static_cast<int>(grpc::StatusCode::INVALID_ARGUMENT),
                          "malformed HTTP request: " + ec.message()),
              false);
      return;
    }
    if (ec) {  // the client went away or stayed silent past the read timeout
      close();
      return;
    }
    lowest().expires_never();
    request_ = parser_->release();
    handle();
  }

  bool authorised(const std::string& query_token) const {
    const auto& token = server_->options.bearer_token;
    if (token.empty()) return true;
    const auto it = request_.find(bhttp::field::authorization);
    if (it != request_.end()) {
      const std::string_view value(it->value().data(), it->value().size());
      constexpr std::string_view kScheme = "bearer ";
      return value.size() > kScheme.size() &&
             lowercase(value.substr(0, kScheme.size())) == kScheme &&
             rpc::constant_time_equal(std::string(value.substr(kScheme.size())), token);
    }
    return !query_token.empty() && rpc::constant_time_equal(query_token, token);
  }

  void handle() {
    const std::string_view target(request_.target().data(), request_.target().size());
    const auto q = target.find('?');
    const std::string_view path = target.substr(0, q);
    const std::string_view query = q == std::string_view::npos ? "" : target.substr(q + 1);
    std::vector<std::pair<std::string, std::string>> params;
    std::string access_token;
    for (std::size_t at = 0; at < query.size();) {
      auto end = query.find('&', at);
      if (end == std::string_view::npos) end = query.size();
      const auto pair = query.substr(at, end - at);
      at = end + 1;
      if (pair.empty()) continue;
      const auto eq = pair.find('=');
      std::string key;
      std::string value;
      if (!url_decode(pair.substr(0, eq), key) ||
          !url_decode(eq == std::string_view::npos ? "" : pair.substr(eq + 1), value)) {
        respond(error_reply(400, 3, "malformed query string: bad %-escape in '" +
                                        std::string(pair) + "'"));
        return;
      }
      if (key == "access_token") {
        access_token = value;
      } else {
        params.emplace_back(std::move(key), std::move(value));
      }
    }
    if (path.substr(0, kApi.size()) != kApi && path != "/api") {
      serve_page(path);
      return;
    }
    if (!authorised(access_token)) {
      Reply r = error_reply(401, 16,
                            server_->options.bearer_token.empty()
                                ? ""
                                : "missing or wrong bearer token (this server wants "
                                  "'Authorization: Bearer <token>')");
      respond(std::move(r));
      return;
    }
    if (path == kEvents) {
      if (request_.method() != bhttp::verb::get) {
        Reply r = error_reply(405, 12, "GET " + std::string(kEvents) + " (Server-Sent Events), not " +
                                           std::string(request_.method_string()));
        r.allow = "GET";
        respond(std::move(r));
        return;
      }
      start_events(params);
      return;
    }
    if (request_.method() != bhttp::verb::post) {
      Reply r = error_reply(405, 12, "a call is POST /api/<package.Service>/<Method>, not " +
                                         std::string(request_.method_string()));
      r.allow = "POST";
      respond(std::move(r));
      return;
    }
    call(path.substr(kApi.size()));
  }

  void serve_page(std::string_view path) {
    if (request_.method() != bhttp::verb::get) {
      Reply r{405, "method not allowed: the page is GET\n", "text/plain; charset=utf-8", "GET"};
      respond(std::move(r));
      return;
    }
    const PageFile* file = find_page_file(path == "/" ? "/index.html" : path);
    if (file == nullptr) {
      respond({404, "not found: " + std::string(path) + "\n", "text/plain; charset=utf-8"});
      return;
    }
    respond({200, std::string(file->body), std::string(file->content_type)});
  }

  // POST /api/<package.Service>/<Method>
  void call(std::string_view name) {
    const auto slash = name.find('/');
    const std::string service(name.substr(0, slash));
    const std::string method(slash == std::string_view::npos ? "" : name.substr(slash + 1));
    const auto* pool = pb::DescriptorPool::generated_pool();
    const pb::ServiceDescriptor* sd = service.empty() ? nullptr : pool->FindServiceByName(service);
    if (sd == nullptr || service.rfind("rs4sim.", 0) != 0) {
      respond(error_reply(404, 5, "no service '" + service +
                                      "' in the API (a call is POST /api/<package.Service>/<Method>, "
                                      "e.g. /api/rs4sim.v1.Device/ListDevices)"));
      return;
    }
    const pb::MethodDescriptor* md = sd->FindMethodByName(method);
    if (md == nullptr) {
      respond(error_reply(404, 5, "no method '" + method + "' in " + service));
      return;
    }
    if (md->client_streaming() || md->server_streaming()) {
      respond(error_reply(501, 12, service + "/" + method +
                                       " streams: over HTTP only Observation.StreamEvents is "
                                       "served, as Server-Sent Events at GET /api/events"));
      return;
    }
    std::unique_ptr<pb::Message> in(
        pb::MessageFactory::generated_factory()->GetPrototype(md->input_type())->New());
    std::string body = request_.body().empty() ? "{}" : request_.body();
    // Short enum names and hex bytes as people write them; an unknown member named with the
    // message's fields (json/request_body.h).
    if (const auto refused = json::normalise_body(body, *md->input_type())) {
      respond({400, status_json(rpc::invalid_argument(refused->field, refused->reason))});
      return;
    }
    pb::util::JsonParseOptions parse;
    parse.ignore_unknown_fields = false;
    if (const auto st = json::to_message(body, *in, parse); !st.ok()) {
      respond(error_reply(400, 3, "the body is not a " + md->input_type()->full_name() +
                                      " in protobuf's JSON mapping: " +
                                      std::string(st.message())));
      return;
    }
    auto c = std::make_shared<UnaryCall>(server_->gate);
    unary_ = c;
    c->request = buffer_of(in->SerializeAsString());
    c->context.set_deadline(std::chrono::system_clock::now() + server_->options.call_timeout);
    const pb::Descriptor* out_type = md->output_type();
    std::weak_ptr<Connection> weak = shared_from_this();
    server_->stub.UnaryCall(
        &c->context, "/" + service + "/" + method, grpc::StubOptions(), &c->request, &c->response,
        [c, weak, gate = server_->gate, out_type, name = service + "/" + method](grpc::Status s) {
          // a gRPC thread: the JSON is made here, the loop only writes it
          Reply r;
          if (s.ok()) {
            if (!to_json(out_type, c->response, r.body)) {
              r = error_reply(500, 13, "the answer is not a " + out_type->full_name());
            }
          } else if (s.error_code() == grpc::StatusCode::UNIMPLEMENTED && s.error_message().empty()) {
            r = error_reply(501, 12, name + ": this run does not serve " +
                                         name.substr(0, name.find('/')));
          } else {
            r = {http_status_of(static_cast<int>(s.error_code())), status_json(s)};
          }
          gate->post([weak, r = std::move(r)]() mutable {
            if (auto self = weak.lock()) {
              self->unary_.reset();
              if (!self->closed_) self->respond(std::move(r));
            }
          });
        });
  }

  void respond(Reply r, bool keep_alive = true) {
    auto res = std::make_shared<bhttp::response<bhttp::string_body>>(
        static_cast<bhttp::status>(r.status), request_.version() == 10 ? 10 : 11);
    res->set(bhttp::field::server, "rs4sim");
    res->set(bhttp::field::content_type, r.content_type);
    res->set(bhttp::field::cache_control, "no-store");
    if (!r.allow.empty()) res->set(bhttp::field::allow, r.allow);
    if (r.status == 401) res->set(bhttp::field::www_authenticate, "Bearer");
    res->body() = std::move(r.body);
    res->prepare_payload();
    res->keep_alive(keep_alive && request_.keep_alive());
    lowest().expires_after(server_->options.write_timeout);
    auto self = shared_from_this();
    auto on_written = [self, res](beast::error_code ec, std::size_t) {
      if (ec || !res->keep_alive()) {
        self->close();
        return;
      }
      self->read();
    };
    std::visit([&](auto& s) { bhttp::async_write(s, *res, std::move(on_written)); }, stream_);
  }

  // ---- GET /api/events ----------------------------------------------------------------------
  void start_events(const std::vector<std::pair<std::string, std::string>>& params) {
    const auto* md = pb::DescriptorPool::generated_pool()->FindMethodByName(
        "rs4sim.v1.Observation.StreamEvents");
    std::unique_ptr<pb::Message> in(
        pb::MessageFactory::generated_factory()->GetPrototype(md->input_type())->New());
    const auto* d = md->input_type();
    const auto* reflection = in->GetReflection();
    for (const auto& [key, value] : params) {
      std::uint64_t v = 0;
      if (key == "addresses" || key == "address") {
        for (std::size_t at = 0; at <= value.size();) {
          auto end = value.find(',', at);
          if (end == std::string::npos) end = value.size();
          if (!parse_uint(std::string_view(value).substr(at, end - at), 0xFFFFFFFF, v)) {
            respond(error_reply(400, 3, key + ": '" + value +
                                            "' is not a comma-separated list of addresses"));
            return;
          }
          reflection->AddUInt32(in.get(), d->FindFieldByName("addresses"),
                                static_cast<std::uint32_t>(v));
          at = end + 1;
        }
      } else if (key == "telegrams") {
        if (value != "true" && value != "false" && value != "1" && value != "0") {
          respond(error_reply(400, 3, "telegrams: '" + value + "' is not true or false"));
          return;
        }
        reflection->SetBool(in.get(), d->FindFieldByName("telegrams"),
                            value == "true" || value == "1");
      } else if (key == "queue_capacity" || key == "queueCapacity") {
        if (!parse_uint(value, 0xFFFFFFFF, v)) {
          respond(error_reply(400, 3, "queue_capacity: '" + value + "' is not a number"));
          return;
        }
        reflection->SetUInt32(in.get(), d->FindFieldByName("queue_capacity"),
                              static_cast<std::uint32_t>(v));
      } else {
        respond(error_reply(400, 3, "unknown query parameter '" + key +
                                        "' (addresses, telegrams, queue_capacity, access_token)"));
        return;
      }
    }
    sse_ = true;
    start_reactor(in->SerializeAsString(), md->output_type());
    // Headers go with the first event (the snapshot); an error before it is a plain answer;
    // with no event after kHeaderGrace the stream starts empty.
    timer_.expires_after(kHeaderGrace);
    timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (ec || self->closed_ || self->sse_started_ || !self->events_) return;
      self->start_sse();
      self->write_events();
    });
    // The client closing its side ends the stream (nothing else is read from it).
    watch_client();
  }

  void start_reactor(const std::string& request, const pb::Descriptor* event_type);

  // The bytes waiting for an SSE client are counted (HttpOptions::event_backlog_bytes).
  void push_event(std::string event) {
    backlog_bytes_ += event.size();
    backlog_.push_back(std::move(event));
  }

  void start_sse() {
    sse_started_ = true;
    backlog_bytes_ += kSseHeader.size();
    backlog_.push_front(std::string(kSseHeader));
    arm_keep_alive();
  }
  static constexpr std::string_view kSseHeader =
      "HTTP/1.1 200 OK\r\nServer: rs4sim\r\nContent-Type: text/event-stream\r\n"
      "Cache-Control: no-store\r\nConnection: close\r\nX-Accel-Buffering: no\r\n\r\n";

  void arm_keep_alive() {
    timer_.expires_after(server_->options.keep_alive);
    timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (ec || self->closed_) return;
      if (self->backlog_.empty()) {
        self->push_event(":\n\n");
        self->write_events();
      }
      self->arm_keep_alive();
    });
  }

  void watch_client() {
    lowest().expires_never();
    auto on_read = [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (self->closed_) return;
      if (ec) {
        self->close();
        return;
      }
      self->watch_client();
    };
    std::visit([&](auto& s) { s.async_read_some(asio::buffer(sink_), std::move(on_read)); },
               stream_);
  }

  void write_events() {
    if (writing_ || closed_ || !sse_started_) return;
    if (backlog_.empty()) {
      if (end_after_backlog_) close();
      return;
    }
    writing_ = true;
    // One write at a time with its own deadline: a client that stops reading is dropped
    // by the timeout or by its backlog's bound, never waited for.
    lowest().expires_after(server_->options.write_timeout);
    auto on_written = [self = shared_from_this()](beast::error_code ec, std::size_t) {
      self->writing_ = false;
      if (self->closed_) return;
      if (ec) {
        self->close();
        return;
      }
      self->backlog_bytes_ -= self->backlog_.front().size();
      self->backlog_.pop_front();
      self->write_events();
    };
    std::visit(
        [&](auto& s) {
          asio::async_write(s, asio::buffer(backlog_.front()), std::move(on_written));
        },
        stream_);
  }

  static AnyStream make_stream(tcp::socket socket, HttpServer::Impl& server) {
    if (server.tls) return AnyStream(std::in_place_type<TlsStream>, std::move(socket), *server.tls);
    return AnyStream(std::in_place_type<PlainStream>, std::move(socket));
  }
  // The TCP stream under TLS or the plain one: timeouts and the socket.
  beast::tcp_stream& lowest() {
    return std::visit([](auto& s) -> beast::tcp_stream& { return beast::get_lowest_layer(s); },
                      stream_);
  }

  friend struct HttpServer::Impl;
  friend class HttpServer;
  AnyStream stream_;
  std::shared_ptr<HttpServer::Impl> server_;
  beast::flat_buffer buffer_;
  std::optional<bhttp::request_parser<bhttp::string_body>> parser_;
  bhttp::request<bhttp::string_body> request_;
  std::shared_ptr<UnaryCall> unary_;
  std::shared_ptr<StreamCall> events_;
  asio::steady_timer timer_;
  std::deque<std::string> backlog_;
  std::size_t backlog_bytes_ = 0;  // the sum of backlog_'s sizes
  std::array<char, 256> sink_{};
  std::uint64_t event_id_ = 0;
  bool closed_ = false;
  bool sse_ = false;
  bool sse_started_ = false;
  bool writing_ = false;
  bool end_after_backlog_ = false;
};

namespace {

class EventReactor final : public grpc::ClientBidiReactor<grpc::ByteBuffer, grpc::ByteBuffer> {
 public:
  EventReactor(grpc::GenericStub& stub, std::shared_ptr<StreamCall> call,
               std::shared_ptr<Gate> gate, std::weak_ptr<Connection> connection,
               const std::string& request, const pb::Descriptor* type)
      : call_(std::move(call)), gate_(std::move(gate)), connection_(std::move(connection)),
        request_(buffer_of(request)), type_(type) {
    stub.PrepareBidiStreamingCall(&call_->context, kStreamMethod, grpc::StubOptions(), this);
    StartWriteLast(&request_, grpc::WriteOptions());
    StartRead(&in_);
    StartCall();
  }
  void OnReadDone(bool ok) override {
    if (!ok) return;  // OnDone follows
    std::string json;
    if (!to_json(type_, in_, json)) json = status_json(13, "an event that is not a rs4sim.v1.Event");
    gate_->post([c = connection_, json = std::move(json)]() mutable {
      if (auto self = c.lock()) self->on_event(std::move(json));
    });
    in_.Clear();
    StartRead(&in_);
  }
  void OnDone(const grpc::Status& s) override {
    gate_->post([c = connection_, s] {
      if (auto self = c.lock()) self->on_stream_done(s);
    });
    delete this;
  }

 private:
  std::shared_ptr<StreamCall> call_;
  std::shared_ptr<Gate> gate_;
  std::weak_ptr<Connection> connection_;
  grpc::ByteBuffer request_;
  grpc::ByteBuffer in_;
  const pb::Descriptor* type_;
};

}  // namespace

void Connection::start_reactor(const std::string& request, const pb::Descriptor* event_type) {
  events_ = std::make_shared<StreamCall>(server_->gate);
  new EventReactor(server_->stub, events_, server_->gate, weak_from_this(), request, event_type);
}

void HttpServer::Impl::accept() {
  if (closed || accepting) return;
  if (options.max_connections != 0 && connections.size() >= options.max_connections) return;
  accepting = true;
  acceptor.async_accept([self = shared_from_this()](beast::error_code ec, tcp::socket socket) {
    self->accepting = false;
    if (self->closed) return;
    if (ec) {
      self->on_accept_error(ec);
      return;
    }
    self->backoff = std::chrono::milliseconds{0};
    auto c = std::make_shared<Connection>(std::move(socket), self);
    self->connections.insert(c);
    c->start();
    self->accept();
  });
}

// Out of descriptors or memory the pending connection stays in the listen queue, so an accept
// re-armed at once fails again at once (a core spun at 100 %): wait 10 ms, doubling up to 1 s,
// until an accept succeeds. Any other failure (the client reset the connection first) is that
// one connection's: accept the next at once.
void HttpServer::Impl::on_accept_error(const beast::error_code& ec) {
  ++stats.accept_failures;
  const int e = ec.value();
  const bool exhausted = ec.category() == boost::system::system_category() &&
                         (e == EMFILE || e == ENFILE || e == ENOBUFS || e == ENOMEM);
  if (!exhausted) {
    accept();
    return;
  }
  constexpr std::chrono::milliseconds kFirst{10};
  constexpr std::chrono::milliseconds kMost{1000};
  backoff = backoff.count() == 0 ? kFirst : std::min(backoff * 2, kMost);
  accepting = true;  // no other accept until the wait is over
  retry.expires_after(backoff);
  retry.async_wait([self = shared_from_this()](beast::error_code) {
    self->accepting = false;
    self->accept();
  });
}

void HttpServer::Impl::close() {
  if (closed) return;
  closed = true;
  retry.cancel();
  beast::error_code ignored;
  acceptor.close(ignored);
  const auto all = connections;  // close() erases
  for (const auto& c : all) c->close();
}

HttpServer::HttpServer(asio::io_context& io, const HttpOptions& options,
                       std::shared_ptr<grpc::Channel> channel)
    : impl_(std::make_shared<Impl>(io, options, std::move(channel))) {
  if (options.tls_cert_chain.empty() != options.tls_private_key.empty()) {
    throw std::runtime_error("--http: TLS needs both the certificate chain and the private key");
  }
  if (!options.tls_cert_chain.empty()) {
    try {
      // TLS 1.2 and later only ([RFC 8996]: TLS 1.0/1.1 deprecated).
      ssl::context c(ssl::context::tls_server);
      c.set_options(ssl::context::default_workarounds | ssl::context::no_sslv2 |
                    ssl::context::no_sslv3 | ssl::context::no_tlsv1 | ssl::context::no_tlsv1_1 |
                    ssl::context::single_dh_use);
      c.use_certificate_chain(asio::buffer(options.tls_cert_chain));
      c.use_private_key(asio::buffer(options.tls_private_key), ssl::context::pem);
      impl_->tls.emplace(std::move(c));
    } catch (const boost::system::system_error& e) {
      throw std::runtime_error(std::string("--http: TLS: ") + e.code().message());
    }
  }
  beast::error_code ec;
  const auto address = asio::ip::make_address(options.host, ec);
  if (ec) throw std::runtime_error("--http: '" + options.host + "' is not an IP address");
  const tcp::endpoint endpoint(address, options.port);
  auto& a = impl_->acceptor;
  if (!a.open(endpoint.protocol(), ec) && !a.set_option(asio::socket_base::reuse_address(true), ec) &&
      !a.bind(endpoint, ec) && !a.listen(asio::socket_base::max_listen_connections, ec)) {
    impl_->port = a.local_endpoint(ec).port();
    impl_->accept();
    return;
  }
  throw std::runtime_error("--http: cannot listen on " + options.host + ":" +
                           std::to_string(options.port) + ": " + ec.message());
}

HttpServer::~HttpServer() {
  impl_->gate->shut();
  impl_->close();
}

std::uint16_t HttpServer::port() const noexcept { return impl_->port; }

std::string HttpServer::url() const {
  std::string host = impl_->options.host;
  if (host.find(':') != std::string::npos) host = "[" + host + "]";
  return (impl_->tls ? "https://" : "http://") + host + ":" + std::to_string(port()) + "/";
}

void HttpServer::close() { impl_->close(); }

HttpStats HttpServer::stats() const {
  HttpStats s = impl_->stats;
  s.connections = impl_->connections.size();
  for (const auto& c : impl_->connections) s.event_bytes_waiting += c->backlog_bytes_;
  return s;
}

bool HttpServer::wait_for_calls(std::chrono::milliseconds timeout) const {
  return impl_->gate->wait_idle(timeout);
}

}  // namespace rs4sim::http
