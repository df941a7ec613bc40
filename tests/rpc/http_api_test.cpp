// The JSON API over HTTP (docs/http.md) against a real server on loopback: the RS4's
// services reached through POST /api/<Service>/<Method> (the same service objects as gRPC,
// forwarded over the in-process channel), every error class, the page, the event stream as
// Server-Sent Events and the clients that stop reading or vanish.
#include "http_front.h"
#include "rs4_fixture.h"

#include <boost/asio/read.hpp>
#include <boost/asio/read_until.hpp>
#include <boost/asio/write.hpp>

#include <chrono>
#include <thread>

namespace rs4sim::rpc {
namespace {

namespace asio = boost::asio;
namespace bhttp = boost::beast::http;
using tcp = asio::ip::tcp;

class HttpApiTest : public RpcRs4Test {
 protected:
  // The boot through the JSON API (RpcRs4Test::boot's steps).
  void boot_over_http(HttpFront& h) {
    for (const char* c : {"CONDITION_DATA_EXCHANGE", "CONDITION_RS4_MEASURING"}) {
      const auto a = h.call("rs4sim.v1.SimTime/RunUntil",
                            std::string(R"({"address": 4, "condition": ")") + c +
                                R"(", "timeoutMs": 60000})");
      ASSERT_EQ(a.status, 200u) << a.body;
      ASSERT_TRUE(from_json<v1::RunUntilResponse>(a.body).reached()) << c;
    }
    ASSERT_EQ(h.call("rs4sim.v1.Device/PressRestart", R"({"address": 4, "duration_ms": 200})").status,
              200u);
    const auto a = h.call("rs4sim.v1.SimTime/RunUntil",
                          R"({"address": 4, "condition": "CONDITION_OSSD_ON", "timeoutMs": 1000})");
    ASSERT_TRUE(from_json<v1::RunUntilResponse>(a.body).reached()) << a.body;
  }
};

// A raw connection (for what a well-behaved client does not do).
struct Raw {
  explicit Raw(std::uint16_t port, int receive_buffer = 0) : socket(io) {
    socket.open(tcp::v4());
    if (receive_buffer > 0) socket.set_option(asio::socket_base::receive_buffer_size(receive_buffer));
    socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  }
  void send(const std::string& s) { asio::write(socket, asio::buffer(s)); }
  // Everything until the server closes (or `limit` bytes).
  std::string rest(std::size_t limit = 1U << 26) {
    std::string out;
    boost::system::error_code ec;
    std::array<char, 65536> chunk{};
    while (!ec && out.size() < limit) {
      const auto n = socket.read_some(asio::buffer(chunk), ec);
      out.append(chunk.data(), n);
    }
    return out;
  }
  // Reads until `text` has arrived; what arrived.
  std::string until(const std::string& text) {
    boost::system::error_code ec;
    asio::read_until(socket, asio::dynamic_buffer(buffer), text, ec);
    return buffer;
  }
  asio::io_context io;
  tcp::socket socket;
  std::string buffer;
};

TEST_F(HttpApiTest, EveryRs4ServiceAnswersAsOverGrpc) {
  HttpFront h(io_, *server_);
  EXPECT_EQ(h.url(), "http://127.0.0.1:" + std::to_string(h.port()) + "/");
  // Device
  auto list = h.call("rs4sim.v1.Device/ListDevices");
  ASSERT_EQ(list.status, 200u) << list.body;
  EXPECT_EQ(list.body, R"({"devices":[{"address":4,"kind":"rs4","powered":true}]})");
  // SimTime: the manual clock starts at 1 h
  auto now = from_json<v1::TimeResponse>(h.call("rs4sim.v1.SimTime/Now").body);
  EXPECT_TRUE(now.simulated());
  EXPECT_EQ(now.now_ns(), 3'600'000'000'000);
  boot_over_http(h);
  // the request in the JSON mapping's both spellings: lowerCamelCase and the proto names
  auto violated = h.call("rs4sim.v1.Device/ViolateField",
                         R"({"address": 4, "field": "FIELD_KIND_PROTECTIVE"})");
  ASSERT_EQ(violated.status, 200u) << violated.body;
  EXPECT_GT(from_json<v1::AddObstacleResponse>(violated.body).obstacle_id(), 0u);
  ASSERT_EQ(h.call("rs4sim.v1.SimTime/Advance", R"({"duration_ms": "200"})").status, 200u);
  // Observation: the HTTP answer is the gRPC answer, field by field
  auto over_http = h.call("rs4sim.v1.Observation/GetState", R"({"address": 4})");
  ASSERT_EQ(over_http.status, 200u);
  const auto grpc_state = state();
  const auto http_state = from_json<v1::DeviceState>(over_http.body);
  EXPECT_EQ(http_state.SerializeAsString(), grpc_state.SerializeAsString());
  EXPECT_FALSE(http_state.ossd());
  EXPECT_TRUE(http_state.input().protective_field_violated());
  // proto3 defaults are printed: a script sees "ossd": false, not a missing key
  EXPECT_NE(over_http.body.find(R"("ossd":false)"), std::string::npos) << over_http.body;
  auto contour = from_json<v1::Contour>(h.call("rs4sim.v1.Observation/GetContour", R"({"address": 4})").body);
  EXPECT_EQ(contour.mm_size(), 529);
  // Faults
  auto fault = h.call("rs4sim.v1.Faults/InjectBusFault",
                      R"({"address": 4, "kind": "BUS_FAULT_KIND_DROP", "direction": "DIRECTION_FROM_STATION", "count": 1})");
  ASSERT_EQ(fault.status, 200u) << fault.body;
  EXPECT_GT(from_json<v1::BusFaultResponse>(fault.body).fault_id(), 0u);
  auto cleared = h.call("rs4sim.v1.Faults/ClearBusFaults");
  EXPECT_EQ(cleared.status, 200u);
  EXPECT_EQ(cleared.body, "{}");
}

// The master's per-station counters in ProfiTrace's vocabulary (docs/http.md "Station
// counters"), read as the page reads them: GetState's plc.dp over JSON. Known counts from the
// faults injected: one dropped reply is one repeat; a reply and its repeat dropped is one no
// answer, one lost and, after the restart, one more sync; a corrupted reply (the FCS check
// rejects it) is a repeat too.
TEST_F(HttpApiTest, StationCountersCountTheInjectedBusFaults) {
  HttpFront h(io_, *server_);
  boot_over_http(h);
  const auto dp = [&h] {
    const auto a = h.call("rs4sim.v1.Observation/GetState", R"({"address": 4})");
    EXPECT_EQ(a.status, 200u) << a.body;
    return from_json<v1::DeviceState>(a.body).plc().dp();
  };
  const auto fault = [&h](const char* kind, int count) {
    const auto a = h.call("rs4sim.v1.Faults/InjectBusFault",
                          std::string(R"({"address": 4, "kind": ")") + kind +
                              R"(", "direction": "DIRECTION_FROM_STATION", "count": )" +
                              std::to_string(count) + "}");
    ASSERT_EQ(a.status, 200u) << a.body;
  };
  const auto before = dp();
  EXPECT_GT(before.data_exchanges(), 0u);
  EXPECT_EQ(before.syncs(), 1u);  // one start-up into data exchange
  EXPECT_EQ(before.lost(), 0u);
  EXPECT_EQ(before.repeats(), 0u);
  // While the RS4 boots it answers the master's start-up with RS: RS/RR counts them, Illegal
  // does not (ProfiTrace's live list counts the two apart); nothing else was unfitting.
  EXPECT_GT(before.negative(), 0u);
  EXPECT_EQ(before.illegal(), 0u);
  EXPECT_NE(h.call("rs4sim.v1.Observation/GetState", R"({"address": 4})").body.find(R"("repeats":"0")"),
            std::string::npos);  // the JSON a script reads: uint64 as a string

