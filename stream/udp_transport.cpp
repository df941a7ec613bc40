#include "stream/udp_transport.h"

#include <boost/asio/error.hpp>

#include <charconv>

namespace rs4sim::stream {

namespace asio = boost::asio;
using asio::ip::udp;

udp::endpoint resolve_udp_endpoint(asio::io_context& io, const std::string& host_port) {
  const auto colon = host_port.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == host_port.size()) {
    throw LinkException(LinkError::kBadEndpoint, "'" + host_port + "': expected HOST:PORT");
  }
  std::string host = host_port.substr(0, colon);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']')
    host = host.substr(1, host.size() - 2);
  const std::string port_text = host_port.substr(colon + 1);
  unsigned port = 0;
  const auto [p, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (ec != std::errc{} || p != port_text.data() + port_text.size() || port > 65535) {
    throw LinkException(LinkError::kBadEndpoint, "'" + host_port + "': port must be 0..65535");
  }
  udp::resolver resolver(io);
  boost::system::error_code rec;
  const auto results = resolver.resolve(host, port_text, udp::resolver::numeric_service, rec);
  if (rec || results.empty()) {
    throw LinkException(LinkError::kBadEndpoint,
                        "'" + host_port + "': cannot resolve '" + host + "': " + rec.message());
  }
  for (const auto& r : results) {
    if (r.endpoint().address().is_v4()) return r.endpoint();  // prefer IPv4 for localhost
  }
  return results.begin()->endpoint();
}

UdpTransport::UdpTransport(asio::io_context& io, const udp::endpoint& listen,
                           const udp::endpoint& peer)
    : socket_(io), peer_(peer) {
  boost::system::error_code ec;
  socket_.open(listen.protocol(), ec);
  if (!ec) socket_.bind(listen, ec);
  if (ec) {
    throw LinkException(LinkError::kBindFailed, "UDP " + listen.address().to_string() + ":" +
                                                    std::to_string(listen.port()) + ": " +
                                                    ec.message());
  }
}

UdpTransport::~UdpTransport() { close(); }

udp::endpoint UdpTransport::local_endpoint() const { return socket_.local_endpoint(); }

void UdpTransport::start(BytesFn on_bytes, ErrorFn on_error) {
  on_bytes_ = std::move(on_bytes);
  on_error_ = std::move(on_error);
  receive_next();
}

void UdpTransport::receive_next() {
  socket_.async_receive_from(asio::buffer(rx_), sender_,
                             [this](const boost::system::error_code& ec, std::size_t n) {
                               if (ec == asio::error::operation_aborted || !socket_.is_open())
                                 return;
                               if (ec) {
                                 if (on_error_) on_error_(ec);
                               } else if (sender_ != peer_) {
                                 ++foreign_;
                               } else if (on_bytes_) {
                                 on_bytes_(std::span<const std::uint8_t>(rx_.data(), n));
                               }
                               receive_next();
                             });
}

void UdpTransport::send(std::span<const std::uint8_t> frame) {
  if (!socket_.is_open()) return;
  tx_.emplace_back(frame.begin(), frame.end());
  if (!sending_) send_next();
}

void UdpTransport::send_next() {
  if (tx_.empty()) {
    sending_ = false;
    return;
  }
  sending_ = true;
  socket_.async_send_to(asio::buffer(tx_.front()), peer_,
                        [this](const boost::system::error_code& ec, std::size_t) {
                          if (ec == asio::error::operation_aborted || tx_.empty()) return;
                          if (ec && on_error_) on_error_(ec);  // e.g. ECONNREFUSED: peer not up yet
                          tx_.pop_front();
                          send_next();
                        });
}

void UdpTransport::close() {
  if (socket_.is_open()) {
    boost::system::error_code ignored;
    socket_.close(ignored);
  }
  tx_.clear();
  sending_ = false;
}

}  // namespace rs4sim::stream
