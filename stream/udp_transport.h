#pragma once
// UDP link for processes on one host: one datagram = one frame (PROFIBUS: SD…ED, or E5, or
// SD4; a byte device: one frame of its protocol), sent to a fixed peer. Datagrams from any other
// sender are dropped and counted.

#include "stream/link_error.h"
#include "stream/transport.h"

#include <boost/asio/ip/udp.hpp>

#include <array>
#include <deque>
#include <string>
#include <vector>

namespace rs4sim::stream {

// Parses and resolves "HOST:PORT" ("127.0.0.1:5000", "localhost:5000", "[::1]:5000").
// Throws LinkException(kBadEndpoint) with the reason.
boost::asio::ip::udp::endpoint resolve_udp_endpoint(boost::asio::io_context& io,
                                                    const std::string& host_port);

class UdpTransport final : public Transport {
 public:
  // Binds `listen` (port 0 = any free port); throws LinkException(kBindFailed).
  UdpTransport(boost::asio::io_context& io, const boost::asio::ip::udp::endpoint& listen,
               const boost::asio::ip::udp::endpoint& peer);
  ~UdpTransport() override;

  [[nodiscard]] bool datagram() const override { return true; }
  void start(BytesFn on_bytes, ErrorFn on_error) override;
  void send(std::span<const std::uint8_t> frame) override;
  void close() override;

  [[nodiscard]] boost::asio::ip::udp::endpoint local_endpoint() const;
  void set_peer(const boost::asio::ip::udp::endpoint& peer) { peer_ = peer; }
  [[nodiscard]] std::uint64_t foreign_datagrams() const { return foreign_; }

 private:
  void receive_next();
  void send_next();

  boost::asio::ip::udp::socket socket_;
  boost::asio::ip::udp::endpoint peer_;
  boost::asio::ip::udp::endpoint sender_;
  BytesFn on_bytes_;
  ErrorFn on_error_;
  std::array<std::uint8_t, 1024> rx_{};
  std::deque<std::vector<std::uint8_t>> tx_;
  bool sending_ = false;
  std::uint64_t foreign_ = 0;
};

}  // namespace rs4sim::stream