  fault("BUS_FAULT_KIND_DROP", 1);
  advance(200);
  auto c = dp();
  EXPECT_EQ(c.repeats(), 1u);
  EXPECT_EQ(c.no_answer(), 0u);
  EXPECT_EQ(c.lost(), 0u);
  EXPECT_EQ(c.syncs(), 1u);

  fault("BUS_FAULT_KIND_CORRUPT", 1);
  advance(200);
  c = dp();
  EXPECT_EQ(c.repeats(), 2u);
  EXPECT_EQ(c.lost(), 0u);
  EXPECT_EQ(c.illegal(), before.illegal());

  fault("BUS_FAULT_KIND_DROP", 2);  // the reply and its one repeat (max_retry_limit 1)
  advance(3000);                    // the restart: diagnosis, Set_Prm, Chk_Cfg, data exchange
  c = dp();
  EXPECT_EQ(c.repeats(), 3u);
  EXPECT_EQ(c.no_answer(), 1u);
  EXPECT_EQ(c.lost(), 1u);
  EXPECT_EQ(c.syncs(), 2u);
  EXPECT_EQ(c.negative(), before.negative());
  EXPECT_TRUE(state().plc().data_exchange());
  EXPECT_GT(c.requests(), before.requests() + 3);
}

TEST_F(HttpApiTest, ServiceErrorsKeepTheirCodeAndDetails) {
  HttpFront h(io_, *server_);
  // NOT_FOUND -> 404 with the service's message
  auto unknown = error_of(h.call("rs4sim.v1.Observation/GetState", R"({"address": 9})"), 404, 5);
  EXPECT_EQ(unknown.message(), "no RS4 at station 9 (stations: 4)");
  // FAILED_PRECONDITION -> 412 with the google.rpc.PreconditionFailure
  auto early = error_of(h.call("rs4sim.v1.Device/ViolateField",
                               R"({"address": 4, "field": "FIELD_KIND_PROTECTIVE"})"),
                        412, 9);
  ASSERT_EQ(early.details_size(), 1);
  google::rpc::PreconditionFailure failure;
  ASSERT_TRUE(early.details(0).UnpackTo(&failure));
  EXPECT_EQ(failure.violations(0).type(), "STATE");
  // INVALID_ARGUMENT -> 400 with the google.rpc.BadRequest naming the field
  auto bad = error_of(h.call("rs4sim.v1.Device/ViolateField", R"({"address": 4, "field": 7})"), 400, 3);
  google::rpc::BadRequest request;
  ASSERT_EQ(bad.details_size(), 1);
  ASSERT_TRUE(bad.details(0).UnpackTo(&request));
  EXPECT_EQ(request.field_violations(0).field(), "field");
  // a service this run does not serve -> 501 naming it
  auto absent = error_of(h.call("rs4sim.v1.Proxy/GetStatus"), 501, 12);
  EXPECT_EQ(absent.message(), "rs4sim.v1.Proxy/GetStatus: this run does not serve rs4sim.v1.Proxy");
}

TEST_F(HttpApiTest, BadRequestsGetThePreciseStatus) {
  http::HttpOptions o;
  o.body_limit = 64;
  HttpFront h(io_, *server_, o);
  auto malformed = error_of(h.call("rs4sim.v1.Observation/GetState", R"({"address": 4)"), 400, 3);
  EXPECT_NE(malformed.message().find("not a rs4sim.v1.StationRequest in protobuf's JSON mapping"),
            std::string::npos)
      << malformed.message();
  auto type = error_of(h.call("rs4sim.v1.Observation/GetState", R"({"address": "four"})"), 400, 3);
  EXPECT_NE(type.message().find(R"((address): invalid value "four" for type TYPE_UINT32)"),
            std::string::npos)
      << type.message();
  auto field = error_of(h.call("rs4sim.v1.Observation/GetState", R"({"adress": 4})"), 400, 3);
  EXPECT_NE(field.message().find("adress"), std::string::npos) << field.message();
  auto service = error_of(h.call("rs4sim.v1.Devices/ListDevices"), 404, 5);
  EXPECT_NE(service.message().find("no service 'rs4sim.v1.Devices'"), std::string::npos);
  auto method = error_of(h.call("rs4sim.v1.Device/ListDevice"), 404, 5);
  EXPECT_EQ(method.message(), "no method 'ListDevice' in rs4sim.v1.Device");
  error_of(h.call("google.protobuf.Empty/X"), 404, 5);  // not a service of the API
  auto stream = error_of(h.call("rs4sim.v1.Observation/StreamEvents"), 501, 12);
  EXPECT_NE(stream.message().find("GET /api/events"), std::string::npos);
  const auto get = h.request(bhttp::verb::get, "/api/rs4sim.v1.Device/ListDevices");
  error_of(get, 405, 12);
  EXPECT_EQ(get.allow, "POST");
  const auto post_events = h.request(bhttp::verb::post, "/api/events", "{}");
  error_of(post_events, 405, 12);
  EXPECT_EQ(post_events.allow, "GET");
  auto big = error_of(h.call("rs4sim.v1.Observation/GetState",
                             R"({"address": 4)" + std::string(60, ' ') + "}"),
                      413, 8);
  EXPECT_EQ(big.message(), "request body over 64 bytes");
  // the simulation did not notice
  EXPECT_EQ(h.call("rs4sim.v1.Observation/GetState", R"({"address": 4})").status, 200u);
}

// 50,000 levels, in the body itself and in the document Device.SetParameterSet carries: both
// refused by the structure scan (json/structure.h) before protobuf's parser sees them.
TEST_F(HttpApiTest, DeepNestingIsRefusedBeforeProtobufParsesIt) {
  HttpFront h(io_, *server_);
  const std::string deep = std::string(50'000, '[') + std::string(50'000, ']');
  auto body = error_of(h.call("rs4sim.v1.Observation/GetState", deep), 400, 3);
  EXPECT_NE(body.message().find("1:102: nested deeper than 100"), std::string::npos)
      << body.message();
  auto doc = error_of(h.call("rs4sim.v1.Device/SetParameterSet",
                             R"({"address": 4, "json": ")" + deep + "\"}"),
                      400, 3);
  EXPECT_NE(doc.message().find("not valid JSON at 1:102: nested deeper than 100"),
            std::string::npos)
      << doc.message();
  EXPECT_EQ(h.call("rs4sim.v1.SimTime/Now").status, 200u);
}

TEST_F(HttpApiTest, ThePageIsServedFromTheBinary) {
  HttpFront h(io_, *server_);
  const auto page = h.request(bhttp::verb::get, "/");
  ASSERT_EQ(page.status, 200u);
  EXPECT_EQ(page.content_type, "text/html; charset=utf-8");
  EXPECT_NE(page.body.find("<title>rs4sim live view</title>"), std::string::npos);
  EXPECT_EQ(page.body.find("http://"), std::string::npos) << "the page loads nothing from elsewhere";
  const auto js = h.request(bhttp::verb::get, "/app.js");
  EXPECT_EQ(js.content_type, "text/javascript; charset=utf-8");
  EXPECT_NE(js.body.find("new EventSource(\"/api/events\""), std::string::npos);
  EXPECT_EQ(h.request(bhttp::verb::get, "/style.css").content_type, "text/css; charset=utf-8");
  EXPECT_EQ(h.request(bhttp::verb::get, "/nothing.html").status, 404u);
  const auto post = h.request(bhttp::verb::post, "/", "x");
  EXPECT_EQ(post.status, 405u);
  EXPECT_EQ(post.allow, "GET");
}

TEST_F(HttpApiTest, TheBearerTokenGuardsTheApiNotThePage) {
  http::HttpOptions o;
  o.bearer_token = "s3cret-token";
  HttpFront h(io_, *server_, o);
  auto missing = error_of(h.call("rs4sim.v1.SimTime/Now"), 401, 16);
  EXPECT_NE(missing.message().find("Authorization: Bearer"), std::string::npos);
  error_of(h.call("rs4sim.v1.SimTime/Now", "{}", "Bearer s3cret-tokeN"), 401, 16);
  error_of(h.call("rs4sim.v1.SimTime/Now", "{}", "Basic s3cret-token"), 401, 16);
  EXPECT_EQ(h.call("rs4sim.v1.SimTime/Now", "{}", "Bearer s3cret-token").status, 200u);
  EXPECT_EQ(h.call("rs4sim.v1.SimTime/Now", "{}", "bearer s3cret-token").status, 200u);
  // 401 before 404: an unknown method tells nothing to a client without the token
  error_of(h.call("rs4sim.v1.Nothing/X"), 401, 16);
  error_of(h.request(bhttp::verb::get, "/api/events"), 401, 16);
  error_of(h.request(bhttp::verb::get, "/api/events?access_token=wrong"), 401, 16);
  EXPECT_EQ(h.request(bhttp::verb::get, "/").status, 200u);
  Raw events(h.port());
  events.send("GET /api/events?addresses=4&access_token=s3cret-token HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_EQ(events.until("\r\n\r\n").substr(0, 15), "HTTP/1.1 200 OK");
}

TEST_F(HttpApiTest, EventsAreServerSentEventsSnapshotFirst) {
  HttpFront h(io_, *server_);
  Raw events(h.port());
  events.send("GET /api/events?addresses=4 HTTP/1.1\r\nHost: x\r\n\r\n");
  const std::string head = events.until("\r\n\r\n");
  EXPECT_EQ(head.substr(0, head.find("\r\n")), "HTTP/1.1 200 OK");
  EXPECT_NE(head.find("Content-Type: text/event-stream"), std::string::npos);
  // the snapshot: every watched value with from = "", in the StreamEvents order
  const std::string snapshot = events.until(R"("what":"output-byte","from":"")");
  EXPECT_NE(snapshot.find(
                "id: 1\ndata: {\"sequence\":\"1\",\"address\":4,\"nowNs\":\"3600000000000\","
                "\"state\":{\"what\":\"powered\",\"from\":\"\",\"to\":\"on\"}}\n\n"),
            std::string::npos)
      << snapshot;
  // then the changes: the master's startup reaches data exchange
  ASSERT_TRUE(run_until(v1::CONDITION_DATA_EXCHANGE, 10'000));
  const std::string change =
      events.until(R"("state":{"what":"dp-state","from":"Wait_Cfg","to":"Data_Exch"}})");
  EXPECT_GT(change.size(), snapshot.size());
  // bad requests are plain answers, before any event
  error_of(h.request(bhttp::verb::get, "/api/events?addresses=9"), 404, 5);
  error_of(h.request(bhttp::verb::get, "/api/events?addresses=4,x"), 400, 3);
  error_of(h.request(bhttp::verb::get, "/api/events?queue_capacity=3"), 400, 3);
  auto unknown = error_of(h.request(bhttp::verb::get, "/api/events?adresses=4"), 400, 3);
  EXPECT_NE(unknown.message().find("unknown query parameter 'adresses'"), std::string::npos);
}

TEST_F(HttpApiTest, AnEventClientThatStopsReadingIsDroppedNotWaitedFor) {
  http::HttpOptions o;
  o.event_backlog = 8;
  HttpFront h(io_, *server_, o);
  Raw stalled(h.port(), 4096);
  stalled.send("GET /api/events?telegrams=true&queue_capacity=1048576 HTTP/1.1\r\nHost: x\r\n\r\n");
  stalled.until("\r\n\r\n");
  // Every telegram of 20 s of bus time goes to the stream (megabytes of JSON) while the
  // client reads nothing: the simulation goes on at its pace ...
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 20; ++i) advance(1000);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
  EXPECT_EQ(h.call("rs4sim.v1.SimTime/Now").status, 200u);
  // ... and the server has closed the stalled stream: what the kernel holds, then the end,
  // with no "event: end" (the run goes on).
  const std::string got = stalled.rest();
  EXPECT_EQ(got.find("event: end"), std::string::npos);
  EXPECT_LT(got.size(), 64U << 20);
}

TEST_F(HttpApiTest, EventClientsThatNeverReadAreBoundedByBytesNotOnlyByCount) {
  http::HttpOptions o;
  o.event_backlog = 1'000'000;        // the count's bound out of the way
  o.event_backlog_bytes = 4U << 10;  // 4 KiB of events per client (the kernel holds more)
  HttpFront h(io_, *server_, o);
  std::vector<std::unique_ptr<Raw>> stalled;
  for (int i = 0; i < 8; ++i) {
    stalled.push_back(std::make_unique<Raw>(h.port(), 4096));
    stalled.back()->send(
        "GET /api/events?telegrams=true&queue_capacity=1048576 HTTP/1.1\r\nHost: x\r\n\r\n");
    stalled.back()->until("\r\n\r\n");
  }
  // Megabytes of telegram events for each client; none reads them. The events reach the
  // server's loop through gRPC's threads, after the simulation made them, and a client's
  // stream may join the event hub only after the first seconds (its headers can come from the
  // grace timer before the stream is subscribed): the simulation goes on, a second at a time,
  // until every client is gone; the bytes waiting stay within 8 x 4 KiB all the while.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  http::HttpStats s = h.stats();
  for (int second = 0; s.connections > 0 && std::chrono::steady_clock::now() < deadline;) {
    if (second < 600) {
      advance(1000);
      ++second;
    }
    EXPECT_LE(s.event_bytes_waiting, 8U * (4U << 10));
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    s = h.stats();
  }
  EXPECT_EQ(s.connections, 0u);
  // Dropped by the bytes' bound, long before the write timeout (10 s) could end them.
  EXPECT_EQ(s.event_clients_dropped, 8u);
  EXPECT_EQ(h.call("rs4sim.v1.SimTime/Now").status, 200u);
}

TEST_F(HttpApiTest, SlowVanishedAndBrokenClientsLeaveTheServerServing) {
  http::HttpOptions o;
  o.read_timeout = std::chrono::milliseconds(200);
  HttpFront h(io_, *server_, o);
  {  // half a request, then silence: closed after the read timeout
    Raw slow(h.port());
    slow.send("POST /api/rs4sim.v1.SimTime/Now HTTP/1.1\r\nContent-Length: 10\r\n\r\n{");
    EXPECT_EQ(slow.rest(), "");
  }
  {  // a call whose client has gone before the answer
    Raw gone(h.port());
    gone.send("POST /api/rs4sim.v1.SimTime/Advance HTTP/1.1\r\nContent-Length: 22\r\n\r\n"
              R"({"durationMs": "1000"})");
    gone.socket.close();
  }
  {  // not HTTP
    Raw broken(h.port());
    broken.send("HELLO\r\n\r\n");
    const std::string answer = broken.rest();
    EXPECT_EQ(answer.substr(0, 24), "HTTP/1.1 400 Bad Request") << answer;
    EXPECT_NE(answer.find("malformed HTTP request"), std::string::npos);
  }
  {  // keep-alive: two calls on one connection
    Raw twice(h.port());
    const std::string call = "POST /api/rs4sim.v1.SimTime/Now HTTP/1.1\r\nContent-Length: 2\r\n\r\n{}";
    twice.send(call + call);
    // (one read may bring both answers: only the first is taken off the buffer)
    const std::string end = "\"simulated\":true}";
    const std::string first = twice.until(end);
    EXPECT_EQ(first.substr(0, 15), "HTTP/1.1 200 OK");
    twice.buffer.erase(0, first.find(end) + end.size());
    EXPECT_NE(twice.until("\"simulated\":true}").find("HTTP/1.1 200 OK"), std::string::npos);
  }
  EXPECT_EQ(h.call("rs4sim.v1.SimTime/Now").status, 200u);
}

// The gRPC codes' HTTP statuses (google/rpc/code.proto's mapping, FAILED_PRECONDITION 412).
TEST(HttpStatusOf, EveryGrpcCode) {
  const std::vector<std::pair<grpc::StatusCode, unsigned>> table{
      {grpc::StatusCode::OK, 200},
      {grpc::StatusCode::CANCELLED, 499},
      {grpc::StatusCode::UNKNOWN, 500},
      {grpc::StatusCode::INVALID_ARGUMENT, 400},
      {grpc::StatusCode::DEADLINE_EXCEEDED, 504},
      {grpc::StatusCode::NOT_FOUND, 404},
      {grpc::StatusCode::ALREADY_EXISTS, 409},
      {grpc::StatusCode::PERMISSION_DENIED, 403},
      {grpc::StatusCode::RESOURCE_EXHAUSTED, 429},
      {grpc::StatusCode::FAILED_PRECONDITION, 412},
      {grpc::StatusCode::ABORTED, 409},
      {grpc::StatusCode::OUT_OF_RANGE, 400},
      {grpc::StatusCode::UNIMPLEMENTED, 501},
      {grpc::StatusCode::INTERNAL, 500},
      {grpc::StatusCode::UNAVAILABLE, 503},
      {grpc::StatusCode::DATA_LOSS, 500},
      {grpc::StatusCode::UNAUTHENTICATED, 401},
  };
  for (const auto& [code, status] : table) {
    EXPECT_EQ(http::http_status_of(static_cast<int>(code)), status) << code;
  }
}

}  // namespace
}  // namespace rs4sim::rpc
